#pragma once
// What a learning estimator (roulette) found in a render: written in unit results and in the
// report's rows (JSON key "learned"), so it has one serializer, here.
#include <cstdint>
#include <nlohmann/json_fwd.hpp>

#include "estimate/roulette.h"

namespace proxyvis {

// What a learning estimator found, for reports (all zero for the others). Costs in the unit of
// EstimatorSetup::fixed_costs, or ns when measured.
struct LearnedSummary {
  uint32_t regions = 0;           // regions with statistics
  uint32_t regions_roulette = 0;  // of those, regions that used proxy + roulette in the last pass
  double p_proxy_blocked = 0;     // P(V' = 0) over all learned samples
  double error_given_blocked = 0, error_given_visible = 0;  // P(V != V' | V' = i)
  double var_exact = 0;  // mean over samples of V_p(1 - V_p), as learned
  // Efficiency of the last pass's plans relative to exact everywhere, predicted from the learned
  // models (sample-weighted Var and Cost summed over regions); 0 when unknown. Exploration cost
  // is not included.
  double predicted_efficiency = 0;
  ClassCosts costs;  // mean over regions' samples

  bool operator==(const LearnedSummary&) const = default;
};

// {"regions", "regions_roulette", "p_proxy_blocked", "error_given_blocked",
// "error_given_visible", "var_exact", "cost_proxy": [V'=0, V'=1], "cost_original": [..],
// "cost_per_sample", "predicted_efficiency"}; every number exactly (util/json_field.h).
void to_json(nlohmann::json& j, const LearnedSummary& l);
void from_json(const nlohmann::json& j, LearnedSummary& l);

}  // namespace proxyvis
