#include "study/study.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <tuple>

#include "study/reference.h"
#include "util/error.h"
#include "util/parallel_in_order.h"
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

std::vector<UnitResult> readUnitResults(const fs::path& dir, const StudyPlan& plan,
                                        const SceneDesc& desc) {
  // Units are read in parallel; the first bad one in unit order is the one reported.
  std::vector<UnitResult> results(plan.units.size());
  parallelInOrder(results.size(), [&](size_t k) {
    results[k] = readUnitResult(dir, plan, k, desc.camera.width, desc.camera.height);
  });
  return results;
}

StudyCells assembleCells(const CompareOptions& o, const StudyPlan& plan,
                         std::vector<UnitResult>& results, const fs::path& scene) {
  std::map<std::tuple<int, EstimatorKind, int>, size_t> equal_spp;  // (spp, estimator, seed)
  std::vector<size_t> equal_time;                                   // by run
  for (size_t k = 0; k < plan.units.size(); ++k) {
    const PlannedUnit& u = plan.units[k];
    if (u.kind == UnitKind::kEqualSpp) equal_spp[{u.spp, u.estimator, u.run}] = k;
    if (u.kind == UnitKind::kEqualTime) equal_time.push_back(k);
  }
  StudyCells out;
  for (int spp : o.spp_list)
    for (EstimatorKind kind : o.estimator_list) {
      CellResult cell;
      for (int k = 0; k < o.seeds; ++k)
        addRun(cell, std::move(results.at(equal_spp.at({spp, kind, k})).renders.at(0)), scene, o,
               kind, kEqualSppTable, k, o.seeds);
      finishCell(cell, kind, kEqualSppTable, 0, o.seeds, 1);
      out.cells.push_back(std::move(cell));
      out.stems.push_back(fmt::format("{}_{}", estimatorName(kind), spp));
    }
  if (o.equal_time > 0) {
    const size_t n = o.estimator_list.size();
    const int runs = o.seeds * o.repeats;
    std::vector<CellResult> cells(n);
    for (int run = 0; run < runs; ++run) {
      std::vector<RenderResult>& renders = results.at(equal_time.at(size_t(run))).renders;
      for (size_t e = 0; e < n; ++e)
        addRun(cells[e], std::move(renders.at(e)), scene, o, o.estimator_list[e], kEqualTimeTable,
               run, runs);
    }
    for (size_t e = 0; e < n; ++e) {
      finishCell(cells[e], o.estimator_list[e], kEqualTimeTable, o.equal_time, o.seeds, o.repeats);
      out.cells.push_back(std::move(cells[e]));
      out.stems.push_back(fmt::format("{}_equal-time", estimatorName(o.estimator_list[e])));
    }
  }
  return out;
}

ReportCeiling studyCeiling(const CompareOptions& o, const StudyPlan& plan,
                           const std::vector<UnitResult>& results,
                           const std::vector<CellResult>& cells) {
  const UnitResult* unit = nullptr;
  for (size_t k = 0; k < plan.units.size(); ++k)
    if (plan.units[k].kind == UnitKind::kCeiling && results[k].ceiling) unit = &results[k];
  if (!unit) return {};
  std::vector<const RenderResult*> exact;
  double renders_seconds = 0;
  for (const CellResult& c : cells) {
    renders_seconds += c.row.seconds * c.row.seeds;
    if (c.row.estimator == estimatorName(EstimatorKind::kExact)) exact.push_back(&c.first);
  }
  if (exact.empty())
    for (const RenderResult& r : unit->renders) exact.push_back(&r);
  ReportCeiling ceiling =
      finishCeiling(*unit->ceiling, exact, unit->facts.proxy_class, unit->facts.uses_proxies, o);
  ceiling.run_share = renders_seconds > 0 ? ceiling.seconds / renders_seconds : 0;
  return ceiling;
}

std::vector<const Image*> referencePartials(const StudyPlan& plan,
                                            const std::vector<UnitResult>& results,
                                            double& seconds) {
  std::vector<const Image*> partials;
  seconds = 0;
  for (size_t k = 0; k < plan.units.size(); ++k)
    if (plan.units[k].kind == UnitKind::kReference) {
      partials.push_back(&results[k].renders.at(0).radiance);
      seconds += results[k].renders.at(0).seconds;
    }
  return partials;
}

}  // namespace proxyvis
