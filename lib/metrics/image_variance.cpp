#include "metrics/image_variance.h"

#include <string>

#include "util/error.h"

namespace proxyvis {

void ImageVarianceAccumulator::add(std::span<const float> partial) {
  if (count_ == 0) {
    mean_.assign(partial.size(), 0.0);
    m2_.assign(partial.size(), 0.0);
  } else if (partial.size() != mean_.size()) {
    throw Error({}, "cannot accumulate partial images",
                "sizes differ (" + std::to_string(partial.size()) + " vs " +
                    std::to_string(mean_.size()) + " values)");
  }
  ++count_;
  for (size_t i = 0; i < partial.size(); ++i) {
    double d = partial[i] - mean_[i];
    mean_[i] += d / count_;
    m2_[i] += d * (partial[i] - mean_[i]);
  }
}

std::vector<float> ImageVarianceAccumulator::mean() const {
  return std::vector<float>(mean_.begin(), mean_.end());
}

double ImageVarianceAccumulator::meanVarianceOfMean() const {
  if (count_ < 2 || m2_.empty()) return 0;
  double sum = 0;
  for (double m2 : m2_) sum += m2 / (count_ - 1) / count_;
  return sum / double(m2_.size());
}

}  // namespace proxyvis
