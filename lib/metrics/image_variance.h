#pragma once
// The reference's own error: a converged reference is the mean of K independent partial images
// (per seed or per pass, equal sample counts). Per value the variance of that mean is s²/K,
// with s² the sample variance of the K partials; averaged over the image it estimates the MSE
// of the reference itself, which must be far below the MSEs it is used to measure.
#include <span>
#include <vector>

namespace proxyvis {

class ImageVarianceAccumulator {
 public:
  // Adds one partial image; every partial must have the same size (throws Error otherwise).
  void add(std::span<const float> partial);
  int count() const { return count_; }
  // Mean of the partials, per value.
  std::vector<float> mean() const;
  // Mean over all values of the estimated variance of the mean (s²/K); 0 for K < 2.
  double meanVarianceOfMean() const;

 private:
  int count_ = 0;
  std::vector<double> mean_, m2_;  // Welford per value
};

}  // namespace proxyvis
