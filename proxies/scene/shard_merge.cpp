#include "proxies/scene/shard_merge.h"

#include <fmt/core.h>

#include <map>

#include "mesh/io/mesh_io.h"
#include "proxies/pipeline/proxy_outputs.h"
#include "proxies/pipeline/report_fields.h"
#include "proxies/scene/output_paths.h"
#include "proxies/scene/scene_mesh.h"
#include "proxies/scene/shard_manifest.h"
#include "util/error.h"
#include "util/input_file.h"
#include "util/output_path.h"
#include "util/program_build_id.h"
#include "util/sha256.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace proxyvis {

namespace {

std::vector<std::string> meshStems(const SceneDesc& scene) {
  std::vector<std::string> names;
  for (const SceneMeshDesc& mesh : scene.meshes) names.push_back(mesh.name);
  return proxyFileStems(names);
}

// One shard's manifest, read and checked against the merge's own scene, settings and build.
struct Shard {
  fs::path dir, manifest_path;
  ShardManifest manifest;
};

Shard readShard(const std::string& dir, const std::string& scene_hash, const json& settings) {
  Shard s;
  s.dir = dir;
  s.manifest_path = fs::path(dir) / kShardManifestName;
  const std::string text = readTextFile(s.manifest_path);
  const json manifest = json::parse(text, nullptr, false);
  const std::string file = s.manifest_path.string();
  if (manifest.is_discarded() || !manifest.is_object())
    throw Error(file, "not a proxy-gen shard manifest: not JSON", "it is truncated or damaged",
                "run that shard again");
  const Field f(manifest, "", s.manifest_path);
  // The format first: another format's other keys are not this one's to read.
  if (f["proxy_gen_shard"].asInt() != kShardManifestFormat)
    throw Error(file, "a shard manifest of another format", "written by another proxy-gen version",
                "run the shards again with this build");
  s.manifest = readShardManifest(f);
  if (s.manifest.build != programBuildId())
    throw Error(file, "a shard of another build",
                "it was made by another proxy-gen executable, whose proxies may differ",
                "run the shards and the merge with one build");
  if (s.manifest.scene_hash != scene_hash)
    throw Error(file, "a shard of another scene",
                "its scene's content hash differs from this scene's (the scene or a file it "
                "references changed, or it is another scene)",
                "merge shards of this very scene, or run them again");
  if (s.manifest.settings != settings)
    throw Error(file, "a shard made with other settings",
                fmt::format("it recorded {}, the merge has {}", s.manifest.settings.dump(),
                            settings.dump()),
                "give the merge the shards' --kind, sizes, budget, --seed and cache flags");
  return s;
}

// Before anything is read or written: no output may replace an input (the scene, its files,
// any file of a shard).
std::vector<std::string> mergeInputs(const MergeRequest& r, const SceneDesc& scene,
                                     const std::vector<std::string>& stems) {
  std::vector<std::string> inputs{r.scene, scene.instances_file.string()};
  for (const SceneMeshDesc& mesh : scene.meshes) inputs.push_back(mesh.file.string());
  for (const std::string& dir : r.shard_dirs) {
    inputs.push_back((fs::path(dir) / kShardManifestName).string());
    inputs.push_back((fs::path(dir) / "scene.json").string());
    for (const std::string& stem : stems) {
      const fs::path p = proxyFilePath(dir, stem, r.kind);
      inputs.push_back(p.string());
      inputs.push_back(p.string() + ".sha256");
    }
  }
  return inputs;
}

// The shards of one --shard i/n split, each once, none missing.
struct ShardSet {
  std::vector<Shard> shards;
  std::map<uint64_t, size_t> by_index;  // shard index -> position in `shards`
  uint64_t count = 0;                   // n
};

ShardSet readShardSet(const MergeRequest& r, const std::string& scene_hash, const json& settings) {
  ShardSet set;
  std::vector<Shard>& shards = set.shards;
  std::map<uint64_t, size_t>& by_index = set.by_index;
  uint64_t& count = set.count;
  for (const std::string& dir : r.shard_dirs) {
    Shard s = readShard(dir, scene_hash, settings);
    const std::string file = s.manifest_path.string();
    const uint64_t i = s.manifest.shard.index, n = s.manifest.shard.count;
    if (n < 1 || n > kMaxShards || i >= n)
      throw Error(file, "not a proxy-gen shard manifest: bad shard numbers", "it is damaged",
                  "run that shard again");
    if (count == 0) count = n;
    if (n != count)
      throw Error(file, fmt::format("shard {}/{} of another split", i, n),
                  fmt::format("{} is a shard of {}", shards.front().manifest_path.string(), count),
                  "merge the shards of one --shard i/n split");
    if (const auto seen = by_index.find(i); seen != by_index.end())
      throw Error(file, fmt::format("shard {}/{} given twice", i, n),
                  fmt::format("{} is the same shard", shards[seen->second].manifest_path.string()),
                  "give each shard's folder once");
    by_index[i] = shards.size();
    shards.push_back(std::move(s));
  }
  for (uint64_t i = 0; i < count; ++i)
    if (!by_index.count(i))
      throw Error(r.scene, fmt::format("shard {}/{} is missing from the merge", i, count),
                  fmt::format("{} of {} shard folders were given", shards.size(), count),
                  "give the folder of every shard 0..n-1");
  return set;
}

}  // namespace

int mergeShards(const MergeRequest& r, const CommonOptions& common) {
  const SceneDesc scene = loadSceneDesc(r.scene);
  const size_t n_meshes = scene.meshes.size();
  const std::vector<std::string> stems = meshStems(scene);
  std::vector<fs::path> proxy_files;
  std::vector<OutputFlag> planned;
  for (const std::string& stem : stems) {
    proxy_files.push_back(proxyFilePath(r.out_dir, stem, r.kind));
    planned.push_back({"--out-dir", proxy_files.back().string()});
  }
  const fs::path scene_out = fs::path(r.out_dir) / "scene.json";
  planned.push_back({"--out-dir", scene_out.string()});
  planned.push_back({"--json", common.json_path});
  checkOutputs(mergeInputs(r, scene, stems), planned);

  const std::string scene_hash = sceneHash(scene);
  const json settings = shardSettings(r.base, r.cache_dir);
  const ShardSet set = readShardSet(r, scene_hash, settings);
  const std::vector<Shard>& shards = set.shards;
  const uint64_t count = set.count;

  // Each mesh from the one shard it belongs to; its proxy file as that shard recorded it.
  std::vector<MeshOutcome> outcomes(n_meshes);
  std::vector<bool> seen(n_meshes, false);
  std::vector<std::optional<std::string>> proxy_bytes(n_meshes);
  for (const Shard& s : shards) {
    const std::string file = s.manifest_path.string();
    const uint64_t shard_index = s.manifest.shard.index;
    for (const ShardMeshEntry& entry : s.manifest.meshes) {
      const uint64_t i = entry.index;
      const std::string& name = entry.name;
      if (i >= n_meshes || scene.meshes[i].name != name ||
          shardOfMesh(name, count) != shard_index || seen[i])
        throw Error(file, fmt::format("mesh '{}' does not belong to this shard", name),
                    "the manifest does not match the scene's split", "run that shard again");
      seen[i] = true;
      MeshOutcome& m = outcomes[i];
      m.report = entry.report;
      m.skipped = entry.skipped;
      m.cache_note = entry.cache_note;
      m.error = entry.error;
      m.code = entry.code;
      if (!entry.proxy_file) continue;
      const fs::path from = s.dir / *entry.proxy_file;
      if (from.filename() != proxy_files[i].filename() || !m.report.proxy)
        throw Error(file, fmt::format("mesh '{}' names another proxy file", name),
                    "the manifest is damaged", "run that shard again");
      std::string bytes = readTextFile(from);
      if (sha256Hex(bytes) != entry.proxy_sha256)
        throw Error(from.string(), "not the proxy its shard wrote",
                    "its SHA-256 differs from the one in the shard's manifest (truncated or "
                    "changed since)",
                    fmt::format("run shard {} again", shard_index));
      m.report.proxy->output = proxy_files[i].string();
      m.ref = proxyRefFor(*m.report.proxy, *parseProxyClass(r.kind), proxy_files[i], bytes);
      proxy_bytes[i] = std::move(bytes);
    }
  }
  for (size_t i = 0; i < n_meshes; ++i)
    if (!seen[i])
      throw Error(
          shards[set.by_index.at(shardOfMesh(scene.meshes[i].name, count))].manifest_path.string(),
          fmt::format("mesh '{}' is missing from its shard", scene.meshes[i].name),
          "the manifest does not match the scene's split", "run that shard again");

  // Only now, with every input checked, is anything staged (the output folder included): the
  // proxies first, then the scene that lists them and the report, as the whole run.
  OutputSet proxies(MissingFolders::kCreate);
  for (size_t i = 0; i < n_meshes; ++i)
    if (proxy_bytes[i]) addEncodedMeshOutput(proxies, *proxy_bytes[i], proxy_files[i]);
  proxies.commit();
  const SceneRunInfo info{r.scene, r.kind, scene_out, r.cache_dir};
  SceneResult result = finishScene(scene, outcomes, std::vector<bool>(n_meshes, true), info);
  OutputSet outputs(MissingFolders::kCreate);
  emit(result.report, result.summary, common, outputs);
  return result.code;
}

}  // namespace proxyvis
