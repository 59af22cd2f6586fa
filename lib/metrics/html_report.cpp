#include "metrics/html_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <regex>

#include "metrics/efficiency_spread.h"
#include "metrics/image_error.h"
#include "metrics/report_labels.h"
#include "util/escape_html.h"

namespace proxyvis {

namespace {

// Fits an 800 px window: the meta grid drops to fewer columns, tables scroll in their own box,
// plots and images shrink (max-width), long words in text (paths) may break anywhere, and
// numbers (td, .num) never wrap inside.
constexpr const char* kStyle = R"(
body { font-family: system-ui, sans-serif; margin: 20px; color: #222; max-width: 1500px; }
h1 { font-size: 24px; margin: 0 0 2px; } p.sub { color: #666; margin: 0 0 10px; font-size: 14px; }
h2 { font-size: 19px; margin-top: 28px; border-bottom: 1px solid #ddd; padding-bottom: 4px; }
h3 { font-size: 15px; margin: 14px 0 6px; }
.meta { color: #444; font-size: 13px; columns: 3 240px; column-gap: 28px; margin: 8px 0; }
.meta div { break-inside: avoid; padding: 1px 0; overflow-wrap: anywhere; }
.meta b { color: #777; font-weight: normal; display: block; font-size: 12px; }
.notes { font-size: 13px; color: #444; padding-left: 20px; }
h1, .notes, p.desc, figcaption, ul.files { overflow-wrap: anywhere; }
.notes li.warning { color: #b00020; font-weight: bold; }
.num, td { white-space: nowrap; }
.scroll { overflow-x: auto; max-width: 100%; }
table { border-collapse: collapse; font-size: 13px; font-variant-numeric: tabular-nums; }
table th, table td { padding: 4px 10px; border-bottom: 1px solid #e4e4e4; text-align: right; }
table th { background: #f4f4f4; vertical-align: bottom; }
table td:first-child, table th:first-child { text-align: left; }
table.meta-table td, table.meta-table th { white-space: normal; text-align: left; }
td.best { font-weight: bold; color: #0a6b0a; }
svg.plot { max-width: 100%; height: auto; }
.gallery { display: flex; flex-wrap: wrap; gap: 12px; }
figure { margin: 0; width: 178px; max-width: 100%; text-align: center; font-size: 13px; }
figure > img { display: block; width: 176px; max-width: 100%; image-rendering: pixelated;
  border: 1px solid #ccc; }
figcaption b { display: block; } figcaption span { color: #666; font-size: 12px; }
figcaption .links { display: block; font-size: 12px; }
.cbar { margin-top: 3px; font-size: 11px; color: #444; }
.cbar img { display: block; width: 176px; max-width: 100%; height: 10px; border: 1px solid #ccc; }
.cbar .ends { display: flex; justify-content: space-between; }
p.desc { color: #555; font-size: 13px; margin-top: 0; }
ul.files { font-size: 13px; padding-left: 20px; } ul.files li { margin: 2px 0; }
a { color: #0b5cad; }
)";

// `text` escaped, with every number token in a no-wrap span: "1.2e-05" must not break at its
// minus sign. Tokens are found in the raw text, so entities made by escaping are never split.
std::string htmlWithNumbers(const std::string& text) {
  static const std::regex kNumber(R"([-+]?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?%?)");
  std::string out;
  size_t done = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), kNumber);
       it != std::sregex_iterator(); ++it) {
    out += escapeHtml(text.substr(done, size_t(it->position()) - done));
    out += "<span class=\"num\">" + escapeHtml(it->str()) + "</span>";
    done = size_t(it->position() + it->length());
  }
  return out + escapeHtml(text.substr(done));
}

// `detail` split at " · ": each part stays on one line, the line may wrap between parts.
std::string detailHtml(const std::string& detail) {
  std::string out;
  size_t start = 0;
  while (start <= detail.size()) {
    size_t end = detail.find(" · ", start);
    std::string part = detail.substr(start, end == std::string::npos ? end : end - start);
    out += (out.empty() ? "" : " · ") + ("<span class=\"num\">" + escapeHtml(part) + "</span>");
    if (end == std::string::npos) break;
    start = end + std::string(" · ").size();
  }
  return out;
}

std::string linkHtml(const HtmlLink& link) {
  return fmt::format("<a href=\"{}\">{}</a>", escapeHtml(link.href), escapeHtml(link.text));
}

bool isWrittenFile(const HtmlReportLayout& layout, const std::string& name) {
  for (const HtmlFileGroup& g : layout.files)
    for (const HtmlLink& l : g.links)
      if (l.href == name) return true;
  return false;
}

std::string metaValueHtml(const nlohmann::json& v, const HtmlReportLayout& layout) {
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    return isWrittenFile(layout, s) ? linkHtml({s, s}) : htmlWithNumbers(s);
  }
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (v.is_number_float())
    return "<span class=\"num\">" + fmt::format("{:.4g}", v.get<double>()) + "</span>";
  if (v.is_number()) return "<span class=\"num\">" + v.dump() + "</span>";
  if (v.is_array()) {
    if (v.empty()) return "none";
    std::string out;
    for (const auto& e : v) out += (out.empty() ? "" : ", ") + metaValueHtml(e, layout);
    return out;
  }
  return escapeHtml(v.dump());
}

bool isArrayOfObjects(const nlohmann::json& v) {
  return v.is_array() && !v.empty() &&
         std::all_of(v.begin(), v.end(), [](const nlohmann::json& e) { return e.is_object(); });
}

// A list of records (e.g. the proxies and their classes) as a table: mesh and proxy first, then
// the other keys.
std::string metaTable(const std::string& key, const nlohmann::json& list,
                      const HtmlReportLayout& layout) {
  std::vector<std::string> columns;
  for (const auto& e : list)
    for (auto it = e.begin(); it != e.end(); ++it)
      if (std::find(columns.begin(), columns.end(), it.key()) == columns.end())
        columns.push_back(it.key());
  // JSON objects come sorted by key; what a record is about reads best first.
  for (const char* first : {"proxy", "mesh"}) {
    auto it = std::find(columns.begin(), columns.end(), first);
    if (it != columns.end()) std::rotate(columns.begin(), it, it + 1);
  }
  std::string out = "<h3>" + escapeHtml(reportLabel(key)) +
                    "</h3>\n<div class=\"scroll\"><table class=\"meta-table\"><tr>";
  for (const std::string& c : columns) out += "<th>" + escapeHtml(reportLabel(c)) + "</th>";
  out += "</tr>\n";
  for (const auto& e : list) {
    out += "<tr>";
    for (const std::string& c : columns)
      out += "<td>" + (e.contains(c) ? metaValueHtml(e.at(c), layout) : std::string()) + "</td>";
    out += "</tr>\n";
  }
  return out + "</table></div>\n";
}

std::string metaHtml(const nlohmann::json& meta, const HtmlReportLayout& layout) {
  if (!meta.is_object() || meta.empty()) return {};
  std::string grid, tables;
  for (auto it = meta.begin(); it != meta.end(); ++it) {
    if (isArrayOfObjects(it.value())) {
      tables += metaTable(it.key(), it.value(), layout);
      continue;
    }
    grid += fmt::format("<div><b>{}</b>{}</div>\n", escapeHtml(reportLabel(it.key())),
                        metaValueHtml(it.value(), layout));
  }
  return "<div class=\"meta\">\n" + grid + "</div>\n" + tables;
}

std::string htmlTable(const std::vector<ReportRow>& rows, std::string_view table) {
  double best = 0;
  for (const ReportRow& r : rows)
    if (r.table == table) best = std::max(best, r.efficiency);
  std::string out =
      "<div class=\"scroll\"><table class=\"rows\"><tr><th>estimator</th><th>samples per "
      "pixel</th><th>time (s)</th><th>MSE</th><th>± s.e.</th><th>relMSE</th><th>± s.e.</th>"
      "<th>efficiency vs exact</th><th>of ceiling</th><th>rays/px proxy</th>"
      "<th>rays/px original</th><th>rays/px probe</th><th>seeds</th></tr>\n";
  for (const ReportRow& r : rows) {
    if (r.table != table) continue;
    double px = r.pixels > 0 ? r.pixels : 1;
    out += fmt::format(
        "<tr><td>{}</td><td>{:.1f}</td><td>{:.3f}</td><td>{:.3e}</td><td>{:.1e}</td>"
        "<td>{:.3e}</td><td>{:.1e}</td><td{}>{}</td><td>{}</td><td>{:.1f}</td><td>{:.1f}</td>"
        "<td>{:.1f}</td><td>{}</td></tr>\n",
        escapeHtml(r.estimator), r.spp, r.seconds, r.mse, r.mse_stderr, r.relmse, r.relmse_stderr,
        r.efficiency == best && best > 0 ? " class=\"best\"" : "", efficiencyText(r),
        ofCeilingText(r), r.rays.proxy / px, r.rays.original / px, r.rays.probe / px, r.seeds);
  }
  return out + "</table></div>\n";
}

std::string colorBarHtml(const HtmlColorBar& bar) {
  std::string scale = bar.range.log_scale ? "log scale" : "linear scale";
  return fmt::format(
      "<div class=\"cbar\"><img src=\"{0}\" alt=\"colour scale from {1:.1e} to {2:.1e} {3}\">"
      "<div class=\"ends\"><span class=\"num\">{1:.1e}</span><span class=\"num\">{2:.1e}</span>"
      "</div><div>{3}, {4}</div></div>",
      escapeHtml(bar.src), bar.range.lo, bar.range.hi, escapeHtml(bar.unit), scale);
}

std::string gallery(const HtmlGallery& g) {
  std::string out = "<h2>" + escapeHtml(g.title) + "</h2>\n";
  if (!g.description.empty())
    out += "<p class=\"desc\">" + htmlWithNumbers(g.description) + "</p>\n";
  out += "<div class=\"gallery\">\n";
  for (const HtmlImage& im : g.images) {
    std::string links;
    for (const HtmlLink& l : im.links) links += (links.empty() ? "" : " · ") + linkHtml(l);
    out += fmt::format(
        "<figure><img src=\"{}\" alt=\"{}\">{}<figcaption><b>{}</b><span>{}</span>{}"
        "</figcaption></figure>\n",
        escapeHtml(im.src), escapeHtml(im.caption),
        g.color_bar ? colorBarHtml(*g.color_bar) : std::string(), escapeHtml(im.caption),
        detailHtml(im.detail),
        links.empty() ? std::string() : "<span class=\"links\">" + links + "</span>");
  }
  return out + "</div>\n";
}

std::string filesHtml(const std::vector<HtmlFileGroup>& files) {
  if (files.empty()) return {};
  std::string out = "<h2>Files of this run</h2>\n<ul class=\"files\">\n";
  for (const HtmlFileGroup& g : files) {
    std::string links;
    for (const HtmlLink& l : g.links) links += (links.empty() ? "" : " · ") + linkHtml(l);
    out += "<li>" + escapeHtml(g.label) + ": " + links + "</li>\n";
  }
  return out + "</ul>\n";
}

}  // namespace

std::string reportToHtml(const Report& report, const HtmlReportLayout& layout) {
  const bool named = !report.scene_name.empty();
  const std::string heading = named ? report.scene_name : report.title;
  std::string out = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
      "<title>{}</title><style>{}</style></head>\n<body>\n<h1>{}</h1>\n",
      escapeHtml(named ? heading + " · render-compare" : heading), kStyle, escapeHtml(heading));
  if (named && !report.title.empty())
    out += "<p class=\"sub\">" + escapeHtml(report.title) + "</p>\n";
  out += metaHtml(report.meta, layout);
  if (!report.notes.empty()) {
    out += "<ul class=\"notes\">\n";
    for (const std::string& n : report.notes)
      out += (n.rfind("WARNING", 0) == 0 ? "<li class=\"warning\">" : "<li>") + htmlWithNumbers(n) +
             "</li>\n";
    out += "</ul>\n";
  }
  out += fmt::format(
      "<p class=\"desc\">MSE over pixels and RGB in linear radiance; relMSE = "
      "mean((I−I<sub>ref</sub>)²/(I<sub>ref</sub>²+ε)), ε = <span class=\"num\">{:g}</span>; "
      "efficiency = 1/(MSE·time) relative to <code>exact</code> of the same table (bold: best), "
      "[lowest–highest, s.e.] of the same ratio run by run against exact's run with the same "
      "seed; ± is the standard error over seeds.</p>\n",
      kRelMseEpsilon);
  for (std::string_view table : {kEqualTimeTable, kEqualSppTable}) {
    bool any = std::any_of(report.rows.begin(), report.rows.end(),
                           [&](const ReportRow& r) { return r.table == table; });
    if (!any) continue;
    out += fmt::format("<h2>{}</h2>\n", table == kEqualTimeTable ? "Equal time" : "Equal samples");
    out += htmlTable(report.rows, table);
  }
  if (report.ceiling) out += ceilingHtml(*report.ceiling);
  for (const LogLogPlot& plot : layout.plots) out += "<div>" + logLogPlotSvg(plot) + "</div>\n";
  for (const HtmlGallery& g : layout.galleries) out += gallery(g);
  out += filesHtml(layout.files);
  return out + "</body></html>\n";
}

}  // namespace proxyvis
