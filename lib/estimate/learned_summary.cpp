#include "estimate/learned_summary.h"

#include <nlohmann/json.hpp>

#include "util/json_field.h"

namespace proxyvis {

void to_json(nlohmann::json& j, const LearnedSummary& l) {
  j = {{"regions", l.regions},
       {"regions_roulette", l.regions_roulette},
       {"p_proxy_blocked", l.p_proxy_blocked},
       {"error_given_blocked", l.error_given_blocked},
       {"error_given_visible", l.error_given_visible},
       {"var_exact", l.var_exact},
       {"cost_proxy", {l.costs.proxy[0], l.costs.proxy[1]}},
       {"cost_original", {l.costs.original[0], l.costs.original[1]}},
       {"cost_per_sample", l.costs.per_sample},
       {"predicted_efficiency", l.predicted_efficiency}};
}

void from_json(const nlohmann::json& j, LearnedSummary& l) {
  const JsonField f(j);
  l.regions = f["regions"].asUint32();
  l.regions_roulette = f["regions_roulette"].asUint32();
  l.p_proxy_blocked = f["p_proxy_blocked"].asDouble();
  l.error_given_blocked = f["error_given_blocked"].asDouble();
  l.error_given_visible = f["error_given_visible"].asDouble();
  l.var_exact = f["var_exact"].asDouble();
  for (size_t i = 0; i < 2; ++i) {
    l.costs.proxy[i] = f["cost_proxy"][i].asDouble();
    l.costs.original[i] = f["cost_original"][i].asDouble();
  }
  l.costs.per_sample = f["cost_per_sample"].asDouble();
  l.predicted_efficiency = f["predicted_efficiency"].asDouble();
}

}  // namespace proxyvis
