// Area-light sampling: the Monte Carlo irradiance at unoccluded points matches Lambert's closed
// form within a z-bound from the measured variance; lights are picked in proportion to area.
#include <gtest/gtest.h>

#include "render/light_sampler.h"
#include "render_test_util.h"
#include "util/rng.h"
#include "util/stats.h"

namespace proxyvis {
namespace {

AreaLightDesc quad(Vec3f c, Vec3f u, Vec3f v, float L) {
  AreaLightDesc l;
  l.triangles = {{c, c + u, c + u + v}, {c, c + u + v, c + v}};
  l.radiance = {L, L, L};
  return l;
}

TEST(LightSampler, IrradianceMatchesLambertsFormula) {
  const AreaLightDesc light = quad({-1, 3, -2}, {3, 0, 0}, {0, 0.5f, 2}, 5.0f);  // tilted quad
  const LightSampler sampler({light});
  EXPECT_NEAR(sampler.totalArea(), 3.0 * std::sqrt(0.25 + 4.0), 1e-5);
  const std::vector<Vec3d> poly = {Vec3d(-1, 3, -2), Vec3d(2, 3, -2), Vec3d(2, 3.5, 0),
                                   Vec3d(-1, 3.5, 0)};
  // Points and normals: below, off to the side, tilted.
  const Vec3d xs[] = {{0, 0, 0}, {4, 0.5, 1}, {-2, 1, -3}};
  const Vec3d ns[] = {{0, 1, 0}, normalize(Vec3d(-0.3, 1, 0.1)), normalize(Vec3d(0.5, 1, 0.5))};
  const double z = sidakZ(1e-3, 3);
  for (int k = 0; k < 3; ++k) {
    RunningStats stats;
    Rng rng(7, uint64_t(k));
    for (int i = 0; i < 200000; ++i) {
      const LightSample s =
          sampler.sample(rng.uniformFloat(), rng.uniformFloat(), rng.uniformFloat());
      const Vec3d w = Vec3d(s.point) - xs[k];
      const double d2 = dot(w, w), d = std::sqrt(d2);
      const double cos_x = std::max(0.0, dot(ns[k], w) / d);
      const double cos_y = std::abs(dot(Vec3d(s.normal), w)) / d;
      stats.add(double(s.radiance.x) * cos_x * cos_y / d2 / s.pdf_area);
    }
    const double ref = test::polygonIrradiance(xs[k], ns[k], poly, 5.0);
    EXPECT_NEAR(stats.mean(), ref, z * stats.standardError()) << "point " << k << " seed 7";
    EXPECT_GT(ref, 0.1);
  }
}

TEST(LightSampler, PicksLightsInProportionToArea) {
  // Light 1 has 3x the area of light 0.
  const LightSampler sampler(
      {quad({0, 5, 0}, {1, 0, 0}, {0, 0, 1}, 1), quad({3, 5, 0}, {3, 0, 0}, {0, 0, 1}, 2)});
  EXPECT_EQ(sampler.numLights(), 2u);
  Rng rng(11, 0);
  const int n = 100000;
  uint64_t on_1 = 0;
  for (int i = 0; i < n; ++i) {
    const LightSample s =
        sampler.sample(rng.uniformFloat(), rng.uniformFloat(), rng.uniformFloat());
    on_1 += s.light;
    ASSERT_NEAR(s.point.y, 5.0f, 1e-5f);
    if (s.light == 0) {
      ASSERT_TRUE(s.point.x >= 0 && s.point.x <= 1 && s.point.z >= 0 && s.point.z <= 1);
      ASSERT_EQ(s.radiance.x, 1.0f);
    } else {
      ASSERT_TRUE(s.point.x >= 3 && s.point.x <= 6 && s.point.z >= 0 && s.point.z <= 1);
      ASSERT_EQ(s.radiance.x, 2.0f);
    }
    ASSERT_DOUBLE_EQ(s.pdf_area, 1.0 / 4.0);
  }
  const double p = 0.75, se = std::sqrt(p * (1 - p) / n);
  EXPECT_NEAR(double(on_1) / n, p, 4.5 * se);
  // sampleLight stays on its light, with that light's pdf.
  const LightSample s = sampler.sampleLight(1, 0.1f, 0.5f, 0.5f);
  EXPECT_EQ(s.light, 1u);
  EXPECT_DOUBLE_EQ(s.pdf_area, 1.0 / 3.0);
}

TEST(LightSampler, UniformOverAQuadByCells) {
  // Chi-square over a 4x4 grid of equal cells of a square light (expected counts >= 5 each).
  const LightSampler sampler({quad({0, 1, 0}, {1, 0, 0}, {0, 0, 1}, 1)});
  Rng rng(3, 0);
  const int n = 160000, cells = 16;
  std::vector<double> count(cells, 0);
  for (int i = 0; i < n; ++i) {
    const LightSample s =
        sampler.sample(rng.uniformFloat(), rng.uniformFloat(), rng.uniformFloat());
    const int cx = std::min(3, int(s.point.x * 4)), cz = std::min(3, int(s.point.z * 4));
    count[size_t(cz * 4 + cx)] += 1;
  }
  double chi2 = 0;
  for (double c : count) chi2 += (c - n / 16.0) * (c - n / 16.0) / (n / 16.0);
  EXPECT_LT(chi2, 37.7);  // chi-square, 15 degrees of freedom, p = 0.001
}

}  // namespace
}  // namespace proxyvis
