#include "compare_options.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

#include "util/error.h"

namespace proxyvis {

namespace {

std::vector<std::string> splitList(const std::string& list) {
  std::vector<std::string> items;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) items.push_back(item);
  return items;
}

}  // namespace

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
      ->check(numberIn(0, kMaxEqualTimeSeconds))
      ->capture_default_str();
  app.add_option("--reference-spp", o.reference_spp,
                 "Samples per pixel of the exact reference (0 = max(1024, 16 x largest --spp))")
      ->check(integerIn(0, kMaxSpp))
      ->capture_default_str();
  app.add_option("--seeds", o.seeds,
                 "Independent renders per table cell (standard error over them)")
      ->check(integerIn(1, kMaxSeeds))
      ->capture_default_str();
  // The scene's own limit (scenes/FORMAT.md): an override may not bypass it.
  app.add_option("--width", o.width, "Override the scene's image width")
      ->check(integerIn(1, kMaxImageSide));
  app.add_option("--height", o.height, "Override the scene's image height")
      ->check(integerIn(1, kMaxImageSide));
  app.add_option("--proxy-kind", o.proxy_kind,
                 "Use each mesh's proxy of this kind (outside, inside, general; default: first)")
      ->check(CLI::IsMember({"outside", "inside", "general"}));
  app.add_option("--q-min", o.q_min, "Roulette floor where an error class is possible")
      ->check(numberIn(1e-6, 1.0))
      ->capture_default_str();
  app.add_option("--probes", o.probes, "Probe rays per shading point (paper-optimal, paper-cost)")
      ->check(integerIn(1, kMaxProbes))
      ->capture_default_str();
  app.add_option("--build", o.build,
                 "Instances as Embree instances, flattened into one BVH, or auto (flat when the "
                 "flattened scene has at most 8 M triangles)")
      ->check(CLI::IsMember({"auto", "flat", "instanced"}))
      ->capture_default_str();
  app.add_option("--roulette-costs", o.roulette_costs,
                 "Roulette's ray costs: 'measured' (per region, timing-dependent choices) or "
                 "'c_p0,c_p1,c_o0,c_o1,c_s' in ns (fixed: bit-reproducible)")
      ->capture_default_str();
  addCommonOptions(app, o.common);
}

void CompareOptions::resolve() {
  estimator_list.clear();
  for (const std::string& name : splitList(estimators)) {
    EstimatorKind kind = parseEstimatorName(name);
    if (std::find(estimator_list.begin(), estimator_list.end(), kind) == estimator_list.end())
      estimator_list.push_back(kind);
  }
  if (estimator_list.empty())
    throw Error({}, "--estimators is empty", {},
                "name at least one estimator, e.g. exact,roulette");
  spp_list.clear();
  const CLI::Validator spp_check = integerIn(1, kMaxSpp);
  for (std::string item : splitList(spp)) {
    const std::string problem = spp_check(item);
    if (!problem.empty())
      throw Error({}, "--spp: " + problem, {}, "give a comma-separated list such as 4,16");
    spp_list.push_back(std::stoi(item));
  }
  fixed_costs.reset();
  if (roulette_costs != "measured") {
    std::vector<double> c;
    for (const std::string& item : splitList(roulette_costs)) {
      const std::optional<double> v = parseNumber(item);
      if (!v || *v < 0) {
        c.clear();
        break;
      }
      c.push_back(*v);
    }
    if (c.size() != 5 || !(c[0] > 0 && c[1] > 0 && c[2] > 0 && c[3] > 0))
      throw Error({}, "--roulette-costs: '" + roulette_costs + "' is not 'measured' or five costs",
                  "expected c_p|V'=0, c_p|V'=1, c_o|V'=0, c_o|V'=1 (> 0) and c_s (>= 0) in ns",
                  "e.g. --roulette-costs 40,20,300,25,60 (bench_render prints measured ones)");
    ClassCosts costs;
    costs.proxy[0] = c[0];
    costs.proxy[1] = c[1];
    costs.original[0] = c[2];
    costs.original[1] = c[3];
    costs.per_sample = c[4];
    fixed_costs = costs;
  }
  std::sort(spp_list.begin(), spp_list.end());
  spp_list.erase(std::unique(spp_list.begin(), spp_list.end()), spp_list.end());
  if (spp_list.empty() && !(equal_time > 0))
    throw Error({}, "nothing to compare", "--spp is empty and --equal-time is 0");
}

int CompareOptions::referenceSpp(int largest_spp_reached) const {
  if (reference_spp > 0) return reference_spp;
  int64_t wanted = std::max<int64_t>(1024, 16 * int64_t(largest_spp_reached));
  int64_t spp = 1;
  while (spp < wanted) spp *= 2;
  return int(std::min<int64_t>(spp, int64_t(kMaxSpp)));
}

}  // namespace proxyvis
