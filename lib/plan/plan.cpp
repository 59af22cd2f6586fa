#include "plan/plan.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "util/atomic_write.h"
#include "util/error.h"
#include "util/fnv1a.h"
#include "util/input_file.h"
#include "util/json_field.h"
#include "util/plan_folder.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

constexpr const char* kPlanFile = "plan.json";

[[noreturn]] void badPlan(const fs::path& file, const std::string& why) {
  throw Error(file.string(), "not a render-compare plan", why,
              "write it again with render-compare SCENE ... --plan DIR");
}

UnitKind parseUnitKind(const JsonField& f) {
  const std::string kind = f.asString();
  for (UnitKind k :
       {UnitKind::kEqualSpp, UnitKind::kEqualTime, UnitKind::kCeiling, UnitKind::kReference})
    if (kind == unitKindName(k)) return k;
  f.fail("unknown unit kind \"" + kind + "\"", "known: equal-spp, equal-time, ceiling, reference");
}

}  // namespace

const char* unitKindName(UnitKind kind) {
  switch (kind) {
    case UnitKind::kEqualSpp:
      return "equal-spp";
    case UnitKind::kEqualTime:
      return "equal-time";
    case UnitKind::kCeiling:
      return "ceiling";
    case UnitKind::kReference:
      return "reference";
  }
  return "?";
}

void to_json(nlohmann::json& j, const PlannedUnit& u) {
  j = {{"kind", unitKindName(u.kind)}};
  if (u.kind == UnitKind::kEqualSpp)
    j.update({{"estimator", estimatorName(u.estimator)}, {"spp", u.spp}, {"seed_index", u.run}});
  if (u.kind == UnitKind::kEqualTime) j["run"] = u.run;
  if (u.kind == UnitKind::kReference) j["partial"] = u.partial;
}

void from_json(const nlohmann::json& j, PlannedUnit& u) {
  const JsonField f(j);
  u = PlannedUnit{};
  u.kind = parseUnitKind(f["kind"]);
  if (u.kind == UnitKind::kEqualSpp) {
    const JsonField name = f["estimator"];
    try {
      u.estimator = parseEstimatorName(name.asString());
    } catch (const JsonFieldError&) {
      throw;
    } catch (const Error& e) {
      name.fail(e.what());
    }
    u.spp = f["spp"].asInt();
    u.run = f["seed_index"].asInt();
  }
  if (u.kind == UnitKind::kEqualTime) u.run = f["run"].asInt();
  if (u.kind == UnitKind::kReference) u.partial = f["partial"].asInt();
}

void to_json(nlohmann::json& j, const StudyPlan& plan) {
  j = {{"args", plan.args},
       {"scene", plan.scene},
       {"scene_hash", plan.scene_hash},
       {"build", plan.build},
       {"seed", plan.seed},
       {"reference_spp", plan.reference_spp},
       {"reference_partials", plan.reference_partials},
       {"reference_per_partial", plan.reference_per_partial},
       {"unit_list", plan.units}};
}

void from_json(const nlohmann::json& j, StudyPlan& plan) {
  const JsonField f(j);
  plan = StudyPlan{};
  plan.args = f["args"].asStrings();
  plan.scene = f["scene"].asString();
  plan.scene_hash = f["scene_hash"].asString();
  plan.build = f["build"].asString();
  plan.seed = f["seed"].asUint64();
  plan.reference_spp = f["reference_spp"].asInt();
  plan.reference_partials = f["reference_partials"].asInt();
  plan.reference_per_partial = f["reference_per_partial"].asInt();
  plan.units = f["unit_list"].getList<PlannedUnit>();
}

std::string studyId(const StudyPlan& plan) {
  return fmt::format("{:016x}", fnv1a(nlohmann::json(plan).dump()));
}

nlohmann::json planToJson(const StudyPlan& plan, const std::string& program) {
  nlohmann::json j = PlanCommands{.version = 1,
                                  .name = "render-compare",
                                  .units = plan.units.size(),
                                  .run_unit = {program, "--run-unit", "{plan_dir}", "{unit}"},
                                  .merge = {program, "--merge", "{plan_dir}"}};
  j["render_compare"] = plan;
  return j;
}

StudyPlan readPlan(const fs::path& dir) {
  const fs::path file = dir / kPlanFile;
  const std::string text = readTextFile(file);
  nlohmann::json all;
  try {
    all = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    badPlan(file, std::string("its JSON does not parse: ") + e.what());
  }
  try {
    const JsonField top(all);
    const PlanCommands commands = top.get<PlanCommands>();
    StudyPlan plan = top["render_compare"].get<StudyPlan>();
    if (commands.units != plan.units.size())
      badPlan(file, "\"units\" does not match the length of its unit list");
    return plan;
  } catch (const JsonFieldError& e) {
    badPlan(file, e.path() + ": " + e.problem());
  }
}

void writePlanFolder(const fs::path& dir, const StudyPlan& plan) {
  createPlanFolder(dir, "study");
  writeTextAtomically(dir / kPlanFile, planToJson(plan, planningProgram()).dump(2) + "\n");
}

fs::path unitResultPath(const fs::path& dir, size_t unit) {
  return dir / "units" / fmt::format("{}.result", unit);
}
fs::path unitDonePath(const fs::path& dir, size_t unit) {
  return dir / "units" / fmt::format("{}.done", unit);
}

}  // namespace proxyvis
