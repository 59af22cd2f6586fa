// render-compare: renders a scene with each visibility estimator at equal samples and at equal
// time, scores every image against a converged `exact` reference (MSE, relMSE, efficiency
// relative to exact, standard error over seeds) and writes the tables, images, heat-maps and an
// HTML report. docs/design.md ("Error metrics"), §2b (what the baseline must be).
#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <cstdio>
#include <future>
#include <optional>
#include <utility>

#include "compare_flags.h"
#include "huge_page_malloc.h"
#include "image/oiio_module.h"
#include "metrics/image_error.h"
#include "plan/unit_stamp.h"
#include "proxies/check/class_trust.h"
#include "render/render_scene.h"
#include "scene/scene_desc.h"
#include "study/data_parallel_study.h"
#include "study/out_of_core_study.h"
#include "study/reference.h"
#include "study/study.h"
#include "study/study_merge.h"
#include "study/study_report.h"
#include "util/app_main.h"
#include "util/error.h"
#include "util/output_path.h"
#include "util/progress.h"
#include "util/staged_folder.h"

namespace proxyvis {
namespace {

namespace fs = std::filesystem;

// The proxies' class decisions (proxies/check/class_trust.h) in the scene's facts: every proxy in
// the report's meta, a note for each whose claimed class was not taken as is.
SceneFacts trustedSceneFacts(const TrustedRenderScene& loaded) {
  SceneFacts f = sceneFacts(*loaded.scene);
  for (const ProxyTrust& t : loaded.trust) {
    f.proxy_classes.push_back(
        {t.mesh, t.proxy.filename().string(), t.claimed ? proxyClassName(*t.claimed) : "none",
         proxyClassName(t.trust.trusted), classStatusName(t.trust.status), t.trust.reason});
    if (t.trust.status == ClassStatus::kReVerified || t.trust.status == ClassStatus::kDowngraded)
      f.trust_notes.push_back("Proxy class " + describeProxyTrust(t));
  }
  return f;
}

// stdout: the headline table and where the report is.
int printReport(const CompareOptions& o, const Report& report) {
  const fs::path html = o.out / "report.html";
  // stdout: the equal-time table (the headline) and where the report is. With --json - the
  // JSON owns stdout, so the human text goes to stderr.
  FILE* human = jsonOnStdout(o.common) ? stderr : stdout;
  std::string_view headline = o.equal_time > 0 ? kEqualTimeTable : kEqualSppTable;
  std::fprintf(human,
               "\n%s MSE (relMSE eps = %g; efficiency = 1/(MSE*time) relative to exact):\n\n%s\n",
               headline == kEqualTimeTable
                   ? fmt::format("Equal time ({:g} s per render)", o.equal_time).c_str()
                   : "Equal samples",
               kRelMseEpsilon, markdownTable(report.rows, headline).c_str());
  std::fprintf(human, "HTML report: %s\n", fs::absolute(html).string().c_str());
  return kExitOk;
}

// The plan in DIR, its options and its scene, refused when the plan is of another build.
struct PlannedStudy {
  StudyPlan plan;
  CompareOptions options;
  SceneDesc desc;
};
PlannedStudy readPlannedStudy(const fs::path& dir, const std::string& to_do,
                              std::optional<size_t> unit = std::nullopt) {
  PlannedStudy s;
  s.plan = readPlan(dir);
  const fs::path plan_file = dir / "plan.json";
  if (unit && *unit >= s.plan.units.size())
    throw Error(plan_file.string(), fmt::format("the plan has no unit {}", *unit),
                fmt::format("its units are 0..{}", s.plan.units.size() - 1),
                "give a unit of the plan");
  requirePlanningBuild(s.plan.build, plan_file, to_do);
  parseStudyArgs(s.plan.args, s.options, plan_file);
  s.desc = plannedScene(s.plan, s.options);
  return s;
}

// The single-machine run: the study's plan with every unit run in process, then the merge.
int runCompare(CompareOptions& o, const CLI::App& app, const fs::path& plan_dir) {
  checkOutputs({o.scene.string()},
               {{"--out", o.out.string(), /*is_folder=*/true}, {"--json", o.common.json_path}});
  o.resolve();
  SceneDesc desc = loadSceneDesc(o.scene);
  o.render.applyTo(desc);
  if (!plan_dir.empty()) {
    const StudyPlan plan = writeStudyPlan(studyArgs(app, o), o, desc, plan_dir);
    const fs::path dir = fs::absolute(plan_dir).lexically_normal();
    std::printf(
        "render-compare: plan %s: %zu units (%d reference partials); run them with "
        "scripts/slurm/submit.sh %s\n",
        (dir / "plan.json").string().c_str(), plan.units.size(), plan.reference_partials,
        dir.string().c_str());
    return kExitOk;
  }
  // The report folder is written under a temporary name and swapped in at the end: a rerun
  // leaves nothing of the previous report, a failed or killed one leaves it intact. Staged
  // before any rendering, so an unwritable --out fails in a second (exit 3).
  StagedFolder folder(o.out, "render-compare", "report.json");
  oiioModule();  // the report's images need it: a missing module fails now, not after the renders

  // A claimed class the proxy file no longer matches is proven again or dropped before any
  // estimator relies on it; a downgrade is always said on stderr (the tables would hide the bias).
  TrustedRenderScene loaded =
      loadTrustedRenderScene(desc, o.render.sceneOptions(o.common.quiet), "render-compare");
  const RenderScene& scene = *loaded.scene;
  const SceneFacts facts = trustedSceneFacts(loaded);
  StudyPlan plan = newStudyPlan(studyArgs(app, o), o, desc);
  const size_t cell_units = plan.units.size();
  StudyMerge merge(o, plan, desc);
  // The reference first when its size is known before the cells (--reference-spp, or no
  // equal-time table: the automatic size from --spp, as --plan sizes it): then each cell unit is
  // scored as it renders and only its first seed's images stay. Otherwise the reference is sized
  // by the samples every cell actually reached (equal-time renders may reach far more than
  // --spp), and the cells' renders wait for it.
  const bool reference_first = o.reference_spp > 0 || !(o.equal_time > 0);
  auto renderCell = [&](size_t k) { return runUnit(scene, facts, o, plan, k); };
  std::vector<UnitResult> waiting;
  if (!reference_first)
    for (size_t k = 0; k < cell_units; ++k) waiting.push_back(renderCell(k));
  const int largest = reference_first ? (o.spp_list.empty() ? 0 : o.spp_list.back())
                                      : largestSppReached(plan, waiting);
  const int reference_spp = o.referenceSpp(largest);
  // A cached reference with as many samples is reused.
  std::optional<Reference> cached =
      loadCachedReference(desc, scene.instancesFlattened(), o.out, reference_spp, folder.path());
  planReference(plan, reference_spp, cached ? cached->spp : 0);
  // The reference's partial renders are quiet: one bar for all of them.
  Progress reference_progress(fmt::format("reference ({} spp)", plan.reference_spp),
                              uint64_t(plan.units.size() - cell_units), o.common.quiet);
  for (size_t k = cell_units; k < plan.units.size(); ++k) {
    merge.addReferencePartial(runUnit(scene, facts, o, plan, k).renders.at(0));
    reference_progress.update();
  }
  reference_progress.done();
  if (cached)
    merge.useCachedReference(std::move(*cached));
  else
    merge.finishReference(scene.instancesFlattened(), folder.path());
  auto addCell = [&](size_t k, UnitResult r) {
    const std::vector<RunScore> scores = merge.score(r);
    merge.addCellUnit(k, std::move(r), scores);
  };
  for (size_t k = 0; k < cell_units; ++k)  // each render draws its own progress bar
    addCell(k, reference_first ? renderCell(k) : std::exchange(waiting[k], UnitResult{}));
  return printReport(o, reportStudy(o, desc, merge.finish(), merge.reference(), folder));
}

// `render-compare --merge DIR`: the report of a plan folder whose units have all run, read unit
// by unit (study/study_merge.h).
int mergeStudy(const fs::path& dir) {
  // OpenImageIO loads while the units are read; a missing module still fails before the report is
  // committed.
  std::future<void> module = preloadOiioModule();
  PlannedStudy in =
      readPlannedStudy(dir, "merge with the program named in the plan, or plan again");
  StagedFolder folder(in.options.out, "render-compare", "report.json");
  StudyMerge merge(in.options, in.plan, in.desc);
  StudyMerge::Cells cells = mergeUnitFiles(merge, dir, in.plan, in.desc, folder.path());
  module.get();
  return printReport(in.options,
                     reportStudy(in.options, in.desc, std::move(cells), merge.reference(), folder));
}

// `render-compare --run-unit DIR K`: reads the plan, loads the scene (checking its hash against
// the plan's), renders unit K with SLURM_CPUS_PER_TASK threads when set, writes its result.
int runUnitCommand(const fs::path& dir, size_t unit, bool quiet) {
  PlannedStudy in = readPlannedStudy(dir, "run the program named in the plan, or plan again", unit);
  CompareOptions& o = in.options;
  o.common.quiet = o.common.quiet || quiet;
  // The plan's --threads, within the SLURM_CPUS_PER_TASK the caller already applied (the smaller
  // of two limits wins).
  const tbb::global_control limit(
      tbb::global_control::max_allowed_parallelism,
      o.common.threads > 0 ? size_t(o.common.threads) : size_t(tbb::info::default_concurrency()));
  TrustedRenderScene loaded =
      loadTrustedRenderScene(in.desc, o.render.sceneOptions(o.common.quiet), "render-compare");
  const UnitResult result = runUnit(*loaded.scene, trustedSceneFacts(loaded), o, in.plan, unit);
  writeUnitResult(dir, in.plan, unit, result);
  return kExitOk;
}

// `render-compare --run-unit DIR K` and `--merge DIR`: their own small command lines.
std::optional<int> runStudyCommand(int argc, char** argv) {
  if (argc < 2) return std::nullopt;
  const std::string mode = argv[1];
  if (mode != "--run-unit" && mode != "--merge") return std::nullopt;
  CLI::App app{mode == "--run-unit"
                   ? "render-compare --run-unit DIR K: render unit K of the plan in DIR "
                     "(docs/slurm.md) and write units/K.result, then units/K.done"
                   : "render-compare --merge DIR: combine the units of the plan in DIR into the "
                     "report one machine would write to its --out",
               "render-compare"};
  fs::path dir;
  size_t unit = 0;
  bool flag = false;
  CommonOptions common;
  app.add_flag(mode, flag, "This mode")->required();
  app.add_option("dir", dir, "The plan folder")->required();
  if (mode == "--run-unit")
    app.add_option("unit", unit, "The unit index")->required()->check(integerIn(0, 999999));
  app.add_flag("--quiet", common.quiet, "No progress or notes on stderr");
  // Under Slurm a unit uses only the CPUs it was given.
  if (const char* cpus = std::getenv("SLURM_CPUS_PER_TASK"))
    if (const std::optional<double> n = parseNumber(cpus); n && *n >= 1 && *n <= 4096)
      common.threads = int(*n);
  return runApp(app, argc, argv, common, [&] {
    return mode == "--run-unit" ? runUnitCommand(dir, unit, common.quiet) : mergeStudy(dir);
  });
}

}  // namespace
}  // namespace proxyvis

int main(int argc, char** argv) {
  proxyvis::execWithHugePageMalloc(argv);
  if (const std::optional<int> status = proxyvis::runStudyCommand(argc, argv)) return *status;
  CLI::App app{
      "render-compare: render a scene with each visibility estimator at equal samples and at "
      "equal time against a converged exact reference; write MSE tables, images and an HTML "
      "report",
      "render-compare"};
  proxyvis::CompareOptions options;
  proxyvis::addCompareOptions(app, options);
  proxyvis::DataParallelFlags data_parallel;
  proxyvis::addDataParallelFlags(app, data_parallel, true);
  proxyvis::OutOfCoreStudyFlags out_of_core;
  proxyvis::addOutOfCoreStudyFlags(app, out_of_core);
  std::filesystem::path plan_dir;
  app.add_option("--plan", plan_dir,
                 "Write the study as independent work units to this folder (plan.json) instead "
                 "of running it: run them with scripts/slurm/submit.sh, which merges them into "
                 "--out (docs/slurm.md). Also: --run-unit DIR K, --merge DIR");
  return proxyvis::runApp(app, argc, argv, options.common, [&] {
    const proxyvis::StudyFlagsGiven given{
        app.count("--estimators") > 0, app.count("--equal-time") > 0, app.count("--repeats") > 0};
    if (!out_of_core.geometry_budget.empty()) {
      if (!plan_dir.empty() || data_parallel.enabled)
        throw proxyvis::Error("",
                              std::string(data_parallel.enabled ? "--data-parallel" : "--plan") +
                                  " is not available with --geometry-budget",
                              "the out-of-core study runs on one machine, in one process",
                              "drop one of them");
      return proxyvis::runOutOfCoreStudy(options, out_of_core, given);
    }
    proxyvis::refuseOutOfCoreFlagsAlone(app, out_of_core, {"--ooc-policies", "--batch-passes"});
    if (data_parallel.enabled) {
      if (!plan_dir.empty())
        throw proxyvis::Error("", "--plan is not available with --data-parallel", {},
                              "run the data-parallel study under mpirun or srun");
      return proxyvis::runDataParallelStudy(options, data_parallel, given);
    }
    proxyvis::refuseDataParallelFlagsAlone(app, data_parallel);
    return proxyvis::runCompare(options, app, plan_dir);
  });
}
