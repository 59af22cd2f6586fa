#pragma once
// The "culling" estimator: the proxy is traced first where the verified class guarantees its
// answer (outside: a miss means visible; inside: a hit means blocked), the original otherwise. A
// general proxy guarantees nothing, so culling is exact there (the proxy is not traced).
#include "estimate/sample_estimators.h"
#include "estimate/visibility_estimator.h"

namespace proxyvis {

class CullingEstimator final : public VisibilityEstimator {
 public:
  explicit CullingEstimator(ProxyClass cls) : cls_(cls) {}
  void estimate(const ShadingPointQuery& q, Rng&, std::span<double> out,
                RayCounts& counts) override {
    for (size_t j = 0; j < q.segments.size(); ++j)
      out[j] = cullingSample(*q.tracer, q.segments[j], cls_, counts);
  }

 private:
  ProxyClass cls_;
};

}  // namespace proxyvis
