// The integrator: an unoccluded plane matches the closed-form irradiance per pixel; output is
// bit-identical at 1 and 2 threads; culling with a verified outside proxy equals exact; AOVs and
// the time budget; bad settings are errors.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "render/internal/integrator.h"
#include "render/render_scene.h"
#include "render/renderer.h"
#include "render_test_util.h"
#include "util/error.h"
#include "util/stats.h"

namespace proxyvis {
namespace {

using test::ScratchDir;

TEST(Integrator, UnoccludedPlaneMatchesLambertPerPixel) {
  ScratchDir dir;
  dir.write("ground.obj", test::groundObj(10));
  const auto path = dir.write("plane.json", R"({
    "camera": {"eye": [0, 6, 8], "look_at": [0, 0, 0], "fov_deg": 50, "resolution": [12, 10]},
    "lights": [{"type": "quad", "corner": [-3, 4, -1], "edge_u": [2, 0, 0], "edge_v": [0, 1, 3],
                "radiance": [5, 4, 3]}],
    "meshes": [{"name": "ground", "file": "ground.obj", "albedo": [0.8, 0.5, 0.25]}]})");
  const auto scene = loadRenderScene(path, test::quiet());
  RenderSettings settings = test::quietSettings(8);
  // The shading point of each pixel: the origin of its pass-0 segment (same for every pass).
  const PassSegments ps = passSegments(*scene, settings, 0);
  const int w = 12, h = 10, seeds = 40;
  ASSERT_GT(ps.segments.size(), size_t(w * h / 2));  // the top rows look past the plane
  std::vector<RunningStats> stats(size_t(w * h));
  test::ExactTestEstimator exact;
  for (int k = 0; k < seeds; ++k) {
    settings.seed = uint64_t(k);
    const RenderResult r = render(*scene, settings, exact);
    for (int p = 0; p < w * h; ++p) stats[size_t(p)].add(r.radiance.pixels[size_t(p) * 3 + 1]);
  }
  const std::vector<Vec3d> poly = {Vec3d(-3, 4, -1), Vec3d(-1, 4, -1), Vec3d(-1, 5, 2),
                                   Vec3d(-3, 5, 2)};
  const double z = sidakZ(1e-3, uint64_t(w * h));
  for (size_t i = 0; i < ps.segments.size(); ++i) {
    const double e = test::polygonIrradiance(Vec3d(ps.segments[i].org), {0, 1, 0}, poly, 4.0);
    const double ref = 0.5 / 3.14159265358979 * e;  // green: albedo 0.5, radiance 4
    const RunningStats& s = stats[ps.pixels[i]];
    EXPECT_NEAR(s.mean(), ref, z * s.standardError() + 1e-6 * ref) << "pixel " << ps.pixels[i];
  }
}

RenderResult renderIn(int threads, const RenderScene& scene, const RenderSettings& settings,
                      VisibilityEstimator& estimator) {
  tbb::task_arena arena(threads);
  RenderResult r;
  arena.execute([&] { r = render(scene, settings, estimator); });
  return r;
}

TEST(Integrator, BitIdenticalAtOneAndTwoThreads) {
  ScratchDir dir;
  const auto scene = test::loadBoxScene(dir, test::kOutsideProxy);
  RenderSettings settings = test::quietSettings(6, 5);
  settings.tile_size = 7;  // tiles that do not divide the image
  test::CullingTestEstimator culling;
  const RenderResult one = renderIn(1, *scene, settings, culling);
  const RenderResult two = renderIn(2, *scene, settings, culling);
  EXPECT_EQ(one.radiance.pixels, two.radiance.pixels);
  EXPECT_EQ(one.visibility.pixels, two.visibility.pixels);
  EXPECT_EQ(one.cost.pixels, two.cost.pixels);
  EXPECT_EQ(one.rays.proxy, two.rays.proxy);
  settings.seed = 6;  // teeth: another seed gives another image
  EXPECT_NE(renderIn(2, *scene, settings, culling).radiance.pixels, one.radiance.pixels);
}

TEST(Integrator, CullingWithVerifiedOutsideProxyEqualsExact) {
  ScratchDir dir;
  const auto scene = test::loadBoxScene(dir, test::kOutsideProxy);
  RenderSettings settings = test::quietSettings(4);
  test::ExactTestEstimator exact;
  test::CullingTestEstimator culling;
  const RenderResult e = render(*scene, settings, exact);
  const RenderResult c = render(*scene, settings, culling);
  EXPECT_EQ(e.radiance.pixels, c.radiance.pixels);
  EXPECT_EQ(c.rays.proxy, c.shadow_segments);
  EXPECT_LT(c.rays.original, c.rays.proxy);  // culling skipped some originals
  // Cost AOV sums to the totals; exact traces one original per segment.
  double orig = 0;
  for (size_t i = 0; i < e.cost.pixels.size(); i += 3) orig += e.cost.pixels[i + 1];
  EXPECT_EQ(uint64_t(orig), e.rays.original);
  EXPECT_EQ(e.rays.original, e.shadow_segments);
  EXPECT_EQ(e.spp, 4);
  EXPECT_EQ(e.primary_rays, uint64_t(24 * 24));
  // Visibility AOV in [0, 1], with shadowed and lit pixels.
  float lo = 1, hi = 0;
  for (float v : e.visibility.pixels) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_EQ(lo, 0.0f);
  EXPECT_EQ(hi, 1.0f);
}

TEST(Integrator, TimeBudgetRunsWholePasses) {
  ScratchDir dir;
  const auto scene = test::loadBoxScene(dir);
  RenderSettings settings = test::timeBudgetSettings(0.05);
  test::ExactTestEstimator exact;
  const RenderResult r = render(*scene, settings, exact);
  EXPECT_GE(r.spp, 1);
  EXPECT_EQ(r.passes, r.spp);
  settings.spp = 3;  // cap
  settings.time_budget = 100;
  EXPECT_EQ(render(*scene, settings, exact).spp, 3);
  settings.samples_per_pass = 2;
  const RenderResult batched = render(*scene, settings, exact);
  EXPECT_EQ(batched.spp, 3);
  EXPECT_EQ(batched.passes, 2);
}

TEST(Integrator, BadSettingsAreErrors) {
  ScratchDir dir;
  const auto scene = test::loadBoxScene(dir);
  test::ExactTestEstimator exact;
  RenderSettings s;
  s.spp = 0;
  EXPECT_THROW(render(*scene, s, exact), Error);
  s.spp = 4;
  s.tile_size = 0;
  EXPECT_THROW(render(*scene, s, exact), Error);
  s.tile_size = 16;
  s.time_budget = -1;
  EXPECT_THROW(render(*scene, s, exact), Error);
}

// Under a time budget a pass of 16 samples (probe estimators) must not overshoot by a whole
// pass: it shrinks to what the time left allows. One ray unit = last pass / (2 x 16 probes + 1
// sample) = 0.01 s below.
TEST(Integrator, LastPassFitsTheTimeBudget) {
  using detail::passSamplesWithinBudget;
  EXPECT_EQ(passSamplesWithinBudget(10.0, 16, 0, 0, 0, 16), 16);    // first pass: whole
  EXPECT_EQ(passSamplesWithinBudget(1.0, 16, 1, 0.33, 1, 16), 16);  // room for a whole pass
  EXPECT_EQ(passSamplesWithinBudget(0.4, 16, 2, 0.33, 1, 16), 8);   // 40 units - 32 of probes
  EXPECT_EQ(passSamplesWithinBudget(0.2, 16, 2, 0.33, 1, 16), 1);   // over half of one sample
  EXPECT_EQ(passSamplesWithinBudget(0.1, 16, 2, 0.33, 1, 16), 0);   // less: stop
  EXPECT_EQ(passSamplesWithinBudget(0.4, 5, 2, 0.33, 1, 16), 5);    // never more than asked
}

}  // namespace
}  // namespace proxyvis
