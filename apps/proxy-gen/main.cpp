// proxy-gen: builds an outside, inside or general proxy of a mesh, or of every mesh of a scene,
// verifies its guarantee and writes it (docs/design.md). Thin CLI over
// proxies/pipeline/proxy_pipeline.h.
#include <fmt/core.h>
#include <tbb/parallel_for.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "mesh/io/mesh_io.h"
#include "output_paths.h"
#include "proxies/check/check_view3d.h"
#include "proxies/pipeline/gltf_proof.h"
#include "proxies/pipeline/proxy_cache.h"
#include "proxies/pipeline/proxy_pipeline.h"
#include "proxies/pipeline/written_class.h"
#include "scene/scene_desc.h"
#include "scene_gltf.h"
#include "scene_mesh.h"
#include "scene_outputs.h"
#include "shard.h"
#include "shard_manifest.h"
#include "shard_plan.h"
#include "stage_progress.h"
#include "summary_text.h"
#include "util/app_main.h"
#include "util/error.h"
#include "util/lower_case.h"
#include "util/output_path.h"
#include "util/output_set.h"
#include "util/program_build_id.h"
#include "util/progress.h"
#include "util/rng.h"
#include "util/sha256.h"
#include "util/stopwatch.h"

namespace fs = std::filesystem;
using namespace proxyvis;
using json = nlohmann::json;

namespace {

// HM'/MH' segments kept for --report's 3D view (it draws a few thousand of each class).
constexpr uint64_t kReportErrorSegments = 2000;

struct Args {
  std::string input, output, out_dir, kind = "outside", method;
  std::optional<double> alpha, offset, ratio, erosion, voxel;
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
  o.voxel = a.voxel;
  o.hard_budget = a.budget == "hard";
  o.max_faces = a.max_faces;
  o.min_faces = a.min_faces;
  o.fill_holes = a.fill_holes;
  o.seed = common.seed;
  o.max_seconds = a.max_seconds;
  return o;
}

// Loading is proxy-gen's own stage: it goes into the report's seconds (and their total, which
// then covers everything but writing).
void addLoadSeconds(ProxyReport& report, double load_seconds) {
  report.seconds["load"] = load_seconds;
  report.seconds["total"] += load_seconds;
}

// The proxy file (a glTF with its proof; proved again when quantization moved its vertices) and
// the --report page, staged in `outputs`.
void addProxyOutputs(const Args& a, const TriMesh& input, ProxyGenResult& result, uint64_t seed,
                     OutputSet& outputs) {
  const bool gltf = isGltfPath(a.output);
  std::optional<PairCheckReport> check;
  if ((gltf || !a.report_html.empty()) && a.check_rays > 0)
    check = classifyProxySegments(input, result.proxy, a.check_rays, seed,
                                  a.report_html.empty() ? 0 : kReportErrorSegments);
  SaveOptions save;
  save.draco_quantization = a.draco_bits;
  save.gltf_compression = parseGltfCompression(a.compress, a.output);
  if (gltf) {
    save.gltf_name = gltfProxyNodeName(fs::path(a.input).stem().string(), result.report);
    json proof = gltfProofExtras(result.report, sha256OfFile(a.input), programBuildId());
    if (!a.pick.mesh.empty()) proof["source_mesh"] = a.pick.mesh;
    if (!a.pick.node.empty()) proof["source_node"] = a.pick.node;
    if (check) proof["segments"] = gltfSegmentEvidence(*check);
    save.gltf_extras = {{"proxyvis", proof}};
  }
  const std::string bytes = encodeMesh(result.proxy, a.output, save);
  if (movesVertices(a.output, save))
    proveWrittenProxy(input, parseMeshBytes(bytes, a.output), result.report, a.output);
  addEncodedMeshOutput(outputs, bytes, a.output);
  if (!a.report_html.empty()) {
    if (!check)
      throw Error("", "--report needs classified segments", "--check-rays 0 classifies none",
                  "drop --check-rays 0");
    outputs.addText(a.report_html, checkReportHtml(input, result.proxy, *check));
    result.report.report_html = a.report_html;
  }
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
  ProxyGenResult result = generateProxy(input, options);
  progress.done();
  addLoadSeconds(result.report, load_seconds);
  OutputSet outputs(MissingFolders::kCreate);
  addProxyOutputs(a, input, result, options.seed, outputs);
  noteWrittenClass(result.report, a.input);
  result.report.output = a.output;
  result.report.output_sha256 = outputs.sha256Of(a.output);
  emit(json(result.report), proxySummaryText(result.report), common, outputs);
  return kExitOk;
}

// The proxy cache of scene mode: --cache DIR (an error when unusable), none with --no-cache, else
// the default folder, which is only a convenience: when it is unusable the run goes on without.
std::unique_ptr<ProxyCache> openCache(const Args& a) {
  if (a.no_cache) return nullptr;
  if (!a.cache_dir.empty()) return std::make_unique<ProxyCache>(a.cache_dir);
  const fs::path dir = defaultProxyCacheDir();
  if (dir.empty()) {
    std::fprintf(stderr,
                 "proxy-gen: note: no proxy cache: neither XDG_CACHE_HOME nor HOME is set (give "
                 "--cache DIR)\n");
    return nullptr;
  }
  try {
    return std::make_unique<ProxyCache>(dir);
  } catch (const Error& e) {
    std::fprintf(stderr, "proxy-gen: note: no proxy cache: %s\n", e.what());
    return nullptr;
  }
}

// Generates (or takes from the cache) the proxies of the meshes `selected`; never throws for a
// mesh: its failure is its outcome.
std::vector<MeshOutcome> generateSceneProxies(const SceneDesc& scene,
                                              const std::vector<bool>& selected,
                                              const std::vector<fs::path>& proxy_files,
                                              const ProxyGenOptions& base, const ProxyCache* cache,
                                              const Args& a, const CommonOptions& common) {
  const size_t n = scene.meshes.size();
  std::vector<MeshOutcome> outcomes(n);
  Progress progress("proxy-gen", size_t(std::count(selected.begin(), selected.end(), true)),
                    common.quiet, a.progress);
  tbb::parallel_for(size_t(0), n, [&](size_t i) {
    if (!selected[i]) return;
    const SceneMeshDesc& mesh = scene.meshes[i];
    MeshOutcome& m = outcomes[i];
    try {
      ProxyGenOptions o = base;
      // Per-mesh stream from the mesh's place in the scene (not in a shard): the same proxy at
      // any thread count and in any shard.
      o.seed = hashKeys(common.seed, i);
      SceneMeshProxy p = proxyForSceneMesh(mesh, o, proxy_files[i], cache);
      m.report = std::move(p.report);
      m.ref = std::move(p.ref);
      m.skipped = std::move(p.skipped);
      m.cache_note = std::move(p.cache_note);
    } catch (const Error& e) {
      m.error = e.what();
      m.code = e.exitCode();
    } catch (const std::bad_alloc&) {
      m.error = fmt::format("{}: out of memory; the mesh is too large for this machine",
                            mesh.file.string());
      m.code = kExitBadInput;
    } catch (const std::exception& e) {
      // A failure inside CGAL or OpenMesh the checks did not foresee: this mesh fails, the rest
      // of the scene goes on.
      m.error = fmt::format("{}: {}", mesh.file.string(), e.what());
      m.code = kExitBadInput;
    }
    if (!m.error.empty()) {
      m.report = {};
      m.report.name = mesh.name;
      m.report.error = m.error;
    }
    progress.update();
    progress.setLabel(mesh.name);  // the mesh finished last (one line each in a log)
  });
  progress.done();
  return outcomes;
}

// The proxy cache folder a scene run asks for (null with --no-cache or without a default).
std::optional<std::string> cacheDirSetting(const Args& a) {
  if (a.no_cache) return std::nullopt;
  if (!a.cache_dir.empty()) return a.cache_dir;
  const fs::path dir = defaultProxyCacheDir();
  if (dir.empty()) return std::nullopt;
  return dir.string();
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
  if (const std::optional<std::string> cache = cacheDirSetting(a); cache && a.cache_dir.empty())
    flags.push_back("--cache=" + fs::absolute(*cache).lexically_normal().string());
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
    return mergeShards({a.input, a.out_dir, a.kind, base, cacheDirSetting(a), a.merge_shards},
                       common);
  SceneDesc scene = loadSceneDesc(a.input);  // registers the scene and its instance list
  const size_t n = scene.meshes.size();
  // File names from mesh names that cannot leave --out-dir; and before any work, no output may
  // replace an input (the scene, a mesh it references, its instance list).
  std::vector<std::string> names, inputs{a.input, scene.instances_file.string()};
  for (const SceneMeshDesc& mesh : scene.meshes) {
    names.push_back(mesh.name);
    inputs.push_back(mesh.file.string());
  }
  const std::vector<std::string> stems = proxyFileStems(names);
  const std::optional<ShardSpec> shard = a.shard.empty() ? std::nullopt : parseShardSpec(a.shard);
  std::vector<bool> selected(n, true);
  std::vector<fs::path> proxy_files;
  std::vector<OutputFlag> planned;
  for (size_t i = 0; i < n; ++i) {
    proxy_files.push_back(proxyFilePath(a.out_dir, stems[i], a.kind));
    if (shard) selected[i] = shardOfMesh(names[i], shard->count) == shard->index;
    if (selected[i]) planned.push_back({"--out-dir", proxy_files.back().string()});
  }
  const fs::path scene_out = fs::path(a.out_dir) / "scene.json";
  const fs::path manifest_out = fs::path(a.out_dir) / kShardManifestName;
  planned.push_back({"--out-dir", scene_out.string()});
  if (shard) planned.push_back({"--out-dir", manifest_out.string()});
  planned.push_back({"--json", common.json_path});
  planned.push_back({"--done", a.done_file});
  planned.push_back({"--gltf", a.scene_gltf});
  checkOutputs(inputs, planned);
  if (!a.scene_gltf.empty() && (shard || !isGltfPath(a.scene_gltf)))
    throw Error(
        a.scene_gltf, shard ? "--gltf needs the whole scene" : "--gltf writes .glb or .gltf",
        shard ? "a shard holds some of its proxies" : "the format is chosen by the extension",
        shard ? "merge the shards first" : "name the file .glb");
  const GltfCompression scene_compression = a.scene_gltf.empty()
                                                ? GltfCompression::kNone
                                                : parseGltfCompression(a.compress, a.scene_gltf);
  // Before any folder is made: an unusable --cache fails the run with nothing written.
  const std::unique_ptr<ProxyCache> cache = openCache(a);
  std::error_code ec;
  fs::create_directories(a.out_dir, ec);
  if (ec) throw WriteError(a.out_dir, "cannot create the output directory", ec.message());

  const std::vector<MeshOutcome> outcomes =
      generateSceneProxies(scene, selected, proxy_files, base, cache.get(), a, common);
  const std::optional<std::string> cache_dir =
      cache ? std::optional<std::string>(cache->dir().string()) : std::nullopt;
  const SceneRunInfo info{a.input, a.kind, scene_out, cache_dir};
  SceneResult result = finishScene(scene, outcomes, selected, info);
  OutputSet outputs(MissingFolders::kCreate);
  // A shard's manifest is what the merge reads: it records the shard, the scene's content hash,
  // the settings and the build, and each of its meshes' outcome with its proxy file's hash.
  if (shard)
    outputs.addText(manifest_out,
                    json(shardManifest(*shard, scene, shardSettings(base, cacheDirSetting(a)),
                                       outcomes, selected, proxy_files))
                            .dump(1) +
                        "\n");
  if (!a.scene_gltf.empty())
    addSceneGltfOutput(outputs, scene_out, outcomes, proxy_files, a.scene_gltf, scene_compression);
  emit(result.report, result.summary, common, outputs);
  // A plan unit's marker, last: it exists only when every output above is in place.
  if (!a.done_file.empty() && result.code == kExitOk) {
    OutputSet done(MissingFolders::kCreate);
    done.addText(a.done_file, fmt::format("shard {}\n", a.shard));
    done.commit();
  }
  return result.code;
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
         "bundled closed meshes, 1.39 on a thin-legged cow), hull (convex: fastest, but 1.3-2.7); "
         "inside: wrap (default; 0.76-0.98 of the volume at --ratio 0.02), erode (voxel erosion: "
         "0.74-0.78 on compact shapes, 0.33 on the dragon's thin parts); general: qem (default), "
         "cgal-sms, meshopt (no guarantee). See docs/proxy_tightness.md")
      ->check(CLI::IsMember({"wrap", "hull", "erode", "qem", "cgal-sms", "meshopt"}));
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
      ->check(CLI::Range(size_t(4), size_t(1000000000)))
      ->capture_default_str();
  app.add_option("--erosion", a.erosion,
                 "erode: erosion distance as a fraction of the diagonal (default 1/75)")
      ->check(numberIn(kErosionRange.lo, kErosionRange.hi));
  app.add_option("--voxel", a.voxel,
                 "erode: voxel edge as a fraction of the diagonal (default 1/150; with a face "
                 "budget, coarser: about 100 voxel faces per budget face)")
      ->check(numberIn(kVoxelRange.lo, kVoxelRange.hi));
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
