#include "proxies/scene/shard_manifest.h"

#include "proxies/pipeline/json_visit.h"
#include "proxies/pipeline/proxy_cache.h"
#include "util/program_build_id.h"
#include "util/sha256.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace proxyvis {

// The keys of the manifest (proxies/pipeline/json_visit.h): one list for writing and reading.

template <typename V>
void fields(ShardMeshEntry& e, V& v) {
  v("index", e.index);
  v("name", e.name);
  v("report", e.report);
  v("skipped", e.skipped);
  v("cache_note", e.cache_note);
  v("error", e.error);
  v("code", e.code);
  v("proxy_file", e.proxy_file);
  v("proxy_sha256", e.proxy_sha256);
}

template <typename V>
void fields(ShardManifest& m, V& v) {
  v("proxy_gen_shard", m.format);
  v("shard", m.shard.index);
  v("shards", m.shard.count);
  v("scene_hash", m.scene_hash);
  v("settings", m.settings);
  v("build", m.build);
  v("meshes", m.meshes);
}

void to_json(json& j, const ShardManifest& m) {
  j = toJsonValue(m);
}

ShardManifest readShardManifest(const Field& f) {
  return readFields<ShardManifest>(f);
}

void from_json(const json& j, ShardManifest& m) {
  m = readWithoutFile(j, readShardManifest);
}

json shardSettings(const ProxyGenOptions& base, const std::optional<std::string>& cache_dir) {
  json s = proxyCacheSettings(base);
  s["cache"] = cache_dir ? json(*cache_dir) : json(nullptr);
  return s;
}

ShardManifest shardManifest(const ShardSpec& shard, const SceneDesc& scene, const json& settings,
                            const std::vector<MeshOutcome>& outcomes,
                            const std::vector<bool>& selected,
                            const std::vector<fs::path>& proxy_files) {
  ShardManifest m{kShardManifestFormat, shard, sceneHash(scene), settings, programBuildId(), {}};
  for (size_t i = 0; i < outcomes.size(); ++i) {
    if (!selected[i]) continue;
    const MeshOutcome& o = outcomes[i];
    ShardMeshEntry e{i,      scene.meshes[i].name, o.report,    o.skipped, o.cache_note, o.error,
                     o.code, std::nullopt,         std::nullopt};
    if (o.ref) {
      e.proxy_file = proxy_files[i].filename().string();
      e.proxy_sha256 = sha256OfOwnFile(proxy_files[i]);
    }
    m.meshes.push_back(std::move(e));
  }
  return m;
}

}  // namespace proxyvis
