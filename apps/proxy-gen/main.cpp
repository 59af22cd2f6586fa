// proxy-gen: builds an outside, inside or general proxy of a mesh, or of every mesh of a scene,
// verifies its guarantee and writes it (docs/design.md). The command line and its wiring: a mesh
// goes through proxies/pipeline/ (proxy_pipeline.h, proxy_outputs.h), a scene, its shards and
// their merge through proxies/scene/ (scene_run.h, shard_merge.h, shard_plan.h).
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <filesystem>

#include "mesh/io/mesh_io.h"
#include "proxies/outside/outside_proxy.h"
#include "proxies/pipeline/proxy_gen_settings.h"
#include "proxies/pipeline/proxy_outputs.h"
#include "proxies/pipeline/proxy_pipeline.h"
#include "proxies/pipeline/proxy_report_text.h"
#include "proxies/pipeline/stage_progress.h"
#include "proxies/scene/scene_run.h"
#include "proxies/scene/shard_merge.h"
#include "proxies/scene/shard_plan.h"
#include "scene/scene_desc.h"
#include "shard_flags.h"
#include "util/app_main.h"
#include "util/error.h"
#include "util/lower_case.h"
#include "util/output_path.h"
#include "util/output_set.h"
#include "util/stopwatch.h"

namespace fs = std::filesystem;
using namespace proxyvis;
using json = nlohmann::json;

namespace {

struct Args {
  std::string input, output, out_dir;
  ProxyGenSettings proxy;  // --kind, --method, the sizes and budgets
  bool progress = false;   // the bar also when stderr is not a terminal
  std::string cache_dir;   // scene mode: the proxy cache (empty = the default folder)
  bool no_cache = false;
  std::string shard;                      // --shard i/n (scene mode)
  std::vector<std::string> merge_shards;  // --merge-shards DIR... (scene mode)
  std::string done_file;                  // --done FILE: a plan unit's marker
  std::string plan_dir;                   // --plan DIR: write the shards as a plan's units
  uint64_t plan_shards = 0;               // --shards N of the plan
  uint64_t check_rays = 100000;           // --check-rays: segments for a glTF's proof, --report
  std::string report_html;                // --report REPORT.html (mesh mode)
  std::string compress = "none";          // --compress (glTF output)
  int draco_bits = 0;                     // --draco-bits (.drc, glTF Draco)
  GltfPick pick;                          // --mesh / --node (glTF input)
  std::string scene_gltf;                 // --gltf OUT (scene mode)
};

ProxyGenOptions toOptions(const Args& a, const CommonOptions& common) {
  return proxyGenOptions(a.proxy, common.seed);
}

int runMesh(const Args& a, const CommonOptions& common) {
  if (!a.shard.empty() || !a.merge_shards.empty() || !a.plan_dir.empty())
    throw Error(a.input, "--shard, --merge-shards and --plan split a scene",
                "a single mesh is one unit of work", "give a scene (.json)");
  if (a.output.empty())
    throw Error("", "no output file", "a mesh input needs -o OUTPUT", "add -o proxy.ply");
  if (!isSupportedMeshExtension(a.output))
    throw Error(a.output, "unsupported output extension",
                "proxy-gen writes .obj, .ply, .off, .drc, .gltf or .glb");
  StageProgress progress(common.quiet, a.progress);
  progress.stage("load");
  const Stopwatch load_clock;
  const TriMesh input = loadMesh(a.input, a.pick);
  const double load_seconds = load_clock.seconds();
  ProxyGenOptions options = toOptions(a, common);
  options.on_stage = [&](const std::string& stage) { progress.stage(stage); };
  // The proof also holds for the input read in double (a text file's decimals; docs/clearance.md).
  std::vector<Vec3d> input_double;
  addDoubleReading(options, a.input, input, input_double);
  ProxyGenResult result = generateProxy(input, options);
  progress.done();
  addLoadSeconds(result.report, load_seconds);
  OutputSet outputs(MissingFolders::kCreate);
  stageProxyOutputs({a.input, a.pick, a.output, a.compress, a.draco_bits, a.report_html,
                     a.check_rays, options.seed},
                    input, result, outputs);
  noteWrittenClass(result.report, a.input);
  result.report.output = a.output;
  result.report.output_sha256 = outputs.sha256Of(a.output);
  emit(json(result.report), proxySummaryText(result.report), common, outputs);
  return kExitOk;
}

// --plan DIR --shards N: checks the scene and the outputs as the run would, writes the plan.
int writePlan(const Args& a, const CommonOptions& common, const CLI::App& app) {
  const SceneDesc scene = loadSceneDesc(a.input);
  std::vector<std::string> inputs{a.input, scene.instances_file.string()};
  for (const SceneMeshDesc& mesh : scene.meshes) inputs.push_back(mesh.file.string());
  const fs::path plan_file = fs::path(a.plan_dir) / "plan.json";
  checkOutputs(inputs, {{"--plan", plan_file.string()},
                        {"--out-dir", (fs::path(a.out_dir) / "scene.json").string()},
                        {"--json", common.json_path}});
  std::vector<std::string> flags = planFlags(app);
  // The default cache folder of this machine for every unit and the merge: nodes with another
  // HOME would otherwise each use (and report) their own.
  if (const std::optional<std::string> cache = cacheDirSetting(a.cache_dir, a.no_cache);
      cache && a.cache_dir.empty())
    flags.push_back("--cache=" + absolutePathText(*cache));
  writeShardPlan(a.plan_dir, a.plan_shards, flags, a.out_dir, common.json_path);
  printHumanReport(common, fmt::format("plan of {} shards: {} (run: scripts/slurm/submit.sh {})\n",
                                       a.plan_shards, plan_file.string(), a.plan_dir));
  return kExitOk;
}

int runScene(const Args& a, const CommonOptions& common, const CLI::App& app) {
  if (!a.report_html.empty())
    throw Error(a.report_html, "--report is for a mesh input",
                "the page shows one input and its proxy",
                "run proxy-gen MESH -o OUT --report PAGE.html");
  if (a.out_dir.empty())
    throw Error(a.input, "no output directory", "a scene input needs --out-dir DIR",
                "add --out-dir out/");
  toOptions(a, common);  // the settings are checked before a plan is written
  if (!a.plan_dir.empty()) return writePlan(a, common, app);
  const ProxyGenOptions base = toOptions(a, common);
  if (!a.merge_shards.empty())
    return mergeShards({a.input, a.out_dir, a.proxy.kind, base,
                        cacheDirSetting(a.cache_dir, a.no_cache), a.merge_shards},
                       common);
  return runSceneProxies({a.input, a.out_dir, a.proxy.kind, base, a.cache_dir, a.no_cache, a.shard,
                          a.done_file, a.scene_gltf, a.compress, a.progress},
                         common);
}

// The mesh and the proxy: input, kind, method, outputs, sizes and budgets.
void addProxyOptions(CLI::App& app, Args& a) {
  app.add_option("input", a.input,
                 "Mesh (.obj .ply .off .drc .gltf .glb) or scene (.json; a .gltf/.glb with "
                 "--out-dir is read as a scene: every mesh its nodes draw)")
      ->required();
  app.add_option("--kind", a.proxy.kind, proxyGenHelp("--kind"))
      ->check(CLI::IsMember({"outside", "inside", "general"}))
      ->capture_default_str();
  app.add_option("--method", a.proxy.method, proxyGenHelp("--method"))
      ->check(
          CLI::IsMember({"wrap", "hull", "convex-parts", "erode", "qem", "cgal-sms", "meshopt"}));
  app.add_option("--parts", a.proxy.parts, proxyGenHelp("--parts"))
      ->check(CLI::Range(size_t(1), kMaxConvexParts));
  app.add_option("-o,--output", a.output,
                 "Output mesh (mesh input): .ply, .obj, .off, .drc (lossless), or .glb/.gltf with "
                 "the proof in the node's extras (docs/gltf.md)");
  addGltfPickOptions(app, a.pick.mesh, a.pick.node);
  addCompressionOptions(app, a.compress, a.draco_bits,
                        "(0 = lossless, default; more moves vertices, so the written proxy is "
                        "proved again against the input and nothing is written if it fails)");
  app.add_option("--report", a.report_html,
                 "Mesh input: also write an HTML page with the check of the proxy and a 3D view of "
                 "input, proxy and the segments that break its class (docs/report_3d.md)");
  app.add_option("--check-rays,--gltf-rays", a.check_rays,
                 "Segments classified against original and proxy for a glTF output's proof "
                 "(HM'/MH' counts and bounds) and for --report (0 = none)")
      ->check(integerIn(0, 100'000'000))
      ->capture_default_str();
  app.add_option("--gltf", a.scene_gltf,
                 "Scene input: also write the scene with its proxies as one .glb/.gltf (outside "
                 "and inside proxies as hidden child nodes, general ones as MSFT_lod levels, "
                 "each with its proof; docs/gltf.md)");
  app.add_option("--out-dir", a.out_dir,
                 "Output directory (scene input): DIR/<mesh>.<kind>.ply, DIR/scene.json");
  app.add_option("--alpha", a.proxy.alpha, proxyGenHelp("--alpha"))
      ->check(numberIn(kAlphaRange.lo, kAlphaRange.hi));
  app.add_option("--offset", a.proxy.offset, proxyGenHelp("--offset"))
      ->check(numberIn(kOffsetRange.lo, kOffsetRange.hi));
  app.add_option("--max-faces", a.proxy.max_faces, proxyGenHelp("--max-faces"))
      ->check(integerIn(0, kMaxFacesLimit));
  app.add_option("--budget", a.proxy.budget, proxyGenHelp("--budget"))
      ->check(CLI::IsMember({"hard", "soft"}))
      ->capture_default_str();
  app.add_option("--max-seconds", a.proxy.max_seconds, proxyGenHelp("--max-seconds"))
      ->check(numberIn(0.1, kMaxSecondsRange.hi))
      ->capture_default_str();
  app.add_option("--ratio", a.proxy.ratio, proxyGenHelp("--ratio"))
      ->check(numberIn(kRatioRange.lo, kRatioRange.hi));
  app.add_option("--min-faces", a.proxy.min_faces, proxyGenHelp("--min-faces"))
      ->check(CLI::Range(size_t(4), size_t(kMaxFacesLimit)))
      ->capture_default_str();
  app.add_option("--erosion", a.proxy.erosion, proxyGenHelp("--erosion"))
      ->check(numberIn(kErosionRange.lo, kErosionRange.hi));
  app.add_option("--voxel", a.proxy.voxel, proxyGenHelp("--voxel"))
      ->check(numberIn(kVoxelRange.lo, kVoxelRange.hi));
  auto* clearance = app.add_option("--clearance", a.proxy.clearance, proxyGenHelp("--clearance"));
  clearance->check(numberIn(kClearanceRange.lo, kClearanceRange.hi));
  app.add_option("--clearance-ulps", a.proxy.clearance_ulps, proxyGenHelp("--clearance-ulps"))
      ->check(numberIn(kClearanceUlpsRange.lo, kClearanceUlpsRange.hi))
      ->excludes(clearance);
  app.add_flag("--fill-holes", a.proxy.fill_holes, proxyGenHelp("--fill-holes"));
}

// Scene input: the cache, shards and their merge, plans for Slurm.
void addSceneOptions(CLI::App& app, Args& a) {
  auto* cache_opt =
      app.add_option("--cache", a.cache_dir,
                     "Scene input: the proxy cache folder (default "
                     "$XDG_CACHE_HOME/proxyvis/proxies, else ~/.cache/proxyvis/proxies). A proxy "
                     "is taken from it when the mesh file's SHA-256, every setting and this build "
                     "are the same; see docs/proxies.md");
  app.add_flag("--no-cache", a.no_cache,
               "Scene input: generate every proxy, neither read nor write the cache")
      ->excludes(cache_opt);
  auto* shard_opt =
      app.add_option("--shard", a.shard,
                     "Scene input: generate only the proxies of shard i of n (0 <= i < n): the "
                     "meshes whose FNV-1a 64 hash of their name, mod n, is i; --out-dir then also "
                     "gets shard.json for --merge-shards (docs/proxy_gen_shards.md)")
          ->check(shardSpecValidator());
  auto* merge_opt =
      app.add_option("--merge-shards", a.merge_shards,
                     "Scene input: merge the --out-dir folders of shards 0..n-1 (run with the same "
                     "settings, which this run must repeat) into --out-dir: the files of one whole "
                     "run, byte for byte")
          ->expected(1, -1)
          ->excludes(shard_opt);
  auto* plan_opt =
      app.add_option("--plan", a.plan_dir,
                     "Scene input: write DIR/plan.json, the run as --shards N units "
                     "for scripts/slurm/submit.sh, and generate nothing (docs/slurm.md)");
  auto* shards_opt =
      app.add_option("--shards", a.plan_shards, "With --plan: the number of shards (units)")
          ->check(integerIn(1, kMaxPlanShards));
  plan_opt->needs(shards_opt)->excludes(shard_opt)->excludes(merge_opt);
  shards_opt->needs(plan_opt);
  app.add_option("--done", a.done_file,
                 "With --shard: write this file after every output is in place and the shard "
                 "succeeded (a plan unit's marker)")
      ->needs(shard_opt);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "proxy-gen: builds an outside (hull, wrap), inside (wrap, erode) or general (qem, cgal-sms, "
      "meshopt) "
      "proxy of a mesh, or of every mesh of a scene (SCENE.json), verifies its guarantee exactly "
      "and "
      "writes it. Sizes are fractions of the bounding-box diagonal.",
      "proxy-gen"};
  Args a;
  CommonOptions common;
  addProxyOptions(app, a);
  addSceneOptions(app, a);
  addCommonOptions(app, common);
  // Under Slurm a shard uses only the CPUs it was given.
  app.parse_complete_callback([&] {
    if (!a.shard.empty()) limitThreadsToSlurm(common.threads);
  });
  app.add_flag("--progress", a.progress,
               "Show the progress bar (stages of one mesh, meshes of a scene) on stderr even when "
               "it is not a terminal (one line per stage); without it, only on a terminal")
      ->excludes("--quiet");
  return runApp(app, argc, argv, common, [&] {
    checkOutputs({a.input},
                 {{"-o", a.output}, {"--json", common.json_path}, {"--report", a.report_html}});
    // A glTF file is a scene with --out-dir (every mesh, like a JSON scene), one mesh with -o.
    const bool scene = lowerExtension(a.input) == ".json" ||
                       (isGltfPath(a.input) && !a.out_dir.empty() && a.output.empty());
    return scene ? runScene(a, common, app) : runMesh(a, common);
  });
}
