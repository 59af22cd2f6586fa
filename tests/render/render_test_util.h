#pragma once
// Shared helpers for the renderer tests: tiny scenes for scratch folders, estimators that need
// no lib/estimate (exact, and culling built on the SegmentTracer), and Lambert's closed form for
// the irradiance from a polygonal light.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "estimate/visibility_estimator.h"
#include "render/render_scene.h"
#include "render/renderer.h"
#include "tests/support/scratch_dir.h"
#include "util/vec3.h"

namespace proxyvis::test {

// Axis-aligned box [lo, hi] as a closed, outward-oriented OBJ (12 triangles).
inline std::string boxObj(Vec3f lo, Vec3f hi) {
  std::string s;
  for (int i = 0; i < 8; ++i)
    s += "v " + std::to_string((i & 1) ? hi.x : lo.x) + " " +
         std::to_string((i & 2) ? hi.y : lo.y) + " " + std::to_string((i & 4) ? hi.z : lo.z) + "\n";
  // Faces as quads (1-based), counter-clockwise seen from outside.
  s += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  return s;
}

// Ground quad of half-size `h` at y = 0, facing +y.
inline std::string groundObj(float h) {
  const std::string a = std::to_string(h), b = std::to_string(-h);
  return "v " + b + " 0 " + b + "\nv " + a + " 0 " + b + "\nv " + a + " 0 " + a + "\nv " + b +
         " 0 " + a + "\nf 1 3 2\nf 1 4 3\n";
}

// Scene options without warnings on stderr.
inline RenderSceneOptions quiet(const std::string& proxy_kind = {}, bool use_proxies = true) {
  // The test scenes give small meshes box proxies with more triangles: keep them.
  return {.proxy_kind = proxy_kind,
          .use_proxies = use_proxies,
          .keep_larger_proxies = true,
          .trace = {},
          .quiet = true};
}

// Exact visibility from the original geometry.
class ExactTestEstimator final : public VisibilityEstimator {
 public:
  void estimate(const ShadingPointQuery& q, Rng&, std::span<double> out, RayCounts& c) override {
    for (size_t i = 0; i < q.segments.size(); ++i) {
      out[i] = q.tracer->originalVisible(q.segments[i]) ? 1.0 : 0.0;
      ++c.original;
    }
  }
};

// Proxy culling for an outside proxy: a segment that misses the proxy is visible, else trace the
// original. Exact when the proxy class is truly outside.
class CullingTestEstimator final : public VisibilityEstimator {
 public:
  void estimate(const ShadingPointQuery& q, Rng&, std::span<double> out, RayCounts& c) override {
    for (size_t i = 0; i < q.segments.size(); ++i) {
      ++c.proxy;
      if (q.tracer->proxyVisible(q.segments[i])) {
        out[i] = 1.0;
      } else {
        ++c.original;
        out[i] = q.tracer->originalVisible(q.segments[i]) ? 1.0 : 0.0;
      }
    }
  }
};

// Irradiance at x (unit normal n) from a polygon of constant radiance L, unoccluded and entirely
// above the tangent plane: Lambert's contour formula E = L/2 * |sum_i beta_i n.(r_i x r_i+1)/|..||
// (Lambert 1760; Arvo, "Irradiance tensors", SIGGRAPH 1995, eq. 3).
inline double polygonIrradiance(const Vec3d& x, const Vec3d& n, const std::vector<Vec3d>& poly,
                                double L) {
  double sum = 0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vec3d a = normalize(poly[i] - x), b = normalize(poly[(i + 1) % poly.size()] - x);
    const Vec3d c = cross(a, b);
    const double beta = std::atan2(length(c), dot(a, b));
    sum += beta * dot(n, c / length(c));
  }
  return 0.5 * L * std::abs(sum);
}

}  // namespace proxyvis::test

namespace proxyvis::test {

// A box A = [-1,1] x [0,2] x [-1,1] standing on a ground quad (half-size 10, y = 0) under a 4 x 4
// light at height 8, seen from the front and above. `proxy_json` is the box's "proxies" array
// (files relative to the scratch dir). Resolution res x res.
struct BoxScene {
  std::string proxies_json = "[]";
  std::string extra_meshes;    // appended to "meshes" (with a leading comma)
  std::string instances_file;  // "instances" file name, empty for none
  std::string light = R"({"type": "quad", "corner": [-2, 8, -2], "edge_u": [4, 0, 0],
      "edge_v": [0, 0, 4], "radiance": [6, 6, 6]})";
  int res = 24;
  bool place_box = true;

  std::filesystem::path write(const ScratchDir& dir) const {
    dir.write("ground.obj", groundObj(10));
    dir.write("box.obj", boxObj({-1, 0, -1}, {1, 2, 1}));
    dir.write("box_out.obj", boxObj({-1.3f, -0.3f, -1.3f}, {1.3f, 2.3f, 1.3f}));  // contains A
    dir.write("box_in.obj", boxObj({-0.7f, 0.3f, -0.7f}, {0.7f, 1.7f, 0.7f}));    // inside A
    dir.write("box_gen.obj", boxObj({-1.2f, 0.3f, -0.6f}, {1.2f, 1.7f, 0.6f}));   // neither
    std::string s = R"({"camera": {"eye": [2.5, 4.5, 6.5], "look_at": [0, 0.8, 0], "fov_deg": 45,
      "resolution": [)" +
                    std::to_string(res) + ", " + std::to_string(res) + R"(]},
      "lights": [)" +
                    light + R"(],
      "meshes": [{"name": "ground", "file": "ground.obj", "albedo": [0.8, 0.8, 0.8]},
                 {"name": "box", "file": "box.obj", "albedo": [0.6, 0.3, 0.2], "place": )" +
                    std::string(place_box ? "true" : "false") + R"(, "proxies": )" + proxies_json +
                    "}" + extra_meshes + "]";
    if (!instances_file.empty()) s += R"(, "instances": {"file": ")" + instances_file + "\"}";
    return dir.write("scene.json", s + "}");
  }
};

// BoxScene with `proxies_json` as the box's proxies, written to `dir` and loaded without warnings.
inline std::unique_ptr<RenderScene> loadBoxScene(const ScratchDir& dir,
                                                 const std::string& proxies_json = "[]") {
  BoxScene b;
  b.proxies_json = proxies_json;
  return loadRenderScene(b.write(dir), quiet());
}

// Settings of a quiet render of `spp` samples per pixel from `seed`.
inline RenderSettings quietSettings(int spp, uint64_t seed = 0) {
  RenderSettings s;
  s.spp = spp;
  s.seed = seed;
  s.quiet = true;
  return s;
}

// Settings of a quiet render that stops after `seconds` on its clock (no sample cap).
inline RenderSettings timeBudgetSettings(double seconds) {
  RenderSettings s = quietSettings(0);
  s.time_budget = seconds;
  return s;
}

inline const char* kOutsideProxy =
    R"([{"kind": "outside", "file": "box_out.obj", "class": "outside"}])";
inline const char* kInsideProxy =
    R"([{"kind": "inside", "file": "box_in.obj", "class": "inside"}])";
inline const char* kGeneralProxy =
    R"([{"kind": "general", "file": "box_gen.obj", "class": "general"}])";

}  // namespace proxyvis::test
