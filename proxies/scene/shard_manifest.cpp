#include "proxies/scene/shard_manifest.h"

#include "proxies/pipeline/proxy_cache.h"
#include "proxies/pipeline/report_fields.h"
#include "util/program_build_id.h"
#include "util/sha256.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace proxyvis {

namespace {

json entryJson(const ShardMeshEntry& e) {
  json j = {{"index", e.index},
            {"name", e.name},
            {"report", e.report},
            {"skipped", e.skipped},
            {"cache_note", e.cache_note},
            {"error", e.error},
            {"code", e.code}};
  if (e.proxy_file) j["proxy_file"] = *e.proxy_file;
  if (e.proxy_sha256) j["proxy_sha256"] = *e.proxy_sha256;
  return j;
}

ShardMeshEntry readEntry(const Field& f) {
  ShardMeshEntry e;
  e.index = readCount(f["index"]);
  e.name = f["name"].asString();
  e.report = readSceneMeshReport(f["report"]);
  e.skipped = f["skipped"].asString();
  e.cache_note = f["cache_note"].asString();
  e.error = f["error"].asString();
  e.code = f["code"].asInt();
  e.proxy_file = optionalString(f, "proxy_file");
  if (e.proxy_file) e.proxy_sha256 = f["proxy_sha256"].asString();
  return e;
}

}  // namespace

void to_json(json& j, const ShardManifest& m) {
  json meshes = json::array();
  for (const ShardMeshEntry& e : m.meshes) meshes.push_back(entryJson(e));
  j = {{"proxy_gen_shard", m.format},
       {"shard", m.shard.index},
       {"shards", m.shard.count},
       {"scene_hash", m.scene_hash},
       {"settings", m.settings},
       {"build", m.build},
       {"meshes", meshes}};
}

ShardManifest readShardManifest(const Field& f) {
  ShardManifest m;
  m.format = f["proxy_gen_shard"].asInt();
  m.shard = {readCount(f["shard"]), readCount(f["shards"])};
  m.scene_hash = f["scene_hash"].asString();
  m.settings = f["settings"].value();
  if (!m.settings.is_object()) f["settings"].fail("expected an object");
  m.build = f["build"].asString();
  const Field meshes = f["meshes"];
  for (size_t i = 0, n = meshes.arraySize(); i < n; ++i) m.meshes.push_back(readEntry(meshes[i]));
  return m;
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
