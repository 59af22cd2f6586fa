#pragma once
// A render-compare study as independent work units (docs/slurm.md): every equal-spp render
// (estimator x spp x seed), every equal-time run (seed x repeat, its estimators interleaved on
// one machine, since times measured on different machines do not compare), the ceiling
// measurement and each partial render of the reference. A unit's result depends only on the plan
// and its index, so units may run anywhere, in any order, and the merge combines them in unit
// order into the report one machine would write. The single-machine run is the same plan with
// every unit run in process.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "compare_options.h"

namespace proxyvis {

enum class UnitKind { kEqualSpp, kEqualTime, kCeiling, kReference };
const char* unitKindName(UnitKind kind);

struct PlannedUnit {
  UnitKind kind = UnitKind::kEqualSpp;
  EstimatorKind estimator = EstimatorKind::kExact;  // equal-spp
  int spp = 0;                                      // equal-spp
  int run = 0;      // equal-spp: the seed index; equal-time: seed + seeds x repeat
  int partial = 0;  // reference: its partial render
};

struct StudyPlan {
  std::vector<std::string> args;  // render-compare's flags, the scene and paths absolute
  std::string scene;              // absolute
  std::string scene_hash;         // sceneHash() at planning time
  std::string build;              // buildId() of the planning program
  uint64_t seed = 0;              // --seed
  // The reference: its samples, in `partials` renders of `per_partial` samples, unless an
  // earlier run's cached reference (in --out) is reused (single-machine runs only).
  int reference_spp = 0, reference_partials = 0, reference_per_partial = 0;
  bool reference_cached = false;
  std::vector<PlannedUnit> units;
};

// The flags as given, without --plan, with the scene, --out and --json absolute, so
// that a unit run from another folder sees the same study.
// `app` is the parsed command line (its --plan, --help and --version are left out).
std::vector<std::string> studyArgs(const CLI::App& app, const CompareOptions& options);

// Parses `args` as render-compare's flags into `options` (resolved); throws Error naming `file`.
void parseStudyArgs(const std::vector<std::string>& args, CompareOptions& options,
                    const std::filesystem::path& file);

// The cells' units in the order one machine runs them: equal-spp by spp, seed by seed, every
// estimator once per seed in an order that rotates with the seed; then the equal-time runs; then
// the ceiling.
std::vector<PlannedUnit> planCellUnits(const CompareOptions& options);

// Appends the reference's partial renders for `spp` samples (rounded up to a multiple of the
// partials), or only records a cached reference of `cached_spp` > 0 samples.
void planReference(StudyPlan& plan, int spp, int cached_spp = 0);

// plan.json: the keys submit.sh reads ("units", "run_unit", "merge", "name") and the study under
// "render_compare".
nlohmann::json planToJson(const StudyPlan& plan, const std::string& program);
// Reads DIR/plan.json; throws Error naming it when it is not a render-compare plan.
StudyPlan readPlan(const std::filesystem::path& dir);

// Writes DIR/plan.json (DIR and DIR/units created), refusing a folder that already holds units.
void writePlanFolder(const std::filesystem::path& dir, const StudyPlan& plan);

}  // namespace proxyvis
