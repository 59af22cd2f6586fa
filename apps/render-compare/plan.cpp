#include "plan.h"

#include <fmt/format.h>

#include <algorithm>

#include "reference.h"
#include "util/atomic_write.h"
#include "util/error.h"
#include "util/input_file.h"
#include "util/plan_folder.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

constexpr const char* kPlanFile = "plan.json";

[[noreturn]] void badPlan(const fs::path& file, const std::string& why) {
  throw Error(file.string(), "not a render-compare plan", why,
              "write it again with render-compare SCENE ... --plan DIR");
}

std::string absoluteText(const std::string& path) {
  return fs::absolute(path).lexically_normal().string();
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

std::vector<std::string> studyArgs(const CLI::App& app, const CompareOptions& o) {
  std::vector<std::string> args;
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->count() == 0) continue;
    if (opt->get_positional()) {
      args.push_back(absoluteText(o.scene.string()));
      continue;
    }
    PV_CHECK_MSG(!opt->get_lnames().empty(), "every render-compare option has a long name");
    const std::string name = "--" + opt->get_lnames().front();
    if (name == "--plan" || name == "--help" || name == "--version") continue;
    // One "--name=value" per value given: flags read back their "true" this way too.
    for (const std::string& value : opt->results())
      args.push_back(
          name + "=" +
          (name == "--out" || (name == "--json" && value != "-") ? absoluteText(value) : value));
  }
  return args;
}

void parseStudyArgs(const std::vector<std::string>& args, CompareOptions& options,
                    const fs::path& file) {
  CLI::App app{"render-compare", "render-compare"};
  addCompareOptions(app, options);
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 parses from the back
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    badPlan(file, std::string("its render-compare flags do not parse: ") + e.what());
  }
  options.resolve();
}

std::vector<PlannedUnit> planCellUnits(const CompareOptions& o) {
  std::vector<PlannedUnit> units;
  const size_t n = o.estimator_list.size();
  for (int spp : o.spp_list)
    for (int k = 0; k < o.seeds; ++k)
      for (size_t turn = 0; turn < n; ++turn) {
        // Seed k starts with estimator k mod n: no estimator always renders first (or last).
        PlannedUnit u;
        u.kind = UnitKind::kEqualSpp;
        u.estimator = o.estimator_list[(turn + size_t(k)) % n];
        u.spp = spp;
        u.run = k;
        units.push_back(u);
      }
  if (o.equal_time > 0)
    for (int run = 0; run < o.seeds * o.repeats; ++run) {
      PlannedUnit u;
      u.kind = UnitKind::kEqualTime;
      u.run = run;
      units.push_back(u);
    }
  PlannedUnit ceiling;
  ceiling.kind = UnitKind::kCeiling;
  units.push_back(ceiling);
  return units;
}

void planReference(StudyPlan& plan, int spp, int cached_spp) {
  if (cached_spp > 0) {
    plan.reference_cached = true;
    plan.reference_spp = cached_spp;
    return;
  }
  plan.reference_partials = std::min(kReferencePartials, spp);
  plan.reference_per_partial = (spp + plan.reference_partials - 1) / plan.reference_partials;
  plan.reference_spp = plan.reference_per_partial * plan.reference_partials;
  for (int r = 0; r < plan.reference_partials; ++r) {
    PlannedUnit u;
    u.kind = UnitKind::kReference;
    u.partial = r;
    plan.units.push_back(u);
  }
}

nlohmann::json planToJson(const StudyPlan& plan, const std::string& program) {
  nlohmann::json units = nlohmann::json::array();
  for (const PlannedUnit& u : plan.units) {
    nlohmann::json j = {{"kind", unitKindName(u.kind)}};
    if (u.kind == UnitKind::kEqualSpp)
      j.update({{"estimator", estimatorName(u.estimator)}, {"spp", u.spp}, {"seed_index", u.run}});
    if (u.kind == UnitKind::kEqualTime) j["run"] = u.run;
    if (u.kind == UnitKind::kReference) j["partial"] = u.partial;
    units.push_back(j);
  }
  return {{"version", 1},
          {"name", "render-compare"},
          {"units", plan.units.size()},
          {"run_unit", {program, "--run-unit", "{plan_dir}", "{unit}"}},
          {"merge", {program, "--merge", "{plan_dir}"}},
          {"render_compare",
           {{"args", plan.args},
            {"scene", plan.scene},
            {"scene_hash", plan.scene_hash},
            {"build", plan.build},
            {"seed", plan.seed},
            {"reference_spp", plan.reference_spp},
            {"reference_partials", plan.reference_partials},
            {"reference_per_partial", plan.reference_per_partial},
            {"unit_list", units}}}};
}

StudyPlan readPlan(const fs::path& dir) {
  const fs::path file = dir / kPlanFile;
  const std::string text = readTextFile(file);
  StudyPlan plan;
  try {
    const nlohmann::json all = nlohmann::json::parse(text);
    const nlohmann::json& j = all.at("render_compare");
    plan.args = j.at("args").get<std::vector<std::string>>();
    plan.scene = j.at("scene").get<std::string>();
    plan.scene_hash = j.at("scene_hash").get<std::string>();
    plan.build = j.at("build").get<std::string>();
    plan.seed = j.at("seed").get<uint64_t>();
    plan.reference_spp = j.at("reference_spp").get<int>();
    plan.reference_partials = j.at("reference_partials").get<int>();
    plan.reference_per_partial = j.at("reference_per_partial").get<int>();
    for (const nlohmann::json& u : j.at("unit_list")) {
      PlannedUnit p;
      const std::string kind = u.at("kind").get<std::string>();
      if (kind == "equal-spp") {
        p.kind = UnitKind::kEqualSpp;
        p.estimator = parseEstimatorName(u.at("estimator").get<std::string>());
        p.spp = u.at("spp").get<int>();
        p.run = u.at("seed_index").get<int>();
      } else if (kind == "equal-time") {
        p.kind = UnitKind::kEqualTime;
        p.run = u.at("run").get<int>();
      } else if (kind == "ceiling") {
        p.kind = UnitKind::kCeiling;
      } else if (kind == "reference") {
        p.kind = UnitKind::kReference;
        p.partial = u.at("partial").get<int>();
      } else {
        badPlan(file, "a unit has the unknown kind \"" + kind + "\"");
      }
      plan.units.push_back(p);
    }
    if (all.at("units").get<size_t>() != plan.units.size())
      badPlan(file, "\"units\" does not match the length of its unit list");
  } catch (const nlohmann::json::exception& e) {
    badPlan(file, std::string("its JSON is not what render-compare writes: ") + e.what());
  }
  return plan;
}

void writePlanFolder(const fs::path& dir, const StudyPlan& plan) {
  createPlanFolder(dir, "study");
  writeTextAtomically(dir / kPlanFile, planToJson(plan, planningProgram()).dump(2) + "\n");
}

}  // namespace proxyvis
