#pragma once
// A render-compare study's settings (its flags: render-compare parses them with CLI11) and the
// lists derived from them.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "estimate/visibility_estimator.h"
#include "render/render_options.h"
#include "util/app_main.h"

namespace proxyvis {

// The largest --seeds: a typo fails at once instead of running for days (the other ranges are
// render/render_options.h's).
inline constexpr uint64_t kMaxSeeds = 1000;
// The largest --repeats of the equal-time schedule.
inline constexpr uint64_t kMaxRepeats = 100;

struct CompareOptions {
  std::filesystem::path scene;
  std::filesystem::path out;
  std::string estimators = allEstimatorNames();
  std::string spp = "4,16";
  double equal_time = 1.0;  // seconds per render; 0 = no equal-time table
  int reference_spp = 0;    // 0 = max(1024, 16 × the largest spp reached), a power of two
  int seeds = 3;
  int repeats = 1;     // equal-time schedule repeats: seeds x repeats runs per equal-time cell
  RenderFlags render;  // image size, proxies, build, estimator settings (shared with `render`)
  CommonOptions common;

  // Parsed from the strings above by resolve(); throws Error for bad values.
  std::vector<EstimatorKind> estimator_list;
  std::vector<int> spp_list;
  void resolve();
  // The reference's samples per pixel given the most any compared render reached (equal-time
  // renders may reach far more than --spp): --reference-spp, else max(1024, 16 × largest),
  // rounded up to a power of two so that the cache key stays put from run to run.
  int referenceSpp(int largest_spp_reached) const;
};

// Which of render-compare's own flags were on the command line, for the studies that compare at
// equal samples (data-parallel, out-of-core): --estimators (else their own list); --equal-time
// and --repeats, which they refuse.
struct StudyFlagsGiven {
  bool estimators = false, equal_time = false, repeats = false;
};

}  // namespace proxyvis
