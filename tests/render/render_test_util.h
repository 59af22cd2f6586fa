#pragma once
// Shared helpers for the renderer tests: scratch folders with tiny scenes, estimators that need
// no lib/estimate (exact, and culling built on the SegmentTracer), and Lambert's closed form for
// the irradiance from a polygonal light.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "estimate/visibility_estimator.h"
#include "util/vec3.h"

namespace proxyvis::test {

class ScratchDir {
 public:
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           (std::string("pv_render_") + info->test_suite_name() + "_" + info->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  ~ScratchDir() { std::filesystem::remove_all(dir_); }
  const std::filesystem::path& path() const { return dir_; }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto p = dir_ / name;
    std::ofstream(p) << text;
    return p;
  }

 private:
  std::filesystem::path dir_;
};

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
