#include "proxies/pipeline/proxy_report_text.h"

#include <fmt/core.h>

#include <set>

#include "proxies/check/distance_report.h"

namespace proxyvis {

const std::vector<StageName>& proxyGenStages() {
  static const std::vector<StageName> stages{
      {"load", "load", 0},
      {"validate_input", "validate", 1},
      {"fill_holes", "fill holes", 1},
      {"build", "build", 2},
      {"simplify", "budget reduction", 3},
      {"budget_ladder", "budget fallbacks", 3},
      {"verify", "verify", 4},
      {"metrics", "measure", 5},
  };
  return stages;
}

namespace {

std::string inputState(const ProxyInputFacts& input) {
  if (input.closed) return "closed";
  return input.watertight ? "watertight, non-manifold"
                          : fmt::format("open, {} boundary edges", input.boundary_edges);
}

// "300 faces, budget 300 (--max-faces): reached" and the like; empty without a face budget.
std::string budgetText(const ProxyReport& r) {
  const ProxyParameters& p = r.parameters;
  std::string budget;
  if (p.max_faces > 0)
    budget = fmt::format("{} faces (--max-faces)", p.max_faces);
  else if (p.max_faces_from_ratio) {
    const uint64_t faces = *p.max_faces_from_ratio;
    budget = faces == p.min_faces.value_or(0)
                 ? fmt::format("{} faces (--min-faces: --ratio asked for fewer of the input's {})",
                               faces, r.input.faces)
                 : fmt::format("{} faces (--ratio times the input's {})", faces, r.input.faces);
  } else if (p.max_faces_auto)
    budget =
        fmt::format("{} faces (the input's count: a proxy must not cost more)", *p.max_faces_auto);
  else if (p.ratio)
    budget = fmt::format("--ratio {:g} of the input's faces", *p.ratio);
  if (budget.empty()) return {};
  if (r.budget_reached) budget += *r.budget_reached ? ", reached" : ", NOT reached (--budget soft)";
  if (r.budget_fallback) budget += fmt::format(", by the fallback {}", *r.budget_fallback);
  return budget;
}

// Why the proxy is, or is not, verified.
std::string verifiedText(const ProxyReport& r) {
  const ProxyChecks& c = r.checks;
  if (r.verified)
    return c.containment_detail
               ? fmt::format("yes (exact containment check: {})", *c.containment_detail)
               : std::string("yes (closed, manifold, no self-intersections)");
  std::vector<std::string> why;
  if (!c.closed) why.push_back("not closed");
  if (!c.manifold) why.push_back("not manifold");
  if (c.self_intersecting_pairs > 0)
    why.push_back(fmt::format("{} self-intersecting face pairs", c.self_intersecting_pairs));
  std::string s = "NO";
  for (size_t i = 0; i < why.size(); ++i) s += (i == 0 ? " (" : ", ") + why[i];
  return why.empty() ? s : s + ")";
}

std::string volumeText(const ProxyReport& r) {
  if (r.volume_ratio) return fmt::format("{:.4f} (proxy volume / input volume)", *r.volume_ratio);
  if (!r.checks.closed) return "none: the proxy is open, it bounds no volume";
  return "none: the input is open, it bounds no volume";
}

std::string secondsText(const std::map<std::string, double>& seconds) {
  std::string s;
  std::set<std::string> shown{"total"};
  auto line = [&](const std::string& label, double value) {
    s += fmt::format("  {:<18} {:8.3f}\n", label, value);
  };
  for (const StageName& stage : proxyGenStages()) {
    const auto it = seconds.find(stage.key);
    if (it == seconds.end()) continue;
    line(stage.label, it->second);
    shown.insert(stage.key);
  }
  for (const auto& [key, value] : seconds)  // a stage this list does not know yet
    if (!shown.count(key)) line(key, value);
  if (const auto total = seconds.find("total"); total != seconds.end())
    line("total", total->second);
  return s;
}

}  // namespace

std::string proxySummaryText(const ProxyReport& r) {
  std::string s;
  s += fmt::format("input:      {} ({} faces, {})\n", r.input.path, r.input.faces,
                   inputState(r.input));
  if (r.output) s += fmt::format("output:     {}\n", *r.output);
  const uint64_t faces = r.faces, built = r.faces_before_budget;
  s += fmt::format("proxy:      {} / {}, {} faces{}\n", proxyClassName(r.kind), r.method, faces,
                   built != faces ? fmt::format(" ({} before the budget reduction)", built) : "");
  if (const std::string budget = budgetText(r); !budget.empty())
    s += fmt::format("budget:     {}\n", budget);
  s += fmt::format("volume ratio: {}\n", volumeText(r));
  s += fmt::format("Hausdorff (sampled, a lower bound): {}\n", hausdorffText(r.hausdorff));
  s += fmt::format("verified:   {}\n", verifiedText(r));
  s +=
      fmt::format("class:      {}{}\n", r.written_class ? proxyClassName(*r.written_class) : "none",
                  r.class_reason ? fmt::format(" ({})", *r.class_reason) : std::string());
  s += "seconds:\n" + secondsText(r.seconds);
  return s;
}

}  // namespace proxyvis
