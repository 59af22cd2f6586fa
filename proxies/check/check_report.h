#pragma once
// How proxy-check shows a PairCheckReport: a human table, JSON, and a PLY of the error segments.
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "proxies/check/pair_check.h"

namespace proxyvis {

// Multi-line report: mesh statistics, the four classes (count, fraction, 95 % interval), derived
// quantities, the sampled class with the bound on the missed class, the exact verdict, and any
// mismatch or contradiction in capitals.
std::string formatHumanReport(const PairCheckReport& report);

// Keys: counts {HH, HM, MH, MM}, V_avg, f_hit, f_miss, intervals, sampled_class, exact,
// cost_ratio, seed, rays, seconds, plus details (meshes, distances, error rates, verdicts).
// Volumes are null for an open mesh, with a "volume_note" saying why (and "volume_ratio_note");
// "hausdorff" holds the distances in scene units and as fractions of the original's diagonal
// (proxies/check/distance_report.h).
nlohmann::json toJson(const PairCheckReport& report);

// proxy-check SCENE's report: each checked proxy's report, in the scene's order.
struct SceneCheckReport {
  std::string scene;  // the scene file
  uint64_t seed = 0, rays = 0;
  std::vector<const PairCheckReport*> checks;

  bool ok() const;  // no check failed
};

// Keys: scene, seed, rays, checks (toJson of each), ok.
nlohmann::json toJson(const SceneCheckReport& report);

// The ends of a rate's 95 % interval as the report writes them: [0, 1] when nothing was counted.
double rateLower(const RateEstimate& e);
double rateUpper(const RateEstimate& e);

// {"HH", "HM", "MH", "MM"}: the report's "counts".
nlohmann::json countsJson(const ClassCounts& counts);

// The error class the segments never showed ("HM'", "MH'" or "HM'+MH'" for an outside, inside
// or equivalent sampled class) and the upper 95 % bound on its rate over all segments; none for a
// general sampled class.
struct MissedClassBound {
  const char* name = nullptr;
  double upper = 0;
};
std::optional<MissedClassBound> missedClassBound(const PairCheckReport& report);

// ASCII PLY: two vertices and one edge per segment, colored red for HM' and blue for MH';
// written atomically.
void writeErrorSegmentsPly(const std::vector<ErrorSegment>& segments,
                           const std::filesystem::path& path);

}  // namespace proxyvis
