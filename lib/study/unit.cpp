#include "study/unit.h"

#include <fmt/format.h>

#include <limits>
#include <nlohmann/json.hpp>

#include "plan/unit_file.h"
#include "plan/unit_stamp.h"
#include "study/reference.h"
#include "study/runs.h"
#include "util/atomic_write.h"
#include "util/error.h"
#include "util/json_field.h"
#include "util/program_build_id.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

// Only the first seed's renders are drawn in the report: the others keep their radiance.
bool keepsAllImages(const PlannedUnit& u) {
  return (u.kind == UnitKind::kEqualSpp || u.kind == UnitKind::kEqualTime) && u.run == 0;
}

[[noreturn]] void notAUnit(const fs::path& path, const std::string& why) {
  throw Error(path.string(), "not a complete render-compare unit result", why,
              "delete its .done marker and run the unit again (submit.sh --resume)");
}

// The result's images, moved out of the unit file into its renders (3 per render: radiance,
// visibility, cost) and checked against the study's image size.
void takeImages(UnitResult& result, UnitFile& file, const fs::path& path, int width, int height) {
  if (file.images.size() != 3 * result.renders.size())
    notAUnit(path, "its image count does not match its renders");
  for (size_t i = 0; i < result.renders.size(); ++i) {
    RenderResult& r = result.renders[i];
    r.radiance = std::move(file.images[3 * i]);
    r.visibility = std::move(file.images[3 * i + 1]);
    r.cost = std::move(file.images[3 * i + 2]);
    if (r.radiance.width != width || r.radiance.height != height || r.radiance.channels != 3)
      throw Error(path.string(), "this unit result has the wrong image size",
                  fmt::format("{}x{}x{}, the study renders {}x{} RGB", r.radiance.width,
                              r.radiance.height, r.radiance.channels, width, height),
                  "delete it and its .done marker, then run the unit again");
  }
}

}  // namespace

void to_json(nlohmann::json& j, const UnitResult& r) {
  j = {{"facts", r.facts}, {"renders", r.renders}};
  if (r.ceiling) j["ceiling"] = *r.ceiling;
}

void from_json(const nlohmann::json& j, UnitResult& r) {
  const JsonField f(j);
  r.facts = f["facts"].get<SceneFacts>();
  r.renders = f["renders"].getList<RenderResult>();
  r.ceiling.reset();
  if (f.has("ceiling")) r.ceiling = f["ceiling"].get<CeilingUnitMeasurement>();
}

UnitResult runUnit(const RenderScene& scene, const SceneFacts& facts, const CompareOptions& o,
                   const StudyPlan& plan, size_t unit) {
  const PlannedUnit& u = plan.units.at(unit);
  UnitResult result;
  result.facts = facts;
  switch (u.kind) {
    case UnitKind::kEqualSpp: {
      RenderResult r = render(scene, runSettings(o, u.estimator, u.spp, 0, u.run));
      requireFinitePixels(
          r.radiance, scene.desc().path,
          fmt::format("the {} render (seed {})", estimatorName(u.estimator), u.run + 1));
      result.renders.push_back(std::move(r));
      break;
    }
    case UnitKind::kEqualTime:
      result.renders = runEqualTimeRun(scene, o, o.equal_time, u.run);
      break;
    case UnitKind::kCeiling: {
      // Units are independent, so the ceiling cannot read the cells' times: its time cap is a
      // share of the planned equal-time renders (without them, its pass cap alone).
      const double planned =
          o.equal_time > 0 ? o.equal_time * double(o.estimator_list.size()) * o.seeds * o.repeats
                           : std::numeric_limits<double>::infinity();
      RenderResult own;
      const bool needs_own = ceilingNeedsOwnRender(o);
      result.ceiling = measureCeiling(scene, o, planned, needs_own ? &own : nullptr);
      if (needs_own) result.renders.push_back(std::move(own));
      break;
    }
    case UnitKind::kReference:
      result.renders.push_back(
          render(scene, referencePartialSettings(u.partial, plan.reference_per_partial)));
      break;
  }
  if (!keepsAllImages(u))
    for (RenderResult& r : result.renders) r.visibility = Image{}, r.cost = Image{};
  return result;
}

void writeUnitResult(const fs::path& dir, const StudyPlan& plan, size_t unit,
                     const UnitResult& result) {
  UnitFile file;
  for (const RenderResult& r : result.renders) {
    file.images.push_back(r.radiance);
    file.images.push_back(r.visibility);
    file.images.push_back(r.cost);
  }
  UnitStamp stamp = plannedStamp(plan, unit);
  stamp.build = programBuildId();
  file.header = stamp;
  file.header.update(nlohmann::json(result));
  writeUnitFile(unitResultPath(dir, unit), std::move(file));
  writeTextAtomically(unitDonePath(dir, unit), fmt::format("{}\n", unit));  // the marker, last
}

UnitResult readUnitResult(const fs::path& dir, const StudyPlan& plan, size_t unit, int width,
                          int height) {
  const fs::path path = unitResultPath(dir, unit);
  std::error_code ec;
  if (!fs::exists(unitDonePath(dir, unit), ec) || !fs::exists(path, ec))
    throw Error(path.string(),
                fmt::format("unit {} of {} has not finished", unit, plan.units.size()),
                "its result or its .done marker is missing",
                "run the missing units first (submit.sh PLAN_DIR --resume)");
  UnitFile file = readUnitFile(path);  // its images are moved into the renders, not copied
  UnitResult result;
  try {
    const JsonField header(file.header);
    requireSameStamp(path, header.get<UnitStamp>(), plannedStamp(plan, unit));
    result = header.get<UnitResult>();
  } catch (const JsonFieldError& e) {
    notAUnit(path, "its header is not what a unit writes: " + e.path() + ": " + e.problem());
  }
  takeImages(result, file, path, width, height);
  return result;
}

}  // namespace proxyvis
