#include "metrics/ceiling_report.h"

#include <fmt/format.h>

#include <utility>

#include "metrics/log_plot.h"
#include "util/escape_html.h"

namespace proxyvis {

namespace {

constexpr const char* kColumns[] = {
    "light", "segments", "P(V'=0)", "P(MH')", "P(HM')",           "V(1-V)", "c_p|0",
    "c_p|1", "c_o|0",    "c_o|1",   "c_s",    "roulette regions", "ceiling"};

// The per-light table's lines: each light by its index, then the whole scene as "all".
std::vector<std::pair<std::string, const CeilingSummary*>> tableLines(const CeilingResult& r) {
  std::vector<std::pair<std::string, const CeilingSummary*>> lines;
  for (size_t i = 0; i < r.lights.size(); ++i) lines.emplace_back(std::to_string(i), &r.lights[i]);
  lines.emplace_back("all", &r.scene);
  return lines;
}

// The cells of one table line, formatted (costs in ns).
std::vector<std::string> cells(const std::string& light, const CeilingSummary& l) {
  return {light,
          fmt::format("{:.0f}", l.segments),
          fmt::format("{:.3f}", l.p_blocked),
          fmt::format("{:.4f}", l.p_mh),
          fmt::format("{:.4f}", l.p_hm),
          fmt::format("{:.4f}", l.visibility_var),
          fmt::format("{:.1f}", l.costs.proxy[0]),
          fmt::format("{:.1f}", l.costs.proxy[1]),
          fmt::format("{:.1f}", l.costs.original[0]),
          fmt::format("{:.1f}", l.costs.original[1]),
          fmt::format("{:.1f}", l.costs.per_sample),
          fmt::format("{} of {}", l.regions_roulette, l.regions),
          fmt::format("{:.3f}×", l.ceiling)};
}

// One line of meta.ceiling.lights.
nlohmann::json lightJson(const std::string& light, const CeilingSummary& l) {
  return {{"light", light},
          {"segments", l.segments},
          {"p_proxy_blocked", l.p_blocked},
          {"p_mh", l.p_mh},
          {"p_hm", l.p_hm},
          {"var_exact", l.visibility_var},
          {"cost_proxy", {l.costs.proxy[0], l.costs.proxy[1]}},
          {"cost_original", {l.costs.original[0], l.costs.original[1]}},
          {"cost_per_sample", l.costs.per_sample},
          {"regions", l.regions},
          {"regions_roulette", l.regions_roulette},
          {"ceiling", l.ceiling}};
}

std::string measuredText(const ReportCeiling& c) {
  return fmt::format(
      "Measured on {} light samples per pixel traced against proxy and original in {:.2f} s "
      "({:.1f} % of the renders' time); costs in ns per ray, c_s in ns per sample. The model's "
      "MSE of exact at 1 spp is {:.3e} (an exact row at N spp should be near it / N).",
      c.passes, c.seconds, 100 * c.run_share, c.exact_mse_1spp);
}

// A Markdown table cell: '|' would end it.
std::string markdownCell(const std::string& text) {
  std::string out;
  for (char ch : text) {
    if (ch == '|') out += '\\';
    out += ch;
  }
  return out;
}

}  // namespace

void to_json(nlohmann::json& j, const ReportCeiling& c) {
  nlohmann::json lights = nlohmann::json::array();
  for (const auto& [light, summary] : tableLines(c.result))
    lights.push_back(lightJson(light, *summary));
  j = {{"value", c.value()},
       {"explanation", c.result.explanation},
       {"model", c.model},
       {"passes", c.passes},
       {"seconds", c.seconds},
       {"run_share", c.run_share},
       {"exact_mse_1spp", c.exact_mse_1spp},
       {"cost_unit", "ns"},
       {"lights", lights}};
}

std::string ceilingMarkdown(const ReportCeiling& c) {
  std::string out =
      fmt::format("\n## Ceiling: {:.3f}× exact\n\n{}\n\n", c.value(), c.result.explanation);
  std::string header = "|", rule = "|";
  for (const char* col : kColumns) {
    header += fmt::format(" {} |", markdownCell(col));
    rule += rule == "|" ? "---|" : "---:|";  // the light's name left, numbers right
  }
  out += header + "\n" + rule + "\n";
  for (const auto& [light, summary] : tableLines(c.result)) {
    out += "|";
    for (const std::string& cell : cells(light, *summary))
      out += fmt::format(" {} |", markdownCell(cell));
    out += "\n";
  }
  return out + "\n" + measuredText(c) + " " + c.model + "\n";
}

std::string ceilingHtml(const ReportCeiling& c) {
  std::string out = fmt::format(
      "<h2>Ceiling: <span class=\"num\">{:.3f}×</span> exact</h2>\n<p>{}</p>\n"
      "<div class=\"scroll\"><table class=\"ceiling\"><tr>",
      c.value(), escapeHtml(c.result.explanation));
  for (const char* col : kColumns) out += "<th>" + escapeHtml(col) + "</th>";
  out += "</tr>\n";
  for (const auto& [light, summary] : tableLines(c.result)) {
    out += "<tr>";
    for (const std::string& cell : cells(light, *summary))
      out += "<td>" + escapeHtml(cell) + "</td>";
    out += "</tr>\n";
  }
  return out + "</table></div>\n<p class=\"desc\">" + escapeHtml(measuredText(c) + " " + c.model) +
         "</p>\n";
}

}  // namespace proxyvis
