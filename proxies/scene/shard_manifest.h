#pragma once
// The record a proxy-gen shard leaves beside its proxies (DIR/shard.json), which the merge of
// shards reads (shard_merge.h, docs/proxy_gen_shards.md).
//
// A shard's manifest names the shard (i of n), the scene's content hash, every setting that
// changes the output, the build, and for each of its meshes the outcome: the report, why it got
// no proxy or why it failed, and the proxy file's name and SHA-256. The merge trusts nothing
// else: the shards' scene.json and reports are for people.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "proxies/pipeline/proxy_pipeline.h"
#include "proxies/scene/scene_outputs.h"
#include "proxies/scene/shard.h"
#include "scene/scene_desc.h"

namespace proxyvis {

class JsonField;

inline constexpr const char* kShardManifestName = "shard.json";
inline constexpr int kShardManifestFormat = 1;

// One mesh of a shard: its outcome (MeshOutcome) and, when it got a proxy, the file's name and
// SHA-256.
struct ShardMeshEntry {
  uint64_t index = 0;  // in the scene's meshes
  std::string name;
  SceneMeshReport report;
  std::string skipped, cache_note, error;
  int code = 0;
  std::optional<std::string> proxy_file, proxy_sha256;
  bool operator==(const ShardMeshEntry&) const = default;
};

// DIR/shard.json.
struct ShardManifest {
  int format = kShardManifestFormat;  // "proxy_gen_shard"
  ShardSpec shard;                    // "shard", "shards"
  std::string scene_hash;
  nlohmann::json settings;  // shardSettings: compared as a whole, never read key by key
  std::string build;
  std::vector<ShardMeshEntry> meshes;
  bool operator==(const ShardManifest&) const = default;
};

void to_json(nlohmann::json& j, const ShardManifest& m);
void from_json(const nlohmann::json& j, ShardManifest& m);
// from_json's reader, for a file's value: errors name the file and the key's path.
ShardManifest readShardManifest(const JsonField& f);

// Every setting that changes what a scene run writes: the generator's (proxyCacheSettings, with
// the base seed) and the proxy cache folder (null = none), which the report names.
nlohmann::json shardSettings(const ProxyGenOptions& base,
                             const std::optional<std::string>& cache_dir);

// The manifest of shard `shard` over `scene`: `selected[i]` says which meshes are its own;
// `proxy_files[i]` is where mesh i's proxy was written (only read for meshes with a proxy).
ShardManifest shardManifest(const ShardSpec& shard, const SceneDesc& scene,
                            const nlohmann::json& settings,
                            const std::vector<MeshOutcome>& outcomes,
                            const std::vector<bool>& selected,
                            const std::vector<std::filesystem::path>& proxy_files);

}  // namespace proxyvis
