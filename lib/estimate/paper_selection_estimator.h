#pragma once
// The paper's selection estimators (Billen et al. 2014): per light sample, one term (proxy, MH'
// correction or HM' correction) picked with probabilities p (selection.h):
//   paper-equal    p = 1/3 each (1/2 when a verified class drops a branch);
//   paper-optimal  p_i ~ sqrt(a_i) from the query's probe segments (each traced against both),
//                  class probabilities with a Dirichlet(1/2) prior so no needed branch gets 0;
//   paper-cost     paper-optimal with the paper's error^(1/4) heuristic.
#include "estimate/selection.h"
#include "estimate/visibility_estimator.h"

namespace proxyvis {

class PaperSelectionEstimator final : public VisibilityEstimator {
 public:
  // kind: kPaperEqual, kPaperOptimal or kPaperCost.
  PaperSelectionEstimator(EstimatorKind kind, ProxyClass cls, int probes);

  int probesPerPoint() const override { return probes_; }
  void estimate(const ShadingPointQuery& q, Rng& rng, std::span<double> out,
                RayCounts& counts) override;

 private:
  SelectionProbabilities probabilities(const ShadingPointQuery& q, RayCounts& counts) const;

  EstimatorKind kind_;
  ProxyClass cls_;
  int probes_;
};

}  // namespace proxyvis
