#pragma once
// render-compare's settings (the CLI flags) and the pieces of work derived from them.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "estimate/roulette.h"
#include "estimate/visibility_estimator.h"
#include "scene/scene_desc.h"  // kMaxImageSide: --width/--height share the scene format's limit
#include "util/app_main.h"

namespace proxyvis {

// The ranges of the numeric flags: what a run can use, so that a typo fails at once instead of
// running for days or bypassing the scene's own limits.
inline constexpr uint64_t kMaxSpp = 1 << 24;  // also the largest automatic reference
inline constexpr double kMaxEqualTimeSeconds = 86400;
inline constexpr uint64_t kMaxSeeds = 1000;
inline constexpr uint64_t kMaxProbes = 4096;

struct CompareOptions {
  std::filesystem::path scene;
  std::filesystem::path out;
  std::string estimators = allEstimatorNames();
  std::string spp = "4,16";
  double equal_time = 1.0;  // seconds per render; 0 = no equal-time table
  int reference_spp = 0;    // 0 = max(1024, 16 × the largest spp reached), a power of two
  int seeds = 3;
  int width = 0, height = 0;  // 0 (not given) = the scene's resolution
  std::string proxy_kind;     // which proxy of each mesh ("outside", "inside", "general")
  double q_min = 0.05;
  int probes = 16;
  // Roulette's cost model: "measured" (per region, from timed rays and queries: its choices then
  // depend on timing and are not bit-reproducible, the estimate stays unbiased) or five numbers
  // in ns "c_p0,c_p1,c_o0,c_o1,c_s" (fixed: the same seed gives the same image at any thread
  // count).
  std::string roulette_costs = "measured";
  // How instances are traced: "instanced" (one BVH per mesh), "flat" (every instance copied into
  // one BVH), "auto" (flat when the flattened originals and proxies stay under kAutoFlatTriangles:
  // docs/design.md, costs point 2, the fastest exact configuration that fits in memory).
  std::string build = "auto";
  static constexpr uint64_t kAutoFlatTriangles = 8'000'000;
  CommonOptions common;

  // Parsed from the strings above by resolve(); throws Error for bad values.
  std::vector<EstimatorKind> estimator_list;
  std::vector<int> spp_list;
  std::optional<ClassCosts> fixed_costs;  // from roulette_costs
  void resolve();
  // The reference's samples per pixel given the most any compared render reached (equal-time
  // renders may reach far more than --spp): --reference-spp, else max(1024, 16 × largest),
  // rounded up to a power of two so that the cache key stays put from run to run.
  int referenceSpp(int largest_spp_reached) const;
};

void addCompareOptions(CLI::App& app, CompareOptions& options);

}  // namespace proxyvis
