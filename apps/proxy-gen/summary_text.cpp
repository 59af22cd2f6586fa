#include "summary_text.h"

#include <fmt/core.h>

#include <set>

#include "proxies/check/distance_report.h"

namespace proxyvis {

using json = nlohmann::json;

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

std::string inputState(const json& input) {
  if (input.value("closed", false)) return "closed";
  return input.value("watertight", false)
             ? "watertight, non-manifold"
             : fmt::format("open, {} boundary edges", input.value("boundary_edges", 0));
}

// "300 faces, budget 300 (--max-faces): reached" and the like; empty without a face budget.
std::string budgetText(const json& r) {
  const json& p = r["parameters"];
  std::string budget;
  if (p.value("max_faces", 0) > 0)
    budget = fmt::format("{} faces (--max-faces)", p["max_faces"].get<uint64_t>());
  else if (p.contains("max_faces_from_ratio")) {
    const uint64_t faces = p["max_faces_from_ratio"].get<uint64_t>();
    budget = faces == p.value("min_faces", uint64_t(0))
                 ? fmt::format("{} faces (--min-faces: --ratio asked for fewer of the input's {})",
                               faces, r["input"]["faces"].get<uint64_t>())
                 : fmt::format("{} faces (--ratio times the input's {})", faces,
                               r["input"]["faces"].get<uint64_t>());
  } else if (p.contains("max_faces_auto"))
    budget = fmt::format("{} faces (the input's count: a proxy must not cost more)",
                         p["max_faces_auto"].get<uint64_t>());
  else if (p.contains("ratio"))
    budget = fmt::format("--ratio {:g} of the input's faces", p["ratio"].get<double>());
  if (budget.empty()) return {};
  if (r.contains("budget_reached"))
    budget += r["budget_reached"].get<bool>() ? ", reached" : ", NOT reached (--budget soft)";
  if (r.contains("budget_fallback"))
    budget += fmt::format(", by the fallback {}", r["budget_fallback"].get<std::string>());
  return budget;
}

// Why the proxy is, or is not, verified.
std::string verifiedText(const json& r) {
  const json& c = r["checks"];
  if (r.value("verified", false))
    return c.contains("containment_detail")
               ? fmt::format("yes (exact containment check: {})",
                             c["containment_detail"].get<std::string>())
               : std::string("yes (closed, manifold, no self-intersections)");
  std::vector<std::string> why;
  if (!c.value("closed", true)) why.push_back("not closed");
  if (!c.value("manifold", true)) why.push_back("not manifold");
  if (c.value("self_intersecting_pairs", 0) > 0)
    why.push_back(fmt::format("{} self-intersecting face pairs",
                              c["self_intersecting_pairs"].get<uint64_t>()));
  std::string s = "NO";
  for (size_t i = 0; i < why.size(); ++i) s += (i == 0 ? " (" : ", ") + why[i];
  return why.empty() ? s : s + ")";
}

std::string volumeText(const json& r) {
  if (r["volume_ratio"].is_number())
    return fmt::format("{:.4f} (proxy volume / input volume)", r["volume_ratio"].get<double>());
  if (!r["checks"].value("closed", false)) return "none: the proxy is open, it bounds no volume";
  return "none: the input is open, it bounds no volume";
}

std::string secondsText(const json& seconds) {
  std::string s;
  std::set<std::string> shown{"total"};
  auto line = [&](const std::string& label, double value) {
    s += fmt::format("  {:<18} {:8.3f}\n", label, value);
  };
  for (const StageName& stage : proxyGenStages()) {
    if (!seconds.contains(stage.key)) continue;
    line(stage.label, seconds[stage.key].get<double>());
    shown.insert(stage.key);
  }
  for (const auto& [key, value] : seconds.items())  // a stage this list does not know yet
    if (!shown.count(key)) line(key, value.get<double>());
  if (seconds.contains("total")) line("total", seconds["total"].get<double>());
  return s;
}

}  // namespace

std::string proxySummaryText(const json& r) {
  std::string s;
  const json& in = r["input"];
  s += fmt::format("input:      {} ({} faces, {})\n", in["path"].get<std::string>(),
                   in["faces"].get<uint64_t>(), inputState(in));
  if (r.contains("output")) s += fmt::format("output:     {}\n", r["output"].get<std::string>());
  const uint64_t faces = r["faces"].get<uint64_t>(), built = r["faces_before_budget"];
  s += fmt::format("proxy:      {} / {}, {} faces{}\n", r["kind"].get<std::string>(),
                   r["method"].get<std::string>(), faces,
                   built != faces ? fmt::format(" ({} before the budget reduction)", built) : "");
  if (const std::string budget = budgetText(r); !budget.empty())
    s += fmt::format("budget:     {}\n", budget);
  s += fmt::format("volume ratio: {}\n", volumeText(r));
  if (r.contains("hausdorff"))
    s += fmt::format("Hausdorff (sampled, a lower bound): {}\n",
                     hausdorffText(hausdorffFromJson(r["hausdorff"])));
  s += fmt::format("verified:   {}\n", verifiedText(r));
  const json& cls = r["class"];
  s += fmt::format("class:      {}{}\n", cls.is_string() ? cls.get<std::string>() : "none",
                   r.contains("class_reason")
                       ? fmt::format(" ({})", r["class_reason"].get<std::string>())
                       : std::string());
  s += "seconds:\n" + secondsText(r["seconds"]);
  return s;
}

}  // namespace proxyvis
