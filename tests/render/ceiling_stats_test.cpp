// The ceiling's measurement (render/ceiling_stats.h): it traces exactly the renderer's segments
// (passSegments) with the self-shadowing rule, files them under the renderer's regions, and its
// counts are deterministic; c_s prices the exact renders' shading at their visibility's rate.
#include "render/ceiling_stats.h"

#include <gtest/gtest.h>

#include "render/render_scene.h"
#include "render/scene_tracer.h"
#include "render_test_util.h"

namespace proxyvis {
namespace {

using test::BoxScene;
using test::ScratchDir;

TEST(CeilingStats, CountsTheRenderersSegmentsByRegion) {
  ScratchDir dir;
  const auto scene = test::loadBoxScene(dir, test::kOutsideProxy);
  ASSERT_TRUE(scene->usesProxies());
  RenderSettings settings;
  settings.seed = 5;
  const CeilingMeasurement m = measureCeilingStats(*scene, settings, 3, 1e9);
  ASSERT_EQ(m.passes, 3);
  ASSERT_EQ(m.num_lights, 1u);

  // The same classes counted directly from the renderer's segments of those passes.
  double segments = 0, blocked = 0, mh = 0, hm = 0, on_box = 0;
  for (int pass = 0; pass < 3; ++pass) {
    const PassSegments ps = passSegments(*scene, settings, pass);
    for (size_t i = 0; i < ps.segments.size(); ++i) {
      const SceneTracer tracer(*scene, ps.objects[i]);
      const bool v = tracer.originalVisible(ps.segments[i]);
      const bool vp = tracer.proxyVisible(ps.segments[i]);
      segments += 1, blocked += !vp, mh += v && !vp, hm += !v && vp;
      on_box += scene->objects()[ps.objects[i]].proxy >= 0;
    }
  }
  CeilingRegionStats all, self;
  for (size_t r = 0; r < m.regions.size(); ++r) {
    addCeilingStats(all, m.regions[r]);
    if (r % 2 == 1)
      addCeilingStats(self, m.regions[r]);  // region = (tile x lights + light) x 2 + self
  }
  ASSERT_GT(segments, 100);
  EXPECT_EQ(double(m.segments), segments);
  EXPECT_EQ(all.segments, segments);
  EXPECT_EQ(all.blocked, blocked);
  EXPECT_EQ(all.mh, mh);
  EXPECT_EQ(all.hm, 0);  // outside proxy
  EXPECT_EQ(hm, 0);
  EXPECT_GT(mh, 0);  // ground in the proxy's shadow but not the box's
  EXPECT_EQ(self.segments, on_box);
  EXPECT_GT(on_box, 0);
  EXPECT_GT(all.var_fv, 0);
  EXPECT_GT(all.f2_mh, 0);
  EXPECT_GT(all.cost_original[0] + all.cost_original[1], 0);
  EXPECT_GT(all.cost_proxy[0] + all.cost_proxy[1], 0);

  // Counts and variances do not depend on timing.
  const CeilingMeasurement again = measureCeilingStats(*scene, settings, 3, 1e9);
  for (size_t r = 0; r < m.regions.size(); ++r) {
    EXPECT_EQ(again.regions[r].segments, m.regions[r].segments);
    EXPECT_EQ(again.regions[r].f2_mh, m.regions[r].f2_mh);
    EXPECT_EQ(again.regions[r].var_fv, m.regions[r].var_fv);
  }
  const CeilingResult result = computeCeiling(ceilingInput(*scene, m, 10, 0.05));
  EXPECT_GE(result.scene.ceiling, 1.0);
  EXPECT_EQ(result.scene.segments, segments);
}

TEST(CeilingStats, StopsAfterTwoPassesWhenOutOfTime) {
  ScratchDir dir;
  const auto scene = loadRenderScene(BoxScene{}.write(dir), test::quiet());
  const CeilingMeasurement m = measureCeilingStats(*scene, RenderSettings{}, 8, 0);
  EXPECT_EQ(m.passes, 2);  // a pixel's variance needs two samples
}

// c_s = c_o x shading / visibility: original rays of 100 ns measured; renders that spent 1 s
// shading and 2 s on visibility give 50 ns per segment.
TEST(CeilingStats, ShadingPricedAtTheVisibilityRate) {
  CeilingMeasurement m;
  m.regions.resize(2);
  m.regions[0].segments = 6, m.regions[0].cost_original[0] = 600;
  m.regions[1].segments = 4, m.regions[1].cost_original[1] = 400;
  RenderResult a, b;
  a.shading_seconds = 0.25, a.visibility_seconds = 0.5, a.shadow_segments = 30;
  b.shading_seconds = 0.75, b.visibility_seconds = 1.5, b.shadow_segments = 20;
  EXPECT_NEAR(shadingNsPerSegment({&a, &b}, m), 50, 1e-9);
  RenderResult empty;
  EXPECT_EQ(shadingNsPerSegment({&empty}, m), 0);
}

}  // namespace
}  // namespace proxyvis
