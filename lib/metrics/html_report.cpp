#include "metrics/html_report.h"

#include <fmt/format.h>

#include <algorithm>

#include "metrics/image_error.h"

namespace proxyvis {

namespace {

constexpr const char* kStyle = R"(
body { font-family: system-ui, sans-serif; margin: 24px 32px; color: #222; max-width: 1500px; }
h1 { font-size: 24px; margin-bottom: 4px; } h2 { font-size: 19px; margin-top: 28px;
  border-bottom: 1px solid #ddd; padding-bottom: 4px; }
.meta { color: #444; font-size: 13px; columns: 3; column-gap: 32px; max-width: 1300px;
  margin: 8px 0; } .meta div { break-inside: avoid; padding: 1px 0; } .meta b { color: #777;
  font-weight: normal; display: inline-block; min-width: 190px; }
.notes { font-size: 13px; color: #444; } .notes li.warning { color: #b00020; font-weight: bold; }
table.rows { border-collapse: collapse; font-size: 13px; font-variant-numeric: tabular-nums; }
table.rows th, table.rows td { padding: 4px 10px; border-bottom: 1px solid #e4e4e4; text-align: right; }
table.rows th { background: #f4f4f4; } table.rows td:first-child, table.rows th:first-child { text-align: left; }
td.best { font-weight: bold; color: #0a6b0a; }
.gallery { display: flex; flex-wrap: wrap; gap: 12px; }
figure { margin: 0; width: 178px; text-align: center; font-size: 13px; overflow-wrap: anywhere; }
figure img { display: block; width: 176px; image-rendering: pixelated; border: 1px solid #ccc; }
figcaption b { display: block; } figcaption span { color: #666; font-size: 12px; }
p.desc { color: #555; font-size: 13px; margin-top: 0; }
)";

std::string metaValue(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) return fmt::format("{:.4g}", v.get<double>());
  return v.dump();
}

std::string htmlTable(const std::vector<ReportRow>& rows, std::string_view table) {
  double best = 0;
  for (const ReportRow& r : rows)
    if (r.table == table) best = std::max(best, r.efficiency);
  std::string out =
      "<table class=\"rows\"><tr><th>estimator</th><th>spp</th><th>time (s)</th>"
      "<th>MSE</th><th>± s.e.</th><th>relMSE</th><th>± s.e.</th><th>efficiency vs exact</th>"
      "<th>rays/px proxy</th><th>rays/px original</th><th>rays/px probe</th><th>seeds</th></tr>\n";
  for (const ReportRow& r : rows) {
    if (r.table != table) continue;
    double px = r.pixels > 0 ? r.pixels : 1;
    out += fmt::format(
        "<tr><td>{}</td><td>{:.1f}</td><td>{:.3f}</td><td>{:.3e}</td><td>{:.1e}</td>"
        "<td>{:.3e}</td><td>{:.1e}</td><td{}>{}</td><td>{:.1f}</td><td>{:.1f}</td>"
        "<td>{:.1f}</td><td>{}</td></tr>\n",
        escapeHtml(r.estimator), r.spp, r.seconds, r.mse, r.mse_stderr, r.relmse, r.relmse_stderr,
        r.efficiency == best && best > 0 ? " class=\"best\"" : "",
        r.efficiency > 0 ? fmt::format("{:.2f}×", r.efficiency) : "n/a", r.rays.proxy / px,
        r.rays.original / px, r.rays.probe / px, r.seeds);
  }
  return out + "</table>\n";
}

std::string gallery(const HtmlGallery& g) {
  std::string out = "<h2>" + escapeHtml(g.title) + "</h2>\n";
  if (!g.description.empty()) out += "<p class=\"desc\">" + escapeHtml(g.description) + "</p>\n";
  out += "<div class=\"gallery\">\n";
  for (const HtmlImage& im : g.images)
    out += fmt::format(
        "<figure><img src=\"{}\" alt=\"{}\"><figcaption><b>{}</b><span>{}</span></figcaption>"
        "</figure>\n",
        escapeHtml(im.src), escapeHtml(im.caption), escapeHtml(im.caption), escapeHtml(im.detail));
  return out + "</div>\n";
}

}  // namespace

std::string reportToHtml(const Report& report, const HtmlReportLayout& layout) {
  std::string out = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{0}</title>"
      "<style>{1}</style></head>\n<body>\n<h1>{0}</h1>\n",
      escapeHtml(report.title), kStyle);
  if (report.meta.is_object() && !report.meta.empty()) {
    out += "<div class=\"meta\">\n";
    for (auto it = report.meta.begin(); it != report.meta.end(); ++it)
      out += fmt::format("<div><b>{}</b>{}</div>\n", escapeHtml(it.key()),
                         escapeHtml(metaValue(it.value())));
    out += "</div>\n";
  }
  if (!report.notes.empty()) {
    out += "<ul class=\"notes\">\n";
    for (const std::string& n : report.notes)
      out += (n.rfind("WARNING", 0) == 0 ? "<li class=\"warning\">" : "<li>") + escapeHtml(n) +
             "</li>\n";
    out += "</ul>\n";
  }
  out += fmt::format(
      "<p class=\"desc\">MSE over pixels and RGB in linear radiance; relMSE = "
      "mean((I−I<sub>ref</sub>)²/(I<sub>ref</sub>²+ε)), ε = {:g}; efficiency = 1/(MSE·time) "
      "relative to <code>exact</code> of the same table (bold: best); ± is the standard error "
      "over seeds.</p>\n",
      kRelMseEpsilon);
  for (std::string_view table : {kEqualTimeTable, kEqualSppTable}) {
    bool any = std::any_of(report.rows.begin(), report.rows.end(),
                           [&](const ReportRow& r) { return r.table == table; });
    if (!any) continue;
    out += fmt::format("<h2>{}</h2>\n", table == kEqualTimeTable ? "Equal time" : "Equal samples");
    out += htmlTable(report.rows, table);
  }
  for (const LogLogPlot& plot : layout.plots) out += "<div>" + logLogPlotSvg(plot) + "</div>\n";
  for (const HtmlGallery& g : layout.galleries) out += gallery(g);
  return out + "</body></html>\n";
}

}  // namespace proxyvis
