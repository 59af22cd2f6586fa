#pragma once
// A study as independent work units (docs/slurm.md): a plan folder holds plan.json, which names
// the study's units, and units/K.result with the marker units/K.done for each unit that ran. A
// unit's result depends only on the plan and its index, so units may run anywhere, in any order,
// and the merge combines them in unit order into what one machine would write.
//
// render-compare's units are every equal-spp render (estimator x spp x seed), every equal-time
// run (seed x repeat, its estimators interleaved on one machine, since times measured on
// different machines do not compare), the ceiling measurement and each partial render of the
// reference (lib/study plans and runs them).
#include <cstdint>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "estimate/visibility_estimator.h"

namespace proxyvis {

enum class UnitKind { kEqualSpp, kEqualTime, kCeiling, kReference };
const char* unitKindName(UnitKind kind);

struct PlannedUnit {
  UnitKind kind = UnitKind::kEqualSpp;
  EstimatorKind estimator = EstimatorKind::kExact;  // equal-spp
  int spp = 0;                                      // equal-spp
  int run = 0;      // equal-spp: the seed index; equal-time: seed + seeds x repeat
  int partial = 0;  // reference: its partial render

  bool operator==(const PlannedUnit&) const = default;
};

struct StudyPlan {
  std::vector<std::string> args;  // render-compare's flags, the scene and paths absolute
  std::string scene;              // absolute
  std::string scene_hash;         // sceneHash() at planning time
  std::string build;              // programBuildId() of the planning program
  uint64_t seed = 0;              // --seed
  // The reference: its samples, in `partials` renders of `per_partial` samples, unless an
  // earlier run's cached reference (in --out) is reused (single-machine runs only: not in JSON).
  int reference_spp = 0, reference_partials = 0, reference_per_partial = 0;
  bool reference_cached = false;
  std::vector<PlannedUnit> units;

  bool operator==(const StudyPlan&) const = default;
};

// A unit: {"kind"} and its kind's own keys ("estimator", "spp", "seed_index" for equal-spp;
// "run" for equal-time; "partial" for reference).
void to_json(nlohmann::json& j, const PlannedUnit& u);
void from_json(const nlohmann::json& j, PlannedUnit& u);
// The study under plan.json's "render_compare": "args", "scene", "scene_hash", "build", "seed",
// "reference_spp", "reference_partials", "reference_per_partial", "unit_list".
void to_json(nlohmann::json& j, const StudyPlan& plan);
void from_json(const nlohmann::json& j, StudyPlan& plan);

// A fingerprint of the study (its JSON: flags and unit list): a unit result of another plan
// with the same scene and seed is still refused.
std::string studyId(const StudyPlan& plan);

// plan.json: the keys submit.sh reads ("units", "run_unit", "merge", "name") and the study under
// "render_compare"; `program` is the executable the units and the merge run.
nlohmann::json planToJson(const StudyPlan& plan, const std::string& program);
// Reads DIR/plan.json; throws Error naming it (and the JSON path) when it is not a plan.
StudyPlan readPlan(const std::filesystem::path& dir);

// Writes DIR/plan.json (DIR and DIR/units created), refusing a folder that already holds units.
void writePlanFolder(const std::filesystem::path& dir, const StudyPlan& plan);

// DIR/units/K.result and DIR/units/K.done.
std::filesystem::path unitResultPath(const std::filesystem::path& dir, size_t unit);
std::filesystem::path unitDonePath(const std::filesystem::path& dir, size_t unit);

}  // namespace proxyvis
