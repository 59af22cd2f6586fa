#include "scene_outputs.h"

#include <fmt/core.h>

#include <cstdio>
#include <map>

#include "summary_text.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace proxyvis {

fs::path proxyFilePath(const std::string& out_dir, const std::string& stem,
                       const std::string& kind) {
  return fs::path(out_dir) / fmt::format("{}.{}.ply", stem, kind);
}

void noteWrittenClass(const ProxyReport& report, const std::string& file) {
  if (!report.class_reason) return;
  std::fprintf(stderr, "proxy-gen: note: %s: written as class %s, not %s: %s\n", file.c_str(),
               proxyClassName(report.written_class.value_or(ProxyClass::kGeneral)),
               proxyClassName(report.kind), report.class_reason->c_str());
}

void emit(const json& report, const std::string& summary, const CommonOptions& common,
          OutputSet& outputs) {
  if (!common.json_path.empty()) outputs.addText(common.json_path, report.dump(2) + "\n");
  outputs.commit();
  printHumanReport(common, summary);
}

SceneResult finishScene(SceneDesc scene, const std::vector<MeshOutcome>& outcomes,
                        const std::vector<bool>& only, const SceneRunInfo& info) {
  SceneResult result;
  std::string& summary = result.summary;
  std::vector<json> reports;
  std::map<std::string, size_t> cache_counts{{"cached", 0}, {"generated", 0}};
  for (size_t i = 0; i < outcomes.size(); ++i) {
    if (!only[i]) continue;
    const MeshOutcome& m = outcomes[i];
    reports.push_back(m.report);
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
  json cache_report = nullptr;
  if (info.cache_dir) {
    cache_report = {{"dir", *info.cache_dir},
                    {"cached", cache_counts["cached"]},
                    {"generated", cache_counts["generated"]}};
    summary += fmt::format("proxy cache: {} ({} cached, {} generated)\n", *info.cache_dir,
                           cache_counts["cached"], cache_counts["generated"]);
  }
  result.report = {{"scene", info.input},
                   {"scene_out", info.scene_out.string()},
                   {"cache", cache_report},
                   {"meshes", reports}};
  return result;
}

}  // namespace proxyvis
