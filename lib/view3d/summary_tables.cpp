// The tables above the 3D view, from the page's View3dCheck: verdicts, the four classes, both
// meshes. An empty text or an unset value leaves its row out.
#include "view3d/internal/summary_tables.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>

#include "util/escape_html.h"
#include "view3d/internal/html_text.h"

namespace proxyvis::detail {
namespace {

// The four classes with their counts and 95 % intervals, when the check has them.
std::string classTable(const View3dPage& page) {
  if (!page.check.classes) return {};
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
  for (size_t i = 0; i < 4; ++i) {
    const Row& row = kRows[i];
    const View3dCheck::ClassRate& rate = (*page.check.classes)[i];
    bool breaks = false;
    for (const View3dSegmentLayer& layer : page.layers) {
      std::string id = layer.id;
      std::transform(id.begin(), id.end(), id.begin(),
                     [](unsigned char c) { return char(std::toupper(c)); });
      breaks = breaks || (layer.breaks_claim && id == row.key);
    }
    const uint64_t count = rate.count;
    html += fmt::format(
        "<tr{}><td>{}</td><td class=\"num\">{}</td><td class=\"num\">{:.6f}</td>"
        "<td>[{:.6f}, {:.6f}]</td><td>{}{}</td></tr>\n",
        breaks && count > 0 ? " class=\"breaks\"" : "", row.name, withThousands(count),
        rate.fraction, rate.lo, rate.hi, row.meaning,
        !breaks      ? std::string()
        : count == 0 ? fmt::format(" &mdash; would break the {} claim", escapeHtml(page.claim))
                     : fmt::format(" &mdash; <span class=\"bad\">breaks the {} claim</span>",
                                   escapeHtml(page.claim)));
  }
  return html + "</tbody></table>\n";
}

// Class, claim and verdicts, each a row when the check has it.
std::string verdictTable(const View3dPage& page) {
  const View3dCheck& c = page.check;
  std::string rows;
  auto row = [&](const std::string& name, const std::string& value_html) {
    rows += fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", name, value_html);
  };
  auto strong = [](const std::string& text) { return "<strong>" + escapeHtml(text) + "</strong>"; };
  if (!c.proven_class.empty())
    row("class", strong(c.proven_class) + (c.proven_class_note.empty()
                                               ? std::string()
                                               : " &mdash; " + escapeHtml(c.proven_class_note)));
  if (!page.claim.empty()) {
    std::string value = strong(page.claim);
    for (const View3dSegmentLayer& layer : page.layers)
      if (layer.breaks_claim)
        value +=
            fmt::format(" &mdash; <span class=\"{}\">{}</span> {} counted, {}",
                        layer.counted == 0 ? "good" : "bad", withThousands(layer.counted),
                        escapeHtml(layer.label),
                        layer.counted == 0 ? "the claim allows none" : "which the claim forbids");
    row("claim", value);
  }
  if (!c.sampled_class.empty()) {
    std::string value = strong(c.sampled_class);
    if (const auto& bound = c.missed_class_bound)
      value += fmt::format(" (no {} seen; its rate is below {:.3g} at 95 %)",
                           escapeHtml(bound->first), bound->second);
    row("sampled class", value);
  }
  if (!c.exact.empty())
    row("exact containment",
        strong(c.exact) +
            (c.exact_detail.empty() ? std::string() : ": " + escapeHtml(c.exact_detail)));
  if (!c.expect.empty())
    row("expected class",
        escapeHtml(c.expect) + (c.contradiction
                                    ? " &mdash; <span class=\"bad\">CONTRADICTED: " +
                                          escapeHtml(*c.contradiction) + "</span>"
                                    : std::string(" &mdash; <span class=\"good\">holds</span>")));
  if (c.mismatch)
    row("mismatch", "<span class=\"bad\">MISMATCH: " + escapeHtml(*c.mismatch) + "</span>");
  if (c.ok)
    row("verdict", *c.ok ? "<span class=\"good\">ok</span>" : "<span class=\"bad\">FAILED</span>");
  return rows.empty() ? std::string() : "<table class=\"verdicts\">\n" + rows + "</table>\n";
}

std::string meshRow(const char* name, const View3dCheck::Mesh& m, const TriMesh& mesh) {
  const std::string file = m.file.empty() ? mesh.source : m.file;
  const std::string closed = !m.closed ? "" : *m.closed ? "closed" : "open";
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
  html += meshRow("original", page.check.original, *page.original);
  html += meshRow("proxy", page.check.proxy, *page.proxy);
  return html + "</tbody></table>\n";
}

}  // namespace proxyvis::detail
