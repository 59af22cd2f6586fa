#include "compare_options.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "util/error.h"

namespace proxyvis {

void addCompareOptions(CLI::App& app, CompareOptions& o) {
  app.add_option("scene", o.scene, "Scene file (JSON, scenes/FORMAT.md)")->required();
  app.add_option("--out", o.out,
                 "Output folder (created if missing; each run replaces it as a whole)")
      ->required();
  app.add_option("--estimators", o.estimators, "Comma-separated estimators")->capture_default_str();
  app.add_option("--spp", o.spp,
                 "Comma-separated light samples per pixel for the equal-sample table")
      ->capture_default_str();
  app.add_option("--equal-time", o.equal_time,
                 "Seconds per render for the equal-time table (0 = no such table)")
      ->check(numberIn(0, kMaxRenderSeconds))
      ->capture_default_str();
  app.add_option("--reference-spp", o.reference_spp,
                 "Samples per pixel of the exact reference. 0 = automatic: 16 x the most samples "
                 "any compared render reached (equal-time renders included), at least 1024, "
                 "rounded up to a power of two. Either is rounded up to a multiple of its 16 "
                 "partial renders; a cached reference with at least as many samples is reused")
      ->check(integerIn(0, kMaxSpp))
      ->capture_default_str();
  app.add_option("--seeds", o.seeds,
                 "Independent renders per table cell (standard error over them)")
      ->check(integerIn(1, kMaxSeeds))
      ->capture_default_str();
  app.add_option("--repeats", o.repeats,
                 "Times the equal-time schedule is run (each with new seeds): seeds x repeats "
                 "runs per equal-time cell, and the efficiency's run-to-run spread over them")
      ->check(integerIn(1, kMaxRepeats))
      ->capture_default_str();
  addRenderFlags(app, o.render);
  addCommonOptions(app, o.common);
}

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
