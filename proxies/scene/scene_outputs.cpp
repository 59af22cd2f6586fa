#include "proxies/scene/scene_outputs.h"

#include <fmt/core.h>

#include <cstdio>
#include <map>

#include "proxies/pipeline/json_visit.h"
#include "proxies/pipeline/proxy_outputs.h"
#include "proxies/pipeline/proxy_report_text.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace proxyvis {

fs::path proxyFilePath(const std::string& out_dir, const std::string& stem,
                       const std::string& kind) {
  return fs::path(out_dir) / fmt::format("{}.{}.ply", stem, kind);
}

// The keys of the report (proxies/pipeline/json_visit.h): one list for writing and reading.

template <typename V>
void fields(ProxyCacheTally& c, V& v) {
  v("dir", c.dir);
  v("cached", c.cached);
  v("generated", c.generated);
}

template <typename V>
void fields(SceneRunReport& r, V& v) {
  v("scene", r.scene);
  v("scene_out", r.scene_out);
  v.nullable("cache", r.cache);
  v("meshes", r.meshes);
}

void to_json(json& j, const SceneRunReport& r) {
  j = toJsonValue(r);
}

void from_json(const json& j, SceneRunReport& r) {
  r = readWithoutFile(j, readFields<SceneRunReport>);
}

SceneResult finishScene(SceneDesc scene, const std::vector<MeshOutcome>& outcomes,
                        const std::vector<bool>& only, const SceneRunInfo& info) {
  SceneResult result;
  std::string& summary = result.summary;
  std::map<std::string, size_t> cache_counts{{"cached", 0}, {"generated", 0}};
  for (size_t i = 0; i < outcomes.size(); ++i) {
    if (!only[i]) continue;
    const MeshOutcome& m = outcomes[i];
    result.report.meshes.push_back(m.report);
    if (!m.error.empty()) {
      // The failure goes to stderr like any error (one line per failed mesh); the scene is
      // still written, without a proxy for this mesh, and the exit code reports it.
      std::fprintf(stderr, "proxy-gen: error: %s\n", m.error.c_str());
      summary += fmt::format("== {}: FAILED: {}\n", scene.meshes[i].name, m.error);
      result.code = std::max(result.code, m.code);
      continue;
    }
    if (!m.cache_note.empty())
      std::fprintf(stderr, "proxy-gen: note: %s: %s\n", scene.meshes[i].file.c_str(),
                   m.cache_note.c_str());
    const std::string state = m.report.cache.value_or("off");
    if (state != "off") ++cache_counts[state];
    const std::string from = state == "off" ? "" : fmt::format(" ({})", state);
    if (!m.skipped.empty()) {
      summary += fmt::format("== {}: no proxy ({}){}\n", scene.meshes[i].name, m.skipped, from);
      continue;
    }
    noteWrittenClass(*m.report.proxy, scene.meshes[i].file.string());
    summary +=
        fmt::format("== {}{}\n{}", scene.meshes[i].name, from, proxySummaryText(*m.report.proxy));
    auto& proxies = scene.meshes[i].proxies;
    std::erase_if(proxies, [&](const ProxyRef& p) { return p.kind == info.kind; });
    proxies.push_back(*m.ref);
  }
  saveSceneDesc(scene, info.scene_out);
  summary += fmt::format("scene with proxies: {}\n", info.scene_out.string());
  result.report.scene = info.input;
  result.report.scene_out = info.scene_out.string();
  if (info.cache_dir) {
    result.report.cache =
        ProxyCacheTally{*info.cache_dir, cache_counts["cached"], cache_counts["generated"]};
    summary += fmt::format("proxy cache: {} ({} cached, {} generated)\n", *info.cache_dir,
                           cache_counts["cached"], cache_counts["generated"]);
  }
  return result;
}

}  // namespace proxyvis
