#include "study/compare_options.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "util/error.h"

namespace proxyvis {

void CompareOptions::resolve() {
  estimator_list.clear();
  for (const std::string& name : splitCommaList(estimators)) {
    EstimatorKind kind = parseEstimatorName(name);
    if (std::find(estimator_list.begin(), estimator_list.end(), kind) == estimator_list.end())
      estimator_list.push_back(kind);
  }
  if (estimator_list.empty())
    throw Error({}, "--estimators is empty", {},
                "name at least one estimator, e.g. exact,roulette");
  spp_list.clear();
  const CLI::Validator spp_check = integerIn(1, kMaxSpp);
  for (std::string item : splitCommaList(spp)) {
    const std::string problem = spp_check(item);
    if (!problem.empty())
      throw Error({}, "--spp: " + problem, {}, "give a comma-separated list such as 4,16");
    spp_list.push_back(std::stoi(item));
  }
  render.resolve();
  std::sort(spp_list.begin(), spp_list.end());
  spp_list.erase(std::unique(spp_list.begin(), spp_list.end()), spp_list.end());
  if (spp_list.empty() && !(equal_time > 0))
    throw Error({}, "nothing to compare", "--spp is empty and --equal-time is 0");
  if (repeats > 1 && !(equal_time > 0))
    throw Error({}, "--repeats has nothing to repeat", "it repeats the equal-time table",
                "give --equal-time a budget, or drop --repeats");
}

int CompareOptions::referenceSpp(int largest_spp_reached) const {
  if (reference_spp > 0) return reference_spp;
  int64_t wanted = std::max<int64_t>(1024, 16 * int64_t(largest_spp_reached));
  int64_t spp = 1;
  while (spp < wanted) spp *= 2;
  return int(std::min<int64_t>(spp, int64_t(kMaxSpp)));
}

}  // namespace proxyvis
