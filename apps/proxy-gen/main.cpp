// proxy-gen: builds an outside, inside or general proxy of a mesh, or of every mesh of a scene,
// verifies its guarantee and writes it (docs/design.md). The command line and its wiring: a mesh
// goes through proxies/pipeline/ (proxy_pipeline.h, proxy_outputs.h), a scene, its shards and
// their merge through proxies/scene/ (scene_run.h, shard_merge.h, shard_plan.h).
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <filesystem>

#include "mesh/io/mesh_io.h"
#include "proxies/outside/outside_proxy.h"
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
  std::string input, output, out_dir, kind = "outside", method;
  std::optional<double> alpha, offset, ratio, erosion, voxel, clearance, clearance_ulps;
  std::optional<size_t> parts;
  std::string budget = "hard";
  size_t max_faces = 0, min_faces = 12;
  double max_seconds = 600;
  bool fill_holes = false;
  bool progress = false;  // the bar also when stderr is not a terminal
  std::string cache_dir;  // scene mode: the proxy cache (empty = the default folder)
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
  ProxyGenOptions o;
  const std::optional<ProxyClass> kind = parseProxyClass(a.kind);
  if (!kind)
    throw Error("", fmt::format("unknown --kind '{}'", a.kind), "use outside, inside or general");
  o.kind = *kind;
  o.method = a.method;
  o.alpha = a.alpha;
  o.offset = a.offset;
  o.ratio = a.ratio;
  o.erosion = a.erosion;
  o.clearance = a.clearance;
  o.clearance_ulps = a.clearance_ulps;
  o.voxel = a.voxel;
  o.parts = a.parts;
  o.hard_budget = a.budget == "hard";
  o.max_faces = a.max_faces;
  o.min_faces = a.min_faces;
  o.fill_holes = a.fill_holes;
  o.seed = common.seed;
  o.max_seconds = a.max_seconds;
  return o;
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
    return mergeShards({a.input, a.out_dir, a.kind, base, cacheDirSetting(a.cache_dir, a.no_cache),
                        a.merge_shards},
                       common);
  return runSceneProxies({a.input, a.out_dir, a.kind, base, a.cache_dir, a.no_cache, a.shard,
                          a.done_file, a.scene_gltf, a.compress, a.progress},
                         common);
}

// The mesh and the proxy: input, kind, method, outputs, sizes and budgets.
void addProxyOptions(CLI::App& app, Args& a) {
  app.add_option("input", a.input,
                 "Mesh (.obj .ply .off .drc .gltf .glb) or scene (.json; a .gltf/.glb with "
                 "--out-dir is read as a scene: every mesh its nodes draw)")
      ->required();
  app.add_option("--kind", a.kind, "outside | inside | general")
      ->check(CLI::IsMember({"outside", "inside", "general"}))
      ->capture_default_str();
  app.add_option(
         "--method", a.method,
         "outside: wrap (default; the tightest: volume ratio 1.01-1.23 at --ratio 0.02 on the "
         "bundled closed meshes, 1.39 on a thin-legged cow), hull (convex: fastest, but 1.3-2.7), "
         "convex-parts (a "
         "proved union of convex pieces, as collision proxies are); "
         "inside: wrap (default; 0.76-0.98 of the volume at --ratio 0.02), erode (voxel erosion: "
         "0.76-0.95 at --ratio 0.02 on the bundled closed meshes); general: qem (default), "
         "cgal-sms, meshopt (no guarantee). See docs/proxy_tightness.md")
      ->check(
          CLI::IsMember({"wrap", "hull", "convex-parts", "erode", "qem", "cgal-sms", "meshopt"}));
  app.add_option("--parts", a.parts,
                 "convex-parts: the most convex pieces (default 16; with a face budget one per 12 "
                 "faces, 2 to 32)")
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
  app.add_option(
         "--alpha", a.alpha,
         "wrap: alpha as a fraction of the diagonal (default 1/50; in a scene, 1/10 for an open "
         "mesh such as foliage, see docs/proxies.md)")
      ->check(numberIn(kAlphaRange.lo, kAlphaRange.hi));
  app.add_option(
         "--offset", a.offset,
         "wrap: offset as a fraction of the diagonal (default 1/600; in a scene, 1/100 for an "
         "open mesh)")
      ->check(numberIn(kOffsetRange.lo, kOffsetRange.hi));
  app.add_option("--max-faces", a.max_faces,
                 "Face budget (0 = none). Outside/inside proxies keep their guarantee while "
                 "reducing; when the method's proxy cannot be reduced to it, coarser sizes, the "
                 "convex hull (outside), a box (12 faces) and a tetrahedron (4 faces) are tried "
                 "and the tightest verified one is kept. Without a budget an outside/inside proxy "
                 "with more faces than the input is reduced to the input's count, as a goal")
      ->check(integerIn(0, kMaxFacesLimit));
  app.add_option("--budget", a.budget,
                 "hard: a --max-faces/--ratio that no verified proxy meets ends the run with exit "
                 "code 1 and nothing written; soft: write the smallest verified proxy anyway "
                 "(\"budget_reached\": false in the JSON); see docs/budgets.md")
      ->check(CLI::IsMember({"hard", "soft"}))
      ->capture_default_str();
  app.add_option("--max-seconds", a.max_seconds,
                 "Time budget per mesh: a wrap, erosion or decimation still running after it is "
                 "stopped and the mesh fails (exit code 2), nothing is written")
      ->check(numberIn(0.1, kMaxSecondsRange.hi))
      ->capture_default_str();
  app.add_option("--ratio", a.ratio,
                 "Faces kept as a fraction of the input: general (default 0.02); outside/inside "
                 "a face budget relative to each mesh (for scenes), used when --max-faces is 0")
      ->check(numberIn(kRatioRange.lo, kRatioRange.hi));
  app.add_option("--min-faces", a.min_faces,
                 "With --ratio (outside/inside): the budget is at least this many faces, so that "
                 "a scene's small meshes keep proxies about as tight as their wraps (ecosys: "
                 "--ratio 0.03 --min-faces 64, docs/proxy_tightness.md)")
      ->check(CLI::Range(size_t(4), size_t(kMaxFacesLimit)))
      ->capture_default_str();
  app.add_option("--erosion", a.erosion,
                 "erode: erosion distance as a fraction of the diagonal (default 1/75)")
      ->check(numberIn(kErosionRange.lo, kErosionRange.hi));
  app.add_option("--voxel", a.voxel,
                 "erode: voxel edge as a fraction of the diagonal (default 1/150; with a face "
                 "budget, coarser: about 100 voxel faces per budget face)")
      ->check(numberIn(kVoxelRange.lo, kVoxelRange.hi));
  auto* clearance = app.add_option(
      "--clearance", a.clearance,
      "outside/inside: the least distance (scene units) the proxy keeps from the input, so its "
      "class holds when the input is read in double or placed by a transform; default: "
      "--clearance-ulps 8 (docs/clearance.md)");
  clearance->check(numberIn(kClearanceRange.lo, kClearanceRange.hi));
  app.add_option("--clearance-ulps", a.clearance_ulps,
                 "outside/inside: the clearance in ulps of float at the input's largest "
                 "coordinate (default 8: a float or double reading of a text file, and a "
                 "placement that rounds each coordinate by a few ulps; 0 = none)")
      ->check(numberIn(kClearanceUlpsRange.lo, kClearanceUlpsRange.hi))
      ->excludes(clearance);
  app.add_flag(
      "--fill-holes", a.fill_holes,
      "inside: fill the holes of an open input first; the proxy is then written as class general "
      "(a ray through a hole can reach it), see docs/proxy_classes.md");
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
