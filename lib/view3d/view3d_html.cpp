#include "view3d/view3d_html.h"

#include <fmt/core.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include "util/error.h"
#include "view3d/internal/view3d_assets.h"
#include "view3d/view_decimate.h"

namespace proxyvis {

static_assert(std::endian::native == std::endian::little,
              "the page reads positions and indices as little-endian typed arrays");

namespace detail {

std::string base64(const void* data, size_t bytes) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* p = static_cast<const unsigned char*>(data);
  std::string out;
  out.reserve((bytes + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 3 <= bytes; i += 3) {
    const uint32_t v = uint32_t(p[i]) << 16 | uint32_t(p[i + 1]) << 8 | p[i + 2];
    for (int shift : {18, 12, 6, 0}) out += kDigits[(v >> shift) & 63];
  }
  if (i + 1 == bytes) {
    const uint32_t v = uint32_t(p[i]) << 16;
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == bytes) {
    const uint32_t v = uint32_t(p[i]) << 16 | uint32_t(p[i + 1]) << 8;
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += kDigits[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

std::string escapeHtml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    const char* entity = c == '&'    ? "&amp;"
                         : c == '<'  ? "&lt;"
                         : c == '>'  ? "&gt;"
                         : c == '"'  ? "&quot;"
                         : c == '\'' ? "&#39;"
                                     : nullptr;
    if (entity)
      out += entity;
    else
      out += c;
  }
  return out;
}

std::string jsonForScript(const nlohmann::json& json) {
  // Invalid UTF-8 (a file name) becomes U+FFFD instead of an exception.
  const std::string text = json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == '<')
      out += "\\u003c";  // only inside strings: "</script>" or "<!--" cannot end the element
    else
      out += c;
  }
  return out;
}

}  // namespace detail

namespace {

using detail::escapeHtml;

// An embedded file, checked to be one that can sit inside a <script> or <style> element.
std::string_view asset(std::string_view name) {
  const std::string_view bytes = detail::view3dAsset(name);
  if (bytes.empty()) throw std::logic_error(fmt::format("view3d: {} was not embedded", name));
  if (bytes.find("</") != std::string_view::npos && name.ends_with(".css"))
    throw std::logic_error(fmt::format("view3d: {} holds '</'", name));
  if (bytes.find("</script") != std::string_view::npos)
    throw std::logic_error(fmt::format("view3d: {} holds '</script'", name));
  return bytes;
}

// three.module.min.js imports "./three.core.min.js", which a data: URL cannot resolve: the
// import map provides it under a bare name.
constexpr std::string_view kCoreSpecifier = "three/core";

std::string dataUrl(std::string_view script) {
  return "data:text/javascript;base64," + detail::base64(script.data(), script.size());
}

// The import map that gives the page's module its three.js without any request.
const std::string& importMap() {
  static const std::string text = [] {
    std::string module(asset("three.module.min.js"));
    const std::string relative = "\"./three.core.min.js\"";
    const std::string bare = fmt::format("\"{}\"", kCoreSpecifier);
    size_t replaced = 0;
    for (size_t at = module.find(relative); at != std::string::npos;
         at = module.find(relative, at + bare.size())) {
      module.replace(at, relative.size(), bare);
      ++replaced;
    }
    if (replaced == 0)
      throw std::logic_error("view3d: three.module.min.js no longer imports ./three.core.min.js");
    const nlohmann::json map = {
        {"imports",
         {{"three", dataUrl(module)},
          {std::string(kCoreSpecifier), dataUrl(asset("three.core.min.js"))},
          {"three/addons/controls/OrbitControls.js", dataUrl(asset("OrbitControls.js"))}}}};
    return detail::jsonForScript(map);
  }();
  return text;
}

std::string withThousands(uint64_t n) {
  std::string digits = std::to_string(n), out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

// The part of segment (a, b) inside `box` (Liang-Barsky), or false when it misses the box.
bool clipToBox(Vec3d& a, Vec3d& b, const Bounds3d& box) {
  double t0 = 0, t1 = 1;
  const Vec3d d = b - a;
  for (int axis = 0; axis < 3; ++axis) {
    if (d[axis] == 0) {
      if (a[axis] < box.lo[axis] || a[axis] > box.hi[axis]) return false;
      continue;
    }
    double near = (box.lo[axis] - a[axis]) / d[axis], far = (box.hi[axis] - a[axis]) / d[axis];
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
    if (t0 > t1) return false;
  }
  const Vec3d start = a + d * t0;
  b = a + d * t1;
  a = start;
  return true;
}

template <typename T>
std::string base64Of(const std::vector<T>& values) {
  return detail::base64(values.data(), values.size() * sizeof(T));
}

// Positions relative to `center` (float32 x, y, z) and indices (uint32), base64.
nlohmann::json meshData(const TriMesh& mesh, const Vec3d& center, uint64_t source_triangles) {
  std::vector<float> positions;
  positions.reserve(mesh.vertices.size() * 3);
  for (const Vec3f& v : mesh.vertices)
    for (int a = 0; a < 3; ++a) positions.push_back(float(double(v[a]) - center[a]));
  std::vector<uint32_t> indices;
  indices.reserve(mesh.triangles.size() * 3);
  for (const Triangle& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());
  return {{"positions", base64Of(positions)},
          {"indices", base64Of(indices)},
          {"triangles", mesh.numTriangles()},
          {"source_triangles", source_triangles}};
}

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

// One checkbox of the layer list. `breaks`: the layer's class breaks the claim (listed in red
// unless `none` of it was counted).
std::string layerControl(const std::string& id, const std::string& color, bool checked, bool breaks,
                         bool none, const std::string& label_html, const std::string& detail_html,
                         const std::string& data_attributes) {
  return fmt::format(
      "<label class=\"layer{}{}\" data-layer=\"{}\"{}><input type=\"checkbox\" "
      "id=\"layer-{}\"{}> <span class=\"swatch\" style=\"background:{}\"></span>{}"
      "<span class=\"detail\">{}</span></label>\n",
      breaks ? " breaks" : "", none ? " none" : "", escapeHtml(id), data_attributes, escapeHtml(id),
      checked ? " checked" : "", escapeHtml(color), label_html, detail_html);
}

bool validColor(const std::string& c) {
  return c.size() == 7 && c[0] == '#' &&
         std::all_of(c.begin() + 1, c.end(), [](unsigned char x) { return std::isxdigit(x); });
}

bool validId(const std::string& id) {
  return !id.empty() && id != "original" && id != "proxy" &&
         std::all_of(id.begin(), id.end(),
                     [](unsigned char x) { return std::isalnum(x) || x == '-' || x == '_'; });
}

}  // namespace

std::string view3dHtml(const View3dPage& page, const View3dLimits& limits) {
  if (!page.original || !page.proxy) throw std::invalid_argument("view3dHtml: a mesh is missing");
  if (page.original->empty()) throw Error(page.original->source, "the mesh has no triangles");
  if (page.proxy->empty()) throw Error(page.proxy->source, "the mesh has no triangles");
  for (const View3dSegmentLayer& layer : page.layers)
    if (!validId(layer.id) || !validColor(layer.color))
      throw std::invalid_argument("view3dHtml: bad layer id or colour: " + layer.id);

  const TriMesh& original = *page.original;
  const TriMesh& proxy = *page.proxy;
  const ViewMesh shown =
      decimateForView(original, std::max<size_t>(limits.max_original_triangles, 1));
  const TriMesh& original_shown = shown.grid ? shown.mesh : original;

  Bounds3f box = original.bounds();
  box.extend(proxy.bounds());
  const Vec3d center = (Vec3d(box.lo) + Vec3d(box.hi)) * 0.5;
  const double radius = 0.5 * length(Vec3d(box.hi) - Vec3d(box.lo));

  std::vector<std::string> notes;
  if (shown.grid)
    notes.push_back(fmt::format(
        "The original has {} triangles, more than the page embeds ({}): the view shows a copy "
        "decimated by vertex clustering on a grid of {} cells along its longest side, with {} "
        "triangles. The check used every triangle.",
        withThousands(original.numTriangles()), withThousands(limits.max_original_triangles),
        shown.grid, withThousands(original_shown.numTriangles())));

  nlohmann::json data = {{"center", {center.x, center.y, center.z}},
                         {"radius", radius},
                         {"original", meshData(original_shown, center, original.numTriangles())},
                         {"proxy", meshData(proxy, center, proxy.numTriangles())},
                         {"layers", nlohmann::json::array()}};

  // Layer controls: the meshes, then the segment layers that break the claim first.
  std::string controls;
  controls += layerControl(
      "original", "#c9b48f", true, false, false, "original",
      fmt::format("{} triangles{}", withThousands(original.numTriangles()),
                  shown.grid ? fmt::format(", {} shown (decimated)",
                                           withThousands(original_shown.numTriangles()))
                             : std::string()),
      fmt::format(" data-triangles=\"{}\" data-shown=\"{}\"", original.numTriangles(),
                  original_shown.numTriangles()));
  controls += layerControl("proxy", "#14948b", true, false, false, "proxy",
                           fmt::format("{} triangles", withThousands(proxy.numTriangles())),
                           fmt::format(" data-triangles=\"{}\" data-shown=\"{}\"",
                                       proxy.numTriangles(), proxy.numTriangles()));
  std::vector<const View3dSegmentLayer*> order;
  for (const View3dSegmentLayer& layer : page.layers) order.push_back(&layer);
  std::stable_sort(order.begin(), order.end(), [](const auto* a, const auto* b) {
    return a->breaks_claim && !b->breaks_claim;
  });
  // Segments are drawn inside the box of both meshes, enlarged by 5 % of its diagonal: what
  // happens away from the meshes says nothing, and whole segments would hide the meshes.
  Bounds3d clip_box{Vec3d(box.lo) - Vec3d(1, 1, 1) * (0.1 * radius),
                    Vec3d(box.hi) + Vec3d(1, 1, 1) * (0.1 * radius)};
  bool any_segments = false;
  for (const View3dSegmentLayer* layer : order) {
    const size_t drawn = std::min(layer->segments.size(), limits.max_segments_per_layer);
    std::vector<float> positions;
    positions.reserve(drawn * 6);
    for (size_t i = 0; i < drawn; ++i) {
      Vec3d a(layer->segments[i].first), b(layer->segments[i].second);
      if (!clipToBox(a, b, clip_box)) a = b = (a + b) * 0.5;  // kept (counted), zero length
      for (const Vec3d& p : {a, b})
        for (int axis = 0; axis < 3; ++axis) positions.push_back(float(p[axis] - center[axis]));
    }
    any_segments = any_segments || drawn > 0;
    data["layers"].push_back({{"id", layer->id},
                              {"color", layer->color},
                              {"counted", layer->counted},
                              {"drawn", drawn},
                              {"positions", base64Of(positions)}});
    std::string detail =
        fmt::format("{} counted, {} drawn", withThousands(layer->counted), withThousands(drawn));
    if (!layer->meaning.empty()) detail += ": " + escapeHtml(layer->meaning);
    if (layer->breaks_claim)
      detail += fmt::format("; {} the {} claim", layer->counted ? "they break" : "would break",
                            escapeHtml(page.claim));
    controls +=
        layerControl(layer->id, layer->color, layer->visible, layer->breaks_claim,
                     layer->breaks_claim && layer->counted == 0, escapeHtml(layer->label), detail,
                     fmt::format(" data-counted=\"{}\" data-drawn=\"{}\"", layer->counted, drawn));
    if (drawn < layer->counted)
      notes.push_back(fmt::format(
          "{}: {} of the {} counted are drawn (the first ones in sampling order, a uniform "
          "sample of them).",
          escapeHtml(layer->label), withThousands(drawn), withThousands(layer->counted)));
  }

  if (any_segments)
    notes.push_back(
        "Segments are drawn clipped to the box around both meshes (enlarged by 5 % of its "
        "diagonal on every side).");
  // Large proxies start without their wireframe (many lines to build and draw).
  const bool wire = proxy.numTriangles() <= 200'000;
  std::string html;
  html.reserve(4'000'000);
  html += fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>{}</title>\n<style>\n{}</style>\n<script type=\"importmap\">{}</script>\n</head>\n",
      escapeHtml(page.title), asset("view3d.css"), importMap());
  html += fmt::format("<body>\n<h1>{}</h1>\n", escapeHtml(page.title));
  html += "<section class=\"tables\">\n";
  html += verdictTable(page);
  html += classTable(page);
  html +=
      "<table class=\"meshes\"><thead><tr><th>mesh</th><th>file</th>"
      "<th class=\"num\">triangles</th><th class=\"num\">vertices</th><th></th></tr></thead>"
      "<tbody>\n";
  html += meshRow("original", find(page.summary, "original"), original);
  html += meshRow("proxy", find(page.summary, "proxy"), proxy);
  html += "</tbody></table>\n</section>\n";

  html +=
      "<h2>3D view</h2>\n<section class=\"view\">\n<div class=\"controls\">\n"
      "<fieldset><legend>Layers</legend>\n";
  html += controls;
  html += fmt::format(
      "</fieldset>\n<label>proxy drawn <select id=\"proxy-style\">"
      "<option value=\"translucent\"{}>translucent</option>"
      "<option value=\"wireframe\">as a wireframe</option>"
      "<option value=\"both\"{}>translucent with its edges</option></select></label>\n"
      "<p><button type=\"button\" id=\"reset-view\">Reset view</button></p>\n"
      "<p class=\"hint\">Drag to rotate, right-drag to pan, wheel to zoom.</p>\n</div>\n",
      wire ? "" : " selected", wire ? " selected" : "");
  html +=
      "<div class=\"viewport\" id=\"viewport\"><p id=\"view3d-status\">Loading the 3D "
      "view&hellip;</p><noscript><p>The 3D view needs JavaScript.</p></noscript></div>\n"
      "</section>\n";
  if (!notes.empty()) {
    html += "<ul class=\"notes\">\n";
    for (const std::string& note : notes) html += "<li>" + note + "</li>\n";
    html += "</ul>\n";
  }
  html += "<details><summary>JSON summary</summary><pre>" +
          escapeHtml(page.summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace)) +
          "</pre></details>\n";
  html += "<details><summary>three.js license</summary><pre>" +
          escapeHtml(std::string(asset("LICENSE"))) + "</pre></details>\n";
  html +=
      "<footer>The 3D view is drawn by three.js (MIT license, above), embedded in this page with "
      "the meshes: it loads nothing from the network.</footer>\n";
  html += "<script type=\"application/json\" id=\"pv-view3d-data\">" + detail::jsonForScript(data) +
          "</script>\n";
  html +=
      fmt::format("<script type=\"module\">\n{}</script>\n</body>\n</html>\n", asset("view3d.js"));
  return html;
}

}  // namespace proxyvis
