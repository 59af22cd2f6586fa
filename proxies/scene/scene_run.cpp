#include "proxies/scene/scene_run.h"

#include <fmt/core.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdio>

#include "mesh/io/mesh_io.h"
#include "proxies/pipeline/proxy_outputs.h"
#include "proxies/scene/output_paths.h"
#include "proxies/scene/scene_gltf.h"
#include "proxies/scene/scene_mesh.h"
#include "proxies/scene/scene_outputs.h"
#include "proxies/scene/shard_manifest.h"
#include "scene/scene_desc.h"
#include "util/error.h"
#include "util/output_path.h"
#include "util/output_set.h"
#include "util/progress.h"
#include "util/rng.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace proxyvis {

namespace {

// The proxy cache of a run: --cache DIR (an error when unusable), none with --no-cache, else the
// default folder, which is only a convenience: when it is unusable the run goes on without.
std::unique_ptr<ProxyCache> openCache(const SceneRunRequest& r) {
  if (r.no_cache) return nullptr;
  if (!r.cache_dir.empty()) return std::make_unique<ProxyCache>(r.cache_dir);
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

// Mesh i's work, whose failure is its outcome (the rest of the scene goes on).
MeshOutcome meshOutcome(const SceneMeshDesc& mesh, size_t i, const fs::path& proxy_file,
                        const SceneRunRequest& r, const ProxyCache* cache, uint64_t seed,
                        const std::vector<Affine3f>& placements) {
  MeshOutcome m;
  try {
    ProxyGenOptions o = r.base;
    // Per-mesh stream from the mesh's place in the scene (not in a shard): the same proxy at any
    // thread count and in any shard.
    o.seed = hashKeys(seed, i);
    o.placements = placements;
    SceneMeshProxy p = proxyForSceneMesh(mesh, o, proxy_file, cache);
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
    // A failure inside CGAL or OpenMesh the checks did not foresee.
    m.error = fmt::format("{}: {}", mesh.file.string(), e.what());
    m.code = kExitBadInput;
  }
  if (!m.error.empty()) {
    m.report = {};
    m.report.name = mesh.name;
    m.report.error = m.error;
  }
  return m;
}

// The proxies of the meshes `selected`, in parallel.
std::vector<MeshOutcome> generateSceneProxies(const SceneDesc& scene,
                                              const std::vector<bool>& selected,
                                              const std::vector<fs::path>& proxy_files,
                                              const SceneRunRequest& r, const ProxyCache* cache,
                                              const CommonOptions& common) {
  std::vector<MeshOutcome> outcomes(scene.meshes.size());
  // Where each mesh is placed: the clearance keeps its class on those placed copies.
  std::vector<std::vector<Affine3f>> placements(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m)
    if (scene.meshes[m].place) placements[m].push_back(scene.meshes[m].transform);
  for (const SceneInstanceDesc& instance : scene.instances)
    placements[instance.mesh].push_back(instance.transform);
  Progress progress("proxy-gen", size_t(std::count(selected.begin(), selected.end(), true)),
                    common.quiet, r.progress);
  tbb::parallel_for(size_t(0), scene.meshes.size(), [&](size_t i) {
    if (!selected[i]) return;
    outcomes[i] =
        meshOutcome(scene.meshes[i], i, proxy_files[i], r, cache, common.seed, placements[i]);
    progress.update();
    progress.setLabel(scene.meshes[i].name);  // the mesh finished last (one line each in a log)
  });
  progress.done();
  return outcomes;
}

// Where a run writes: each selected mesh's proxy file, and whether it is the run's.
struct ScenePlan {
  std::optional<ShardSpec> shard;
  std::vector<bool> selected;
  std::vector<fs::path> proxy_files;
  fs::path scene_out, manifest_out;
};

// File names from mesh names that cannot leave --out-dir; and before any work, no output may
// replace an input (the scene, a mesh it references, its instance list).
ScenePlan planSceneOutputs(const SceneRunRequest& r, const SceneDesc& scene,
                           const CommonOptions& common) {
  ScenePlan plan;
  plan.shard = r.shard.empty() ? std::nullopt : parseShardSpec(r.shard);
  const std::optional<ShardSpec>& shard = plan.shard;
  const size_t n = scene.meshes.size();
  std::vector<std::string> names, inputs{r.scene, scene.instances_file.string()};
  for (const SceneMeshDesc& mesh : scene.meshes) {
    names.push_back(mesh.name);
    inputs.push_back(mesh.file.string());
  }
  const std::vector<std::string> stems = proxyFileStems(names);
  plan.selected.assign(n, true);
  std::vector<OutputFlag> planned;
  for (size_t i = 0; i < n; ++i) {
    plan.proxy_files.push_back(proxyFilePath(r.out_dir, stems[i], r.kind));
    if (shard) plan.selected[i] = shardOfMesh(names[i], shard->count) == shard->index;
    if (plan.selected[i]) planned.push_back({"--out-dir", plan.proxy_files.back().string()});
  }
  plan.scene_out = fs::path(r.out_dir) / "scene.json";
  plan.manifest_out = fs::path(r.out_dir) / kShardManifestName;
  planned.push_back({"--out-dir", plan.scene_out.string()});
  if (shard) planned.push_back({"--out-dir", plan.manifest_out.string()});
  planned.push_back({"--json", common.json_path});
  planned.push_back({"--done", r.done_file});
  planned.push_back({"--gltf", r.scene_gltf});
  checkOutputs(inputs, planned);
  if (!r.scene_gltf.empty() && (shard || !isGltfPath(r.scene_gltf)))
    throw Error(
        r.scene_gltf, shard ? "--gltf needs the whole scene" : "--gltf writes .glb or .gltf",
        shard ? "a shard holds some of its proxies" : "the format is chosen by the extension",
        shard ? "merge the shards first" : "name the file .glb");
  return plan;
}

}  // namespace

std::optional<std::string> cacheDirSetting(const std::string& cache_dir, bool no_cache) {
  if (no_cache) return std::nullopt;
  if (!cache_dir.empty()) return cache_dir;
  const fs::path dir = defaultProxyCacheDir();
  if (dir.empty()) return std::nullopt;
  return dir.string();
}

int runSceneProxies(const SceneRunRequest& r, const CommonOptions& common) {
  SceneDesc scene = loadSceneDesc(r.scene);  // registers the scene and its instance list
  const ScenePlan plan = planSceneOutputs(r, scene, common);
  const GltfCompression scene_compression = r.scene_gltf.empty()
                                                ? GltfCompression::kNone
                                                : parseGltfCompression(r.compress, r.scene_gltf);
  // Before any folder is made: an unusable --cache fails the run with nothing written.
  const std::unique_ptr<ProxyCache> cache = openCache(r);
  std::error_code ec;
  fs::create_directories(r.out_dir, ec);
  if (ec) throw WriteError(r.out_dir, "cannot create the output directory", ec.message());

  const std::vector<MeshOutcome> outcomes =
      generateSceneProxies(scene, plan.selected, plan.proxy_files, r, cache.get(), common);
  const std::optional<std::string> cache_dir =
      cache ? std::optional<std::string>(cache->dir().string()) : std::nullopt;
  const SceneRunInfo info{r.scene, r.kind, plan.scene_out, cache_dir};
  SceneResult result = finishScene(scene, outcomes, plan.selected, info);
  OutputSet outputs(MissingFolders::kCreate);
  // A shard's manifest is what the merge reads: it records the shard, the scene's content hash,
  // the settings and the build, and each of its meshes' outcome with its proxy file's hash.
  if (plan.shard) {
    const json settings = shardSettings(r.base, cacheDirSetting(r.cache_dir, r.no_cache));
    const ShardManifest manifest =
        shardManifest(*plan.shard, scene, settings, outcomes, plan.selected, plan.proxy_files);
    outputs.addText(plan.manifest_out, json(manifest).dump(1) + "\n");
  }
  if (!r.scene_gltf.empty())
    addSceneGltfOutput(outputs, plan.scene_out, outcomes, plan.proxy_files, r.scene_gltf,
                       scene_compression);
  emit(json(result.report), result.summary, common, outputs);
  // A plan unit's marker, last: it exists only when every output above is in place.
  if (!r.done_file.empty() && result.code == kExitOk) {
    OutputSet done(MissingFolders::kCreate);
    done.addText(r.done_file, fmt::format("shard {}\n", r.shard));
    done.commit();
  }
  return result.code;
}

}  // namespace proxyvis
