#include "study.h"

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <algorithm>
#include <map>
#include <tuple>

#include "parallel_in_order.h"
#include "util/error.h"
#include "util/program_build_id.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

// Units and merge must be the build that planned: another build may trace or round differently.
void requirePlanningBuild(const StudyPlan& plan, const fs::path& plan_file, const char* to_do) {
  if (plan.build != programBuildId())
    throw Error(
        plan_file.string(),
        fmt::format("the plan was written by another build of render-compare ({}; this is {})",
                    plan.build, programBuildId()),
        "units and merge must be one build, or the tables could mix renderers", to_do);
}

// The plan's options and the scene description they give, refused when the scene's content
// changed since the plan was written.
SceneDesc plannedScene(const StudyPlan& plan, CompareOptions& o, const fs::path& plan_file) {
  parseStudyArgs(plan.args, o, plan_file);
  SceneDesc desc = loadSceneDesc(o.scene);
  o.render.applyTo(desc);
  if (sceneHash(desc) != plan.scene_hash)
    throw Error(
        desc.path.string(), "the scene changed since the plan was written",
        fmt::format("its content hash is {}, the plan's {}", sceneHash(desc), plan.scene_hash),
        "restore it, or plan and run the study again");
  return desc;
}

}  // namespace

StudyPlan newStudyPlan(const CLI::App& app, const CompareOptions& o, const SceneDesc& desc) {
  StudyPlan plan;
  plan.args = studyArgs(app, o);
  plan.scene = fs::absolute(o.scene).lexically_normal().string();
  plan.scene_hash = sceneHash(desc);
  plan.build = programBuildId();
  plan.seed = o.common.seed;
  plan.units = planCellUnits(o);
  return plan;
}

int writeStudyPlan(const CLI::App& app, const CompareOptions& o, const SceneDesc& desc,
                   const fs::path& dir) {
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
  StudyPlan plan = newStudyPlan(app, o, desc);
  int largest = 0;
  for (int spp : o.spp_list) largest = std::max(largest, spp);
  planReference(plan, o.referenceSpp(largest));
  writePlanFolder(plan_dir, plan);
  std::printf(
      "render-compare: plan %s: %zu units (%d reference partials); run them with "
      "scripts/slurm/submit.sh %s\n",
      (plan_dir / "plan.json").string().c_str(), plan.units.size(), plan.reference_partials,
      plan_dir.string().c_str());
  return kExitOk;
}

int largestSppReached(const StudyPlan& plan, const std::vector<UnitResult>& results) {
  int largest = 0;
  for (size_t k = 0; k < results.size(); ++k)
    if (plan.units[k].kind == UnitKind::kEqualSpp || plan.units[k].kind == UnitKind::kEqualTime)
      for (const RenderResult& r : results[k].renders) largest = std::max(largest, r.spp);
  return largest;
}

MergeInputs readMergeInputs(const fs::path& dir) {
  MergeInputs in;
  in.plan = readPlan(dir);
  const fs::path plan_file = dir / "plan.json";
  requirePlanningBuild(in.plan, plan_file,
                       "merge with the program named in the plan, or plan again");
  in.desc = plannedScene(in.plan, in.options, plan_file);
  // Units are read in parallel; the first bad one in unit order is the one reported.
  in.results.resize(in.plan.units.size());
  parallelInOrder(in.results.size(), [&](size_t k) {
    in.results[k] = readUnitResult(dir, in.plan, k);
    for (const RenderResult& r : in.results[k].renders)
      if (r.radiance.width != in.desc.camera.width || r.radiance.height != in.desc.camera.height ||
          r.radiance.channels != 3)
        throw Error(unitResultPath(dir, k).string(), "this unit result has the wrong image size",
                    fmt::format("{}x{}x{}, the study renders {}x{} RGB", r.radiance.width,
                                r.radiance.height, r.radiance.channels, in.desc.camera.width,
                                in.desc.camera.height),
                    "delete it and its .done marker, then run the unit again");
  });
  return in;
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

int runUnitCommand(const fs::path& dir, size_t unit, bool quiet) {
  const StudyPlan plan = readPlan(dir);
  const fs::path plan_file = dir / "plan.json";
  if (unit >= plan.units.size())
    throw Error(plan_file.string(), fmt::format("the plan has no unit {}", unit),
                fmt::format("its units are 0..{}", plan.units.size() - 1),
                "give a unit of the plan");
  requirePlanningBuild(plan, plan_file, "run the program named in the plan, or plan again");
  CompareOptions o;
  SceneDesc desc = plannedScene(plan, o, plan_file);
  o.common.quiet = o.common.quiet || quiet;
  // The plan's --threads, within the SLURM_CPUS_PER_TASK the caller already applied (the smaller
  // of two limits wins).
  const tbb::global_control limit(
      tbb::global_control::max_allowed_parallelism,
      o.common.threads > 0 ? size_t(o.common.threads) : size_t(tbb::info::default_concurrency()));
  TrustedRenderScene loaded =
      loadTrustedRenderScene(desc, o.render.sceneOptions(o.common.quiet), "render-compare");
  const UnitResult result =
      runUnit(*loaded.scene, sceneFacts(*loaded.scene, loaded.trust), o, plan, unit);
  writeUnitResult(dir, plan, unit, result);
  return kExitOk;
}

}  // namespace proxyvis
