#include "view3d/view3d_html.h"

#include <fmt/core.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include "util/error.h"
#include "util/escape_html.h"
#include "view3d/internal/html_text.h"
#include "view3d/internal/summary_tables.h"
#include "view3d/internal/view3d_assets.h"
#include "view3d/view_decimate.h"

namespace proxyvis {

static_assert(std::endian::native == std::endian::little,
              "the page reads positions and indices as little-endian typed arrays");

namespace {

using detail::withThousands;

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

void checkPage(const View3dPage& page) {
  if (!page.original || !page.proxy) throw std::invalid_argument("view3dHtml: a mesh is missing");
  if (page.original->empty()) throw Error(page.original->source, "the mesh has no triangles");
  if (page.proxy->empty()) throw Error(page.proxy->source, "the mesh has no triangles");
  for (const View3dSegmentLayer& layer : page.layers)
    if (!validId(layer.id) || !validColor(layer.color))
      throw std::invalid_argument("view3dHtml: bad layer id or colour: " + layer.id);
}

// What the page's parts are built into: the embedded data (meshes, then segment layers), the
// layer list's checkboxes and the notes under the view.
struct PageContent {
  nlohmann::json data;
  std::string controls;
  std::vector<std::string> notes;
};

// The two meshes' data and checkboxes, the original decimated when it has too many triangles.
PageContent meshContent(const View3dPage& page, const View3dLimits& limits, const Vec3d& center,
                        double radius) {
  const TriMesh& original = *page.original;
  const TriMesh& proxy = *page.proxy;
  const ViewMesh shown =
      decimateForView(original, std::max<size_t>(limits.max_original_triangles, 1));
  const TriMesh& original_shown = shown.grid ? shown.mesh : original;
  PageContent content;
  if (shown.grid)
    content.notes.push_back(fmt::format(
        "The original has {} triangles, more than the page embeds ({}): the view shows a copy "
        "decimated by vertex clustering on a grid of {} cells along its longest side, with {} "
        "triangles. The check used every triangle.",
        withThousands(original.numTriangles()), withThousands(limits.max_original_triangles),
        shown.grid, withThousands(original_shown.numTriangles())));
  content.data = {{"center", {center.x, center.y, center.z}},
                  {"radius", radius},
                  {"original", meshData(original_shown, center, original.numTriangles())},
                  {"proxy", meshData(proxy, center, proxy.numTriangles())},
                  {"layers", nlohmann::json::array()}};
  content.controls += layerControl(
      "original", "#c9b48f", true, false, false, "original",
      fmt::format("{} triangles{}", withThousands(original.numTriangles()),
                  shown.grid ? fmt::format(", {} shown (decimated)",
                                           withThousands(original_shown.numTriangles()))
                             : std::string()),
      fmt::format(" data-triangles=\"{}\" data-shown=\"{}\"", original.numTriangles(),
                  original_shown.numTriangles()));
  content.controls += layerControl("proxy", "#14948b", true, false, false, "proxy",
                                   fmt::format("{} triangles", withThousands(proxy.numTriangles())),
                                   fmt::format(" data-triangles=\"{}\" data-shown=\"{}\"",
                                               proxy.numTriangles(), proxy.numTriangles()));
  return content;
}

// One segment layer's data, checkbox and note (when not all of it is drawn); returns how many
// segments it draws. Segments are clipped to `clip_box`; one that misses it is kept (it is
// counted) as a point.
size_t addSegmentLayer(const View3dSegmentLayer& layer, const std::string& claim,
                       size_t max_segments, const Bounds3d& clip_box, const Vec3d& center,
                       PageContent& content) {
  const size_t drawn = std::min(layer.segments.size(), max_segments);
  std::vector<float> positions;
  positions.reserve(drawn * 6);
  for (size_t i = 0; i < drawn; ++i) {
    Vec3d a(layer.segments[i].first), b(layer.segments[i].second);
    if (!clipToBox(a, b, clip_box)) a = b = (a + b) * 0.5;  // kept (counted), zero length
    for (const Vec3d& p : {a, b})
      for (int axis = 0; axis < 3; ++axis) positions.push_back(float(p[axis] - center[axis]));
  }
  content.data["layers"].push_back({{"id", layer.id},
                                    {"color", layer.color},
                                    {"counted", layer.counted},
                                    {"drawn", drawn},
                                    {"positions", base64Of(positions)}});
  std::string detail =
      fmt::format("{} counted, {} drawn", withThousands(layer.counted), withThousands(drawn));
  if (!layer.meaning.empty()) detail += ": " + escapeHtml(layer.meaning);
  if (layer.breaks_claim)
    detail += fmt::format("; {} the {} claim", layer.counted ? "they break" : "would break",
                          escapeHtml(claim));
  content.controls +=
      layerControl(layer.id, layer.color, layer.visible, layer.breaks_claim,
                   layer.breaks_claim && layer.counted == 0, escapeHtml(layer.label), detail,
                   fmt::format(" data-counted=\"{}\" data-drawn=\"{}\"", layer.counted, drawn));
  if (drawn < layer.counted)
    content.notes.push_back(fmt::format(
        "{}: {} of the {} counted are drawn (the first ones in sampling order, a uniform "
        "sample of them).",
        escapeHtml(layer.label), withThousands(drawn), withThousands(layer.counted)));
  return drawn;
}

// The 3D view's section: the layer list, the proxy's drawing style and the viewport.
std::string viewSection(const std::string& controls, bool wireframe) {
  std::string html =
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
      wireframe ? "" : " selected", wireframe ? " selected" : "");
  html +=
      "<div class=\"viewport\" id=\"viewport\"><p id=\"view3d-status\">Loading the 3D "
      "view&hellip;</p><noscript><p>The 3D view needs JavaScript.</p></noscript></div>\n"
      "</section>\n";
  return html;
}

// The whole page around the content: head with style and import map, tables, view, notes,
// the JSON summary, three.js's license, the data and the page's script.
std::string pageHtml(const View3dPage& page, const PageContent& content) {
  // Large proxies start without their wireframe (many lines to build and draw).
  const bool wire = page.proxy->numTriangles() <= 200'000;
  std::string html;
  html.reserve(4'000'000);
  html += fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>{}</title>\n<style>\n{}</style>\n<script type=\"importmap\">{}</script>\n</head>\n",
      escapeHtml(page.title), asset("view3d.css"), importMap());
  html += fmt::format("<body>\n<h1>{}</h1>\n", escapeHtml(page.title));
  html += "<section class=\"tables\">\n" + detail::summaryTables(page) + "</section>\n";
  html += viewSection(content.controls, wire);
  if (!content.notes.empty()) {
    html += "<ul class=\"notes\">\n";
    for (const std::string& note : content.notes) html += "<li>" + note + "</li>\n";
    html += "</ul>\n";
  }
  html += "<details><summary>JSON summary</summary><pre>" +
          escapeHtml(page.json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace)) +
          "</pre></details>\n";
  html += "<details><summary>three.js license</summary><pre>" +
          escapeHtml(std::string(asset("LICENSE"))) + "</pre></details>\n";
  html +=
      "<footer>The 3D view is drawn by three.js (MIT license, above), embedded in this page with "
      "the meshes: it loads nothing from the network.</footer>\n";
  html += "<script type=\"application/json\" id=\"pv-view3d-data\">" +
          detail::jsonForScript(content.data) + "</script>\n";
  html +=
      fmt::format("<script type=\"module\">\n{}</script>\n</body>\n</html>\n", asset("view3d.js"));
  return html;
}

}  // namespace

std::string view3dHtml(const View3dPage& page, const View3dLimits& limits) {
  checkPage(page);
  Bounds3f box = page.original->bounds();
  box.extend(page.proxy->bounds());
  const Vec3d center = (Vec3d(box.lo) + Vec3d(box.hi)) * 0.5;
  const double radius = 0.5 * length(Vec3d(box.hi) - Vec3d(box.lo));
  PageContent content = meshContent(page, limits, center, radius);

  // Segment layers, those that break the claim first.
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
    const size_t drawn = addSegmentLayer(*layer, page.claim, limits.max_segments_per_layer,
                                         clip_box, center, content);
    any_segments = any_segments || drawn > 0;
  }
  if (any_segments)
    content.notes.push_back(
        "Segments are drawn clipped to the box around both meshes (enlarged by 5 % of its "
        "diagonal on every side).");
  return pageHtml(page, content);
}

}  // namespace proxyvis
