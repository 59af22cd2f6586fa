#pragma once
// What ties a work unit's result to the plan it was run for: its index and kind, the scene's
// content hash, the seed, the build that ran it and the study's fingerprint. A result whose stamp
// differs from the plan's is refused, so a merge never mixes studies, scenes, seeds or builds.
// The checks are general: any sharded run (e.g. proxy-gen's shards, whose manifests carry a
// build and a scene hash) can stamp its pieces and check them with requireSameStamp and
// requirePlanningBuild.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "plan/plan.h"

namespace proxyvis {

struct UnitStamp {
  uint64_t unit = 0;
  std::string kind;        // unitKindName()
  std::string scene_hash;  // sceneHash() of the scene the unit rendered
  uint64_t seed = 0;
  std::string build;  // programBuildId() of the program that ran the unit
  std::string study;  // studyId() of its plan

  bool operator==(const UnitStamp&) const = default;
};

// {"unit", "kind", "scene_hash", "seed", "build", "study"}: a unit result header's first keys.
void to_json(nlohmann::json& j, const UnitStamp& s);
void from_json(const nlohmann::json& j, UnitStamp& s);

// The stamp a result of unit `unit` of `plan` must carry (the planning build's).
UnitStamp plannedStamp(const StudyPlan& plan, size_t unit);

// Throws Error naming `file` and the first field in which `found` differs from `expected`
// ("its scene hash is A, the plan's is B").
void requireSameStamp(const std::filesystem::path& file, const UnitStamp& found,
                      const UnitStamp& expected);

// Units and merge must be the build that planned: another build may trace or round differently.
// Throws Error naming `plan_file` when `planned_build` is not this program's; `to_do` says what
// to do instead.
void requirePlanningBuild(const std::string& planned_build, const std::filesystem::path& plan_file,
                          const std::string& to_do);

}  // namespace proxyvis
