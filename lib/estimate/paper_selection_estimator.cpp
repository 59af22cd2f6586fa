#include "estimate/paper_selection_estimator.h"

#include "estimate/class_probabilities.h"
#include "estimate/sample_estimators.h"

namespace proxyvis {

namespace {

// Dirichlet pseudo-count per possible class for the probe-based estimates: keeps every p > 0
// where its class can occur (unbiasedness does not depend on the probes being representative).
constexpr double kProbePrior = 0.5;

}  // namespace

PaperSelectionEstimator::PaperSelectionEstimator(EstimatorKind kind, ProxyClass cls, int probes)
    : kind_(kind), cls_(cls), probes_(kind == EstimatorKind::kPaperEqual ? 0 : probes) {}

void PaperSelectionEstimator::estimate(const ShadingPointQuery& q, Rng& rng, std::span<double> out,
                                       RayCounts& counts) {
  const SelectionProbabilities p = probabilities(q, counts);
  for (size_t j = 0; j < q.segments.size(); ++j)
    out[j] = selectionSample(*q.tracer, q.segments[j], p, rng.uniformDouble(), counts);
}

SelectionProbabilities PaperSelectionEstimator::probabilities(const ShadingPointQuery& q,
                                                              RayCounts& counts) const {
  if (kind_ == EstimatorKind::kPaperEqual) return equalProbabilities(cls_);
  ClassCounts cc;
  for (const Segment& s : q.probes) {
    ++counts.probe;
    cc.add(q.tracer->originalVisible(s), q.tracer->proxyVisible(s));
  }
  const ClassProbabilities c = estimateClassProbabilities(cc, cls_, kProbePrior);
  const SelectionProbabilities opt = optimalProbabilities(c, cls_);
  if (kind_ == EstimatorKind::kPaperOptimal) return opt;
  return costHeuristicProbabilities(opt, c.error());  // smoothed: > 0 if errors are possible
}

}  // namespace proxyvis
