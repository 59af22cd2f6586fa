#pragma once
// A self-contained HTML page with an interactive 3D view of an original mesh, its proxy and
// classified segments, above a summary of the check that produced them (docs/report_3d.md).
// three.js (vendored in lib/view3d/vendor/, MIT) and the mesh data are embedded in the page, so
// it works from a file with the network off. Used by proxy-check --html.
#include <array>
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mesh/tri_mesh.h"
#include "util/vec3.h"

namespace proxyvis {

// Segments of one class, drawn as lines of one colour under a checkbox of their own.
struct View3dSegmentLayer {
  std::string id;        // "hm": names the checkbox (layer-hm) and the page's data
  std::string label;     // "HM' segments"
  std::string meaning;   // "original blocks, proxy misses"
  std::string color;     // CSS hex colour, "#d62728"
  uint64_t counted = 0;  // how many the check counted (the page draws at most a cap of them)
  // They break the class the page is about (HM' for an outside claim): highlighted, shown first.
  bool breaks_claim = false;
  bool visible = true;                            // the checkbox's initial state
  std::vector<std::pair<Vec3f, Vec3f>> segments;  // a sample of them (end points)
};

// What the check found, as the tables above the view show it. proxies/check fills it from its
// typed report (check_view3d.cpp); an empty text or an unset optional leaves its row out.
struct View3dCheck {
  // A class's count and fraction of all segments with its 95 % interval.
  struct ClassRate {
    uint64_t count = 0;
    double fraction = 0, lo = 0, hi = 1;
  };
  std::optional<std::array<ClassRate, 4>> classes;  // HH', HM', MH', MM'
  std::string proven_class;  // the class the exact check proves, and what that means
  std::string proven_class_note;
  std::string sampled_class;
  // The error class the segments never showed and the upper 95 % bound on its rate.
  std::optional<std::pair<std::string, double>> missed_class_bound;
  std::string exact, exact_detail;  // the exact containment verdict and its detail
  std::string expect;               // the --expect class, and the evidence against it
  std::optional<std::string> contradiction;
  std::optional<std::string> mismatch;  // sampled and exact verdicts disagree
  std::optional<bool> ok;
  // A mesh's file as the check names it (empty: the TriMesh's source) and whether it is closed.
  struct Mesh {
    std::string file;
    std::optional<bool> closed;
  };
  Mesh original, proxy;
};

struct View3dPage {
  std::string title;  // "proxy-check: bunny.outside.ply against bunny.off"
  const TriMesh* original = nullptr;
  const TriMesh* proxy = nullptr;
  std::string claim;  // the class the page checks ("outside"), or empty; shown in the summary
  std::vector<View3dSegmentLayer> layers;
  View3dCheck check;    // the tables above the view
  nlohmann::json json;  // the check's report as its program writes it, shown whole below the view
};

struct View3dLimits {
  // An original with more triangles is shown decimated (vertex clustering) to at most this many,
  // with a note; the proxy is always embedded whole.
  size_t max_original_triangles = 2'000'000;
  size_t max_segments_per_layer = 2'000;  // each layer draws the first ones of its list
};

// The page's text. Throws Error for a missing or empty mesh.
std::string view3dHtml(const View3dPage& page, const View3dLimits& limits = {});

// Helpers of the page writer, exposed for tests.
namespace detail {
std::string base64(const void* data, size_t bytes);
// JSON text that is safe inside <script>: every '<' written as \u003c.
std::string jsonForScript(const nlohmann::json& json);
}  // namespace detail

}  // namespace proxyvis
