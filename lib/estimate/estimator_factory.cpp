// The estimators by name, and makeEstimator(): one file per estimator (exact_estimator.h,
// culling_estimator.h, paper_selection_estimator.h, roulette_estimator.h).
#include <string>

#include "estimate/culling_estimator.h"
#include "estimate/exact_estimator.h"
#include "estimate/paper_selection_estimator.h"
#include "estimate/roulette_estimator.h"
#include "estimate/visibility_estimator.h"
#include "util/error.h"

namespace proxyvis {

namespace {

constexpr EstimatorKind kAllKinds[] = {EstimatorKind::kExact,      EstimatorKind::kCulling,
                                       EstimatorKind::kPaperEqual, EstimatorKind::kPaperOptimal,
                                       EstimatorKind::kPaperCost,  EstimatorKind::kRoulette};

}  // namespace

const char* estimatorName(EstimatorKind kind) {
  switch (kind) {
    case EstimatorKind::kExact:
      return "exact";
    case EstimatorKind::kCulling:
      return "culling";
    case EstimatorKind::kPaperEqual:
      return "paper-equal";
    case EstimatorKind::kPaperOptimal:
      return "paper-optimal";
    case EstimatorKind::kPaperCost:
      return "paper-cost";
    case EstimatorKind::kRoulette:
      return "roulette";
  }
  return "?";
}

EstimatorKind parseEstimatorName(const std::string& name) {
  for (EstimatorKind k : kAllKinds)
    if (name == estimatorName(k)) return k;
  throw Error("", "unknown estimator '" + name + "'",
              "valid estimators: " + allEstimatorNames(", "));
}

std::vector<EstimatorKind> allEstimators() {
  return std::vector<EstimatorKind>(std::begin(kAllKinds), std::end(kAllKinds));
}

std::string allEstimatorNames(const char* separator) {
  std::string names;
  for (EstimatorKind k : kAllKinds) {
    if (!names.empty()) names += separator;
    names += estimatorName(k);
  }
  return names;
}

std::unique_ptr<VisibilityEstimator> makeEstimator(const EstimatorSetup& setup) {
  if (setup.num_regions == 0) throw Error("", "estimator needs at least one learning region");
  if (!(setup.q_min > 0 && setup.q_min <= 1))
    throw Error("", "q_min must be in (0, 1]", "got " + std::to_string(setup.q_min),
                "a floor of 0 would make roulette biased where an error class is possible");
  if (setup.probes_per_point < 0) throw Error("", "probes per point must be >= 0");
  switch (setup.kind) {
    case EstimatorKind::kExact:
      return std::make_unique<ExactEstimator>();
    case EstimatorKind::kCulling:
      return std::make_unique<CullingEstimator>(setup.proxy_class);
    case EstimatorKind::kPaperEqual:
    case EstimatorKind::kPaperOptimal:
    case EstimatorKind::kPaperCost:
      return std::make_unique<PaperSelectionEstimator>(setup.kind, setup.proxy_class,
                                                       setup.probes_per_point);
    case EstimatorKind::kRoulette:
      return std::make_unique<RouletteEstimator>(setup);
  }
  throw Error("", "unknown estimator kind");
}

}  // namespace proxyvis
