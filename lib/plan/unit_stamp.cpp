#include "plan/unit_stamp.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "util/error.h"
#include "util/json_field.h"
#include "util/program_build_id.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void foreignUnit(const fs::path& file, const std::string& what,
                              const std::string& unit_value, const std::string& plan_value) {
  throw Error(file.string(),
              fmt::format("this unit result is not of this plan: its {} is {}, the plan's is {}",
                          what, unit_value, plan_value),
              "it was rendered for another study, scene, seed or build",
              "delete it and its .done marker, then run the unit again (submit.sh --resume)");
}

}  // namespace

void to_json(nlohmann::json& j, const UnitStamp& s) {
  j = {{"unit", s.unit}, {"kind", s.kind},   {"scene_hash", s.scene_hash},
       {"seed", s.seed}, {"build", s.build}, {"study", s.study}};
}

void from_json(const nlohmann::json& j, UnitStamp& s) {
  const JsonField f(j);
  s.unit = f["unit"].asUint64();
  s.kind = f["kind"].asString();
  s.scene_hash = f["scene_hash"].asString();
  s.seed = f["seed"].asUint64();
  s.build = f["build"].asString();
  s.study = f["study"].asString();
}

UnitStamp plannedStamp(const StudyPlan& plan, size_t unit) {
  return {
      unit,         unitKindName(plan.units.at(unit).kind), plan.scene_hash, plan.seed, plan.build,
      studyId(plan)};
}

void requireSameStamp(const fs::path& file, const UnitStamp& found, const UnitStamp& expected) {
  if (found.unit != expected.unit)
    foreignUnit(file, "unit index", std::to_string(found.unit), std::to_string(expected.unit));
  if (found.kind != expected.kind) foreignUnit(file, "kind", found.kind, expected.kind);
  if (found.scene_hash != expected.scene_hash)
    foreignUnit(file, "scene hash", found.scene_hash, expected.scene_hash);
  if (found.seed != expected.seed)
    foreignUnit(file, "seed", std::to_string(found.seed), std::to_string(expected.seed));
  if (found.build != expected.build) foreignUnit(file, "build", found.build, expected.build);
  if (found.study != expected.study)
    foreignUnit(file, "study (flags and units)", found.study, expected.study);
}

void requirePlanningBuild(const std::string& planned_build, const fs::path& plan_file,
                          const std::string& to_do) {
  if (planned_build != programBuildId())
    throw Error(
        plan_file.string(),
        fmt::format("the plan was written by another build of render-compare ({}; this is {})",
                    planned_build, programBuildId()),
        "units and merge must be one build, or the tables could mix renderers", to_do);
}

}  // namespace proxyvis
