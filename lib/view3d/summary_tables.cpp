// The tables above the 3D view, read from the check's JSON summary (the keys view3d_html.h
// lists): verdicts, the four classes, both meshes. A key the summary lacks leaves its row out.
#include "view3d/internal/summary_tables.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>

#include "util/escape_html.h"
#include "view3d/internal/html_text.h"

namespace proxyvis::detail {
namespace {

const nlohmann::json* find(const nlohmann::json& j, const char* key) {
  if (!j.is_object()) return nullptr;
  const auto it = j.find(key);
  return it == j.end() || it->is_null() ? nullptr : &*it;
}

std::string text(const nlohmann::json* j) {
  if (!j) return {};
  if (j->is_string()) return j->get<std::string>();
  return j->dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

double number(const nlohmann::json* j, double fallback = 0) {
  return j && j->is_number() ? j->get<double>() : fallback;
}

// The four classes with their counts and 95 % intervals, when the summary has them.
std::string classTable(const View3dPage& page) {
  const nlohmann::json* counts = find(page.summary, "counts");
  if (!counts) return {};
  const nlohmann::json* intervals = find(page.summary, "intervals");
  struct Row {
    const char *key, *name, *meaning;
  };
  static constexpr Row kRows[] = {{"HH", "HH'", "both block"},
                                  {"HM", "HM'", "original blocks, proxy misses"},
                                  {"MH", "MH'", "original misses, proxy blocks"},
                                  {"MM", "MM'", "both miss"}};
  std::string html =
      "<table class=\"classes\"><thead><tr><th>class</th><th class=\"num\">count</th>"
      "<th class=\"num\">fraction</th><th>95 % interval</th><th>meaning</th></tr></thead><tbody>\n";
  for (const Row& row : kRows) {
    bool breaks = false;
    for (const View3dSegmentLayer& layer : page.layers) {
      std::string id = layer.id;
      std::transform(id.begin(), id.end(), id.begin(),
                     [](unsigned char c) { return char(std::toupper(c)); });
      breaks = breaks || (layer.breaks_claim && id == row.key);
    }
    const nlohmann::json* interval = intervals ? find(*intervals, row.key) : nullptr;
    const uint64_t count = uint64_t(number(find(*counts, row.key)));
    html += fmt::format(
        "<tr{}><td>{}</td><td class=\"num\">{}</td><td class=\"num\">{:.6f}</td>"
        "<td>[{:.6f}, {:.6f}]</td><td>{}{}</td></tr>\n",
        breaks && count > 0 ? " class=\"breaks\"" : "", row.name, withThousands(count),
        number(interval ? find(*interval, "value") : nullptr),
        number(interval ? find(*interval, "lo") : nullptr),
        number(interval ? find(*interval, "hi") : nullptr, 1), row.meaning,
        !breaks      ? std::string()
        : count == 0 ? fmt::format(" &mdash; would break the {} claim", escapeHtml(page.claim))
                     : fmt::format(" &mdash; <span class=\"bad\">breaks the {} claim</span>",
                                   escapeHtml(page.claim)));
  }
  return html + "</tbody></table>\n";
}

// Class, claim and verdicts, each a row when the summary has it.
std::string verdictTable(const View3dPage& page) {
  const nlohmann::json& s = page.summary;
  std::string rows;
  auto row = [&](const std::string& name, const std::string& value_html) {
    rows += fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", name, value_html);
  };
  if (const nlohmann::json* c = find(s, "class")) {
    std::string value = "<strong>" + escapeHtml(text(c)) + "</strong>";
    if (const nlohmann::json* note = find(s, "class_note"))
      value += " &mdash; " + escapeHtml(text(note));
    row("class", value);
  }
  if (!page.claim.empty()) {
    std::string value = "<strong>" + escapeHtml(page.claim) + "</strong>";
    for (const View3dSegmentLayer& layer : page.layers)
      if (layer.breaks_claim)
        value +=
            fmt::format(" &mdash; <span class=\"{}\">{}</span> {} counted, {}",
                        layer.counted == 0 ? "good" : "bad", withThousands(layer.counted),
                        escapeHtml(layer.label),
                        layer.counted == 0 ? "the claim allows none" : "which the claim forbids");
    row("claim", value);
  }
  if (const nlohmann::json* sampled = find(s, "sampled_class")) {
    std::string value = "<strong>" + escapeHtml(text(sampled)) + "</strong>";
    if (const nlohmann::json* bound = find(s, "missed_class_upper_bound"))
      value += fmt::format(" (no {} seen; its rate is below {:.3g} at 95 %)",
                           escapeHtml(text(find(*bound, "class"))), number(find(*bound, "rate")));
    row("sampled class", value);
  }
  if (const nlohmann::json* exact = find(s, "exact")) {
    std::string value = "<strong>" + escapeHtml(text(exact)) + "</strong>";
    if (const nlohmann::json* detail = find(s, "exact_detail"))
      value += ": " + escapeHtml(text(detail));
    row("exact containment", value);
  }
  if (const nlohmann::json* expect = find(s, "expect")) {
    const nlohmann::json* contradiction = find(s, "contradiction");
    row("expected class",
        escapeHtml(text(expect)) +
            (contradiction ? " &mdash; <span class=\"bad\">CONTRADICTED: " +
                                 escapeHtml(text(contradiction)) + "</span>"
                           : std::string(" &mdash; <span class=\"good\">holds</span>")));
  }
  if (const nlohmann::json* mismatch = find(s, "mismatch"))
    row("mismatch", "<span class=\"bad\">MISMATCH: " + escapeHtml(text(mismatch)) + "</span>");
  if (const nlohmann::json* ok = find(s, "ok"); ok && ok->is_boolean())
    row("verdict",
        ok->get<bool>() ? "<span class=\"good\">ok</span>" : "<span class=\"bad\">FAILED</span>");
  return rows.empty() ? std::string() : "<table class=\"verdicts\">\n" + rows + "</table>\n";
}

std::string meshRow(const char* name, const nlohmann::json* m, const TriMesh& mesh) {
  const std::string file = m ? text(find(*m, "file")) : mesh.source;
  std::string closed;
  if (const nlohmann::json* c = m ? find(*m, "closed") : nullptr; c && c->is_boolean())
    closed = c->get<bool>() ? "closed" : "open";
  return fmt::format(
      "<tr><td>{}</td><td class=\"file\">{}</td><td class=\"num\">{}</td>"
      "<td class=\"num\">{}</td><td>{}</td></tr>\n",
      name, escapeHtml(file), withThousands(mesh.numTriangles()), withThousands(mesh.numVertices()),
      closed);
}

}  // namespace

std::string summaryTables(const View3dPage& page) {
  std::string html = verdictTable(page);
  html += classTable(page);
  html +=
      "<table class=\"meshes\"><thead><tr><th>mesh</th><th>file</th>"
      "<th class=\"num\">triangles</th><th class=\"num\">vertices</th><th></th></tr></thead>"
      "<tbody>\n";
  html += meshRow("original", find(page.summary, "original"), *page.original);
  html += meshRow("proxy", find(page.summary, "proxy"), *page.proxy);
  return html + "</tbody></table>\n";
}

}  // namespace proxyvis::detail
