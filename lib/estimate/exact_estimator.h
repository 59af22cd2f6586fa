#pragma once
// The "exact" estimator: every segment traced against the original geometry (no proxy).
#include "estimate/sample_estimators.h"
#include "estimate/visibility_estimator.h"

namespace proxyvis {

class ExactEstimator final : public VisibilityEstimator {
 public:
  void estimate(const ShadingPointQuery& q, Rng&, std::span<double> out,
                RayCounts& counts) override {
    for (size_t j = 0; j < q.segments.size(); ++j)
      out[j] = exactSample(*q.tracer, q.segments[j], counts);
  }
};

}  // namespace proxyvis
