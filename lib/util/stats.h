#pragma once
// Small statistics shared by proxy-check, the estimators and the tests.
#include <cmath>
#include <cstdint>

namespace proxyvis {

// Mean and variance online (Welford 1962), mergeable (Chan et al. 1979) for per-thread partials.
class RunningStats {
 public:
  void add(double x) {
    ++n_;
    double d = x - mean_;
    mean_ += d / double(n_);
    m2_ += d * (x - mean_);
  }
  void merge(const RunningStats& o);
  uint64_t count() const { return n_; }
  double mean() const { return mean_; }
  // Unbiased sample variance (n - 1 in the denominator); 0 for fewer than two samples.
  double variance() const { return n_ > 1 ? m2_ / double(n_ - 1) : 0.0; }
  // Standard error of the mean.
  double standardError() const { return n_ > 0 ? std::sqrt(variance() / double(n_)) : 0.0; }

 private:
  uint64_t n_ = 0;
  double mean_ = 0, m2_ = 0;
};

struct Interval {
  double lo = 0, hi = 0;
};

// Wilson score interval for a binomial proportion k/n at normal quantile z (1.96 = 95 %).
// For k = 0 the upper bound is about z^2/n (~3.84/n at 95 %); n = 0 gives [0, 1].
Interval wilsonInterval(uint64_t k, uint64_t n, double z = 1.959963984540054);

// Two-sided normal quantile for confidence `level` (0.95 -> 1.96).
double normalQuantileTwoSided(double level);

// z for a two-sided test at family-wise level alpha over m independent checks (Sidak).
double sidakZ(double alpha, uint64_t m);

}  // namespace proxyvis
