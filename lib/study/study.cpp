#include "study/study.h"

#include <fmt/format.h>

#include <algorithm>

#include "study/reference.h"
#include "util/error.h"
#include "util/program_build_id.h"

namespace proxyvis {

namespace fs = std::filesystem;

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

SceneDesc plannedScene(const StudyPlan& plan, const CompareOptions& o) {
  SceneDesc desc = loadSceneDesc(o.scene);
  o.render.applyTo(desc);
  if (sceneHash(desc) != plan.scene_hash)
    throw Error(
        desc.path.string(), "the scene changed since the plan was written",
        fmt::format("its content hash is {}, the plan's {}", sceneHash(desc), plan.scene_hash),
        "restore it, or plan and run the study again");
  return desc;
}

StudyPlan newStudyPlan(const std::vector<std::string>& args, const CompareOptions& o,
                       const SceneDesc& desc) {
  StudyPlan plan;
  plan.args = args;
  plan.scene = fs::absolute(o.scene).lexically_normal().string();
  plan.scene_hash = sceneHash(desc);
  plan.build = programBuildId();
  plan.seed = o.common.seed;
  plan.units = planCellUnits(o);
  return plan;
}

StudyPlan writeStudyPlan(const std::vector<std::string>& args, const CompareOptions& o,
                         const SceneDesc& desc, const fs::path& dir) {
  if (o.equal_time > 0 && o.reference_spp == 0)
    throw Error({}, "--plan with --equal-time needs --reference-spp",
                "the automatic reference is sized from the samples the equal-time renders reach, "
                "which are not known before the units run",
                "give --reference-spp (e.g. 16 x the spp an equal-time render reaches)");
  const fs::path plan_dir = fs::absolute(dir).lexically_normal();
  const fs::path out = fs::absolute(o.out).lexically_normal();
  // The merge replaces --out as a whole: a plan inside it would be deleted.
  const auto [o_end, p_end] =
      std::mismatch(out.begin(), out.end(), plan_dir.begin(), plan_dir.end());
  if (o_end == out.end())
    throw Error(plan_dir.string(), "the plan folder is inside --out",
                "the merge replaces the report folder as a whole",
                "choose a plan folder outside it");
  StudyPlan plan = newStudyPlan(args, o, desc);
  int largest = 0;
  for (int spp : o.spp_list) largest = std::max(largest, spp);
  planReference(plan, o.referenceSpp(largest));
  writePlanFolder(plan_dir, plan);
  return plan;
}

int largestSppReached(const StudyPlan& plan, const std::vector<UnitResult>& results) {
  int largest = 0;
  for (size_t k = 0; k < results.size(); ++k)
    if (plan.units[k].kind == UnitKind::kEqualSpp || plan.units[k].kind == UnitKind::kEqualTime)
      for (const RenderResult& r : results[k].renders) largest = std::max(largest, r.spp);
  return largest;
}

}  // namespace proxyvis
