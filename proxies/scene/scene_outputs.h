#pragma once
// What proxy-gen writes at the end of a scene run, from each mesh's outcome: the scene with its
// proxies, the summary and the JSON report. A whole run, a shard and the merge of shards all end
// here, so the merge of shards writes exactly what the whole run writes.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "proxies/pipeline/proxy_report.h"
#include "scene/scene_desc.h"
#include "util/app_main.h"
#include "util/error.h"
#include "util/output_set.h"

namespace proxyvis {

// One mesh of the scene after its work: a proxy (ref), no proxy (skipped: why) or a failure
// (error, code).
struct MeshOutcome {
  SceneMeshReport report;
  std::optional<ProxyRef> ref;
  std::string skipped;
  std::string cache_note;
  std::string error;
  int code = kExitOk;
};

// Where the proxy of the mesh with file stem `stem` goes: DIR/<stem>.<kind>.ply.
std::filesystem::path proxyFilePath(const std::string& out_dir, const std::string& stem,
                                    const std::string& kind);

struct SceneRunInfo {
  std::string input;  // the scene as named on the command line
  std::string kind;   // --kind
  std::filesystem::path scene_out;
  std::optional<std::string> cache_dir;  // the proxy cache used, if any
};

// The proxy cache a scene run used, and how many of its meshes came from it ("cache").
struct ProxyCacheTally {
  std::string dir;
  uint64_t cached = 0, generated = 0;
  bool operator==(const ProxyCacheTally&) const = default;
};

// The JSON report of a scene run (--json): the scene, the scene written, the cache (null
// without one) and each mesh's report.
struct SceneRunReport {
  std::string scene, scene_out;
  std::optional<ProxyCacheTally> cache;
  std::vector<SceneMeshReport> meshes;
  bool operator==(const SceneRunReport&) const = default;
};

void to_json(nlohmann::json& j, const SceneRunReport& r);
void from_json(const nlohmann::json& j, SceneRunReport& r);

struct SceneResult {
  int code = kExitOk;
  SceneRunReport report;
  std::string summary;
};

// Prints each mesh's error and notes on stderr, writes `scene` with the new proxies to
// info.scene_out (entries of meshes that failed or got none keep the scene's own proxies) and
// returns the report, the summary and the exit code (the worst mesh's). `outcomes` holds one
// entry per mesh of `scene`; entries of meshes not worked on are left out when `only` says so.
SceneResult finishScene(SceneDesc scene, const std::vector<MeshOutcome>& outcomes,
                        const std::vector<bool>& only, const SceneRunInfo& info);

}  // namespace proxyvis
