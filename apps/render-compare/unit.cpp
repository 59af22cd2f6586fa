#include "unit.h"

#include <fmt/format.h>
#include <tbb/global_control.h>

#include <cstdio>
#include <cstdlib>
#include <limits>

#include "ceiling_phase.h"
#include "metrics/ceiling_report.h"
#include "reference.h"
#include "runs.h"
#include "scene/scene_desc.h"
#include "unit_file.h"
#include "util/app_main.h"
#include "util/atomic_write.h"
#include "util/error.h"
#include "util/fnv1a.h"
#include "util/program_build_id.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

nlohmann::json factsToJson(const SceneFacts& f) {
  return {{"proxy_class", proxyClassName(f.proxy_class)},
          {"uses_proxies", f.uses_proxies},
          {"instances_flattened", f.instances_flattened},
          {"build", f.build},
          {"build_reason", f.build_reason},
          {"build_description", f.build_description},
          {"original_triangles", f.original_triangles},
          {"proxy_triangles", f.proxy_triangles},
          {"warnings", f.warnings},
          {"proxy_classes", f.proxy_classes},
          {"trust_notes", f.trust_notes}};
}

SceneFacts factsFromJson(const nlohmann::json& j) {
  SceneFacts f;
  f.proxy_class = parseProxyClass(j.at("proxy_class").get<std::string>()).value();
  f.uses_proxies = j.at("uses_proxies").get<bool>();
  f.instances_flattened = j.at("instances_flattened").get<bool>();
  f.build = j.at("build").get<std::string>();
  f.build_reason = j.at("build_reason").get<std::string>();
  f.build_description = j.at("build_description").get<std::string>();
  f.original_triangles = j.at("original_triangles").get<uint64_t>();
  f.proxy_triangles = j.at("proxy_triangles").get<uint64_t>();
  f.warnings = j.at("warnings").get<std::vector<std::string>>();
  f.proxy_classes = j.at("proxy_classes");
  f.trust_notes = j.at("trust_notes").get<std::vector<std::string>>();
  return f;
}

nlohmann::json costsToJson(const ClassCosts& c) {
  return {{"proxy", {c.proxy[0], c.proxy[1]}},
          {"original", {c.original[0], c.original[1]}},
          {"per_sample", c.per_sample}};
}

ClassCosts costsFromJson(const nlohmann::json& j) {
  ClassCosts c;
  for (int i = 0; i < 2; ++i) {
    c.proxy[i] = j.at("proxy").at(i).get<double>();
    c.original[i] = j.at("original").at(i).get<double>();
  }
  c.per_sample = j.at("per_sample").get<double>();
  return c;
}

// Every number of a RenderResult (doubles round-trip exactly through nlohmann's JSON); the
// images go to the unit file's image list.
nlohmann::json renderToJson(const RenderResult& r) {
  const LearnedSummary& l = r.learned;
  return {{"spp", r.spp},
          {"passes", r.passes},
          {"seconds", r.seconds},
          {"cpu_seconds", r.cpu_seconds},
          {"shading_seconds", r.shading_seconds},
          {"primary_seconds", r.primary_seconds},
          {"visibility_seconds", r.visibility_seconds},
          {"rays", {r.rays.proxy, r.rays.original, r.rays.probe}},
          {"primary_rays", r.primary_rays},
          {"shadow_segments", r.shadow_segments},
          {"proxy_class", proxyClassName(r.proxy_class)},
          {"learned",
           {{"regions", l.regions},
            {"regions_roulette", l.regions_roulette},
            {"p_proxy_blocked", l.p_proxy_blocked},
            {"error_given_blocked", l.error_given_blocked},
            {"error_given_visible", l.error_given_visible},
            {"var_exact", l.var_exact},
            {"predicted_efficiency", l.predicted_efficiency},
            {"costs", costsToJson(l.costs)}}}};
}

RenderResult renderFromJson(const nlohmann::json& j) {
  RenderResult r;
  r.spp = j.at("spp").get<int>();
  r.passes = j.at("passes").get<int>();
  r.seconds = j.at("seconds").get<double>();
  r.cpu_seconds = j.at("cpu_seconds").get<double>();
  r.shading_seconds = j.at("shading_seconds").get<double>();
  r.primary_seconds = j.at("primary_seconds").get<double>();
  r.visibility_seconds = j.at("visibility_seconds").get<double>();
  r.rays.proxy = j.at("rays").at(0).get<uint64_t>();
  r.rays.original = j.at("rays").at(1).get<uint64_t>();
  r.rays.probe = j.at("rays").at(2).get<uint64_t>();
  r.primary_rays = j.at("primary_rays").get<uint64_t>();
  r.shadow_segments = j.at("shadow_segments").get<uint64_t>();
  r.proxy_class = parseProxyClass(j.at("proxy_class").get<std::string>()).value();
  const nlohmann::json& l = j.at("learned");
  r.learned.regions = l.at("regions").get<uint32_t>();
  r.learned.regions_roulette = l.at("regions_roulette").get<uint32_t>();
  r.learned.p_proxy_blocked = l.at("p_proxy_blocked").get<double>();
  r.learned.error_given_blocked = l.at("error_given_blocked").get<double>();
  r.learned.error_given_visible = l.at("error_given_visible").get<double>();
  r.learned.var_exact = l.at("var_exact").get<double>();
  r.learned.predicted_efficiency = l.at("predicted_efficiency").get<double>();
  r.learned.costs = costsFromJson(l.at("costs"));
  return r;
}

// A fingerprint of the study (its flags and unit list): a unit of another plan with the same
// scene and seed is still refused.
std::string studyId(const StudyPlan& plan) {
  return fmt::format("{:016x}", fnv1a(planToJson(plan, "").at("render_compare").dump()));
}

// Only the first seed's renders are drawn in the report: the others keep their radiance.
bool keepsAllImages(const PlannedUnit& u) {
  return (u.kind == UnitKind::kEqualSpp || u.kind == UnitKind::kEqualTime) && u.run == 0;
}

[[noreturn]] void foreignUnit(const fs::path& file, const std::string& what,
                              const std::string& unit_value, const std::string& plan_value) {
  throw Error(file.string(),
              fmt::format("this unit result is not of this plan: its {} is {}, the plan's is {}",
                          what, unit_value, plan_value),
              "it was rendered for another study, scene, seed or build",
              "delete it and its .done marker, then run the unit again (submit.sh --resume)");
}

}  // namespace

SceneFacts sceneFacts(const RenderScene& scene, const std::vector<ProxyTrust>& trust) {
  SceneFacts f;
  f.proxy_class = scene.proxyClass();
  f.uses_proxies = scene.usesProxies();
  f.instances_flattened = scene.instancesFlattened();
  f.build = scene.buildChoice().name();
  f.build_reason = scene.buildChoice().reason;
  f.build_description = scene.buildChoice().description();
  f.original_triangles = scene.originalTriangles();
  f.proxy_triangles = scene.proxyTriangles();
  f.warnings = scene.warnings();
  for (const ProxyTrust& t : trust) {
    f.proxy_classes.push_back({{"mesh", t.mesh},
                               {"proxy", t.proxy.filename().string()},
                               {"claimed", t.claimed ? proxyClassName(*t.claimed) : "none"},
                               {"class", proxyClassName(t.trust.trusted)},
                               {"class_status", classStatusName(t.trust.status)},
                               {"reason", t.trust.reason}});
    if (t.trust.status == ClassStatus::kReVerified || t.trust.status == ClassStatus::kDowngraded)
      f.trust_notes.push_back("Proxy class " + describeProxyTrust(t));
  }
  return f;
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

fs::path unitResultPath(const fs::path& dir, size_t unit) {
  return dir / "units" / fmt::format("{}.result", unit);
}
fs::path unitDonePath(const fs::path& dir, size_t unit) {
  return dir / "units" / fmt::format("{}.done", unit);
}

void writeUnitResult(const fs::path& dir, const StudyPlan& plan, size_t unit,
                     const UnitResult& result) {
  UnitFile file;
  nlohmann::json renders = nlohmann::json::array();
  for (const RenderResult& r : result.renders) {
    renders.push_back(renderToJson(r));
    file.images.push_back(r.radiance);
    file.images.push_back(r.visibility);
    file.images.push_back(r.cost);
  }
  file.header = {{"unit", unit},
                 {"kind", unitKindName(plan.units.at(unit).kind)},
                 {"scene_hash", plan.scene_hash},
                 {"seed", plan.seed},
                 {"build", programBuildId()},
                 {"study", studyId(plan)},
                 {"facts", factsToJson(result.facts)},
                 {"renders", renders}};
  if (result.ceiling) file.header["ceiling"] = ceilingMeasurementToJson(*result.ceiling);
  writeUnitFile(unitResultPath(dir, unit), std::move(file));
  writeTextAtomically(unitDonePath(dir, unit), fmt::format("{}\n", unit));  // the marker, last
}

UnitResult readUnitResult(const fs::path& dir, const StudyPlan& plan, size_t unit) {
  const fs::path path = unitResultPath(dir, unit);
  std::error_code ec;
  if (!fs::exists(unitDonePath(dir, unit), ec) || !fs::exists(path, ec))
    throw Error(path.string(),
                fmt::format("unit {} of {} has not finished", unit, plan.units.size()),
                "its result or its .done marker is missing",
                "run the missing units first (submit.sh PLAN_DIR --resume)");
  UnitFile file = readUnitFile(path);  // its images are moved into the renders, not copied
  const nlohmann::json& h = file.header;
  UnitResult result;
  try {
    const std::string kind = unitKindName(plan.units[unit].kind);
    if (h.at("unit").get<size_t>() != unit)
      foreignUnit(path, "unit index", h.at("unit").dump(), std::to_string(unit));
    if (h.at("kind").get<std::string>() != kind)
      foreignUnit(path, "kind", h.at("kind").get<std::string>(), kind);
    if (h.at("scene_hash").get<std::string>() != plan.scene_hash)
      foreignUnit(path, "scene hash", h.at("scene_hash").get<std::string>(), plan.scene_hash);
    if (h.at("seed").get<uint64_t>() != plan.seed)
      foreignUnit(path, "seed", h.at("seed").dump(), std::to_string(plan.seed));
    if (h.at("build").get<std::string>() != plan.build)
      foreignUnit(path, "build", h.at("build").get<std::string>(), plan.build);
    if (h.at("study").get<std::string>() != studyId(plan))
      foreignUnit(path, "study (flags and units)", h.at("study").get<std::string>(), studyId(plan));
    result.facts = factsFromJson(h.at("facts"));
    const nlohmann::json& renders = h.at("renders");
    if (file.images.size() != 3 * renders.size())
      throw Error(path.string(), "not a complete render-compare unit result",
                  "its image count does not match its renders", "run the unit again");
    for (size_t i = 0; i < renders.size(); ++i) {
      RenderResult r = renderFromJson(renders[i]);
      r.radiance = std::move(file.images[3 * i]);
      r.visibility = std::move(file.images[3 * i + 1]);
      r.cost = std::move(file.images[3 * i + 2]);
      result.renders.push_back(std::move(r));
    }
    if (h.contains("ceiling")) {
      result.ceiling = ceilingMeasurementFromJson(h.at("ceiling"));
      // A field added to the measurement but not read back here would vanish from sharded runs.
      PV_CHECK_MSG(ceilingMeasurementToJson(*result.ceiling) == h.at("ceiling"),
                   "ceilingMeasurementFromJson() does not read back every field");
    }
  } catch (const nlohmann::json::exception& e) {
    throw Error(path.string(), "not a complete render-compare unit result",
                std::string("its header is not what a unit writes: ") + e.what(),
                "delete its .done marker and run the unit again (submit.sh --resume)");
  } catch (const std::bad_optional_access&) {
    throw Error(path.string(), "not a complete render-compare unit result",
                "it names an unknown proxy class", "run the unit again");
  }
  return result;
}

}  // namespace proxyvis
