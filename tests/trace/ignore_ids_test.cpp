// Self-shadowing support in lib/trace: a query that ignores a user id does not see that geometry,
// with either strategy (an intersection filter, or ray masks then the filter), exactly, even for
// objects that share the ignored one's mask bit.
#include <embree3/rtcore.h>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <limits>

#include "brute_force.h"
#include "test_meshes.h"
#include "trace/internal/trace_scene_impl.h"  // maskBit, to build colliding ids
#include "trace/trace_scene.h"
#include "trace_compare.h"

namespace proxyvis {
// Readable parameter names in test listings.
void PrintTo(IgnoreStrategy s, std::ostream* os) {
  *os << (s == IgnoreStrategy::kAuto     ? "auto"
          : s == IgnoreStrategy::kFilter ? "filter"
                                         : "mask-then-filter");
}
}  // namespace proxyvis
namespace proxyvis::test {
namespace {

// Self-shadowing support: geometry with the ignored user id is invisible to that query only.
class IgnoreStrategies : public ::testing::TestWithParam<IgnoreStrategy> {
 protected:
  TraceSceneOptions options() const {
    TraceSceneOptions o;
    o.ignore = GetParam();
    return o;
  }
};
INSTANTIATE_TEST_SUITE_P(TraceScene, IgnoreStrategies,
                         ::testing::Values(IgnoreStrategy::kFilter,
                                           IgnoreStrategy::kMaskThenFilter),
                         [](const auto& info) {
                           return info.param == IgnoreStrategy::kFilter ? "Filter"
                                                                        : "MaskThenFilter";
                         });

TEST_P(IgnoreStrategies, IgnoreUserIdHidesOnlyThatGeometry) {
  TraceDevice device;
  TraceSceneBuilder builder(device, options());
  // Along +x: sphere A (user 1) at x=0, instance B (user 2) of a sphere at x=4, mesh C (user 3)
  // at x=8 sharing user id 1 with A (two pieces of one object).
  builder.addMesh(icosphere(2, {0, 0, 0}, 1), 1);
  uint32_t proto = builder.addPrototype(icosphere(2));
  builder.addInstance(proto, Affine3f::translation({4, 0, 0}), 2);
  builder.addMesh(icosphere(2, {8, 0, 0}, 1), 1);
  auto scene = builder.build();
  Segment through_a{{-2, 0, 0}, 0, {1, 0, 0}, 2};     // x in [-2, 0]: only A
  Segment through_b{{2, 0, 0}, 0, {1, 0, 0}, 4};      // x in [2, 6]: only B
  Segment through_all{{-2, 0, 0}, 0, {1, 0, 0}, 12};  // all three
  EXPECT_TRUE(scene->occluded(through_a));
  EXPECT_FALSE(scene->occluded(through_a, 1));
  EXPECT_TRUE(scene->occluded(through_a, 2));
  EXPECT_TRUE(scene->occluded(through_b));
  EXPECT_FALSE(scene->occluded(through_b, 2));
  EXPECT_TRUE(scene->occluded(through_b, 1));
  EXPECT_TRUE(scene->occluded(through_all, 1));
  EXPECT_TRUE(scene->occluded(through_all, 2));
  EXPECT_TRUE(scene->occluded(through_all, 99));

  Hit h = scene->intersect(through_all);
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.user_id, 1u);
  EXPECT_NEAR(h.t, 1.0f, 0.05f);  // x = -1
  h = scene->intersect(through_all, 1);
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.user_id, 2u);
  EXPECT_EQ(h.instance_id, 1u);
  EXPECT_EQ(h.geom_id, proto);
  EXPECT_NEAR(h.t, 5.0f, 0.05f);  // x = 3
  EXPECT_LT(h.ng.x, 0);           // outward normal of the instanced sphere faces the ray
  h = scene->intersect(through_all, 2);
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.user_id, 1u);
  EXPECT_NEAR(h.t, 1.0f, 0.05f);
  // A ray leaving A's surface outward: blocked by A's far side only if not ignored.
  Segment from_inside{{0, 0, 0}, 0, {1, 0, 0}, 2.5f};  // ends before B (x >= 3)
  EXPECT_TRUE(scene->occluded(from_inside));
  EXPECT_FALSE(scene->occluded(from_inside, 1));
}

// Ignoring is exact even for objects that share the ignored object's mask bit (they are only
// seen by the second, filtered pass): A and B share a bit, C has another one.
TEST_P(IgnoreStrategies, IgnoreIsExactForObjectsSharingAMaskBit) {
  const uint32_t a = 5;
  uint32_t b = a + 1, c = a + 1;
  while (maskBit(b) != maskBit(a)) ++b;
  while (maskBit(c) == maskBit(a)) ++c;
  for (bool instanced : {false, true}) {
    SCOPED_TRACE(instanced ? "instances" : "flattened meshes");
    TraceDevice device;
    TraceSceneBuilder builder(device, options());
    const TriMesh unit = icosphere(2);
    const uint32_t proto = builder.addPrototype(unit);
    auto add = [&](float x, uint32_t user) {
      if (instanced)
        builder.addInstance(proto, Affine3f::translation({x, 0, 0}), user);
      else
        builder.addMesh(icosphere(2, {x, 0, 0}, 1), user);
    };
    add(0, a);  // A at x = 0, B at x = 4, C at x = 8, a second piece of A at x = 12
    add(4, b);
    add(8, c);
    add(12, a);
    auto scene = builder.build();
    const Segment from_a{{0, 0, 0}, 0, {1, 0, 0}, 20};
    EXPECT_TRUE(scene->occluded(from_a, a));
    Hit h = scene->intersect(from_a, a);
    ASSERT_TRUE(h.hit);
    EXPECT_EQ(h.user_id, b);
    EXPECT_NEAR(h.t, 3.0f, 0.05f);
    h = scene->intersect(from_a, b);
    ASSERT_TRUE(h.hit);
    EXPECT_EQ(h.user_id, a);
    EXPECT_NEAR(h.t, 1.0f, 0.05f);
    h = scene->intersect({{4, 0, 0}, 0, {1, 0, 0}, 20}, b);  // from B: C next, not the second A
    ASSERT_TRUE(h.hit);
    EXPECT_EQ(h.user_id, c);
    EXPECT_FALSE(scene->occluded({{0, 0, 0}, 0, {1, 0, 0}, 2.5f}, a));  // only A
    EXPECT_TRUE(scene->occluded({{2, 0, 0}, 0, {1, 0, 0}, 2.5f}, a));   // reaches B
    EXPECT_FALSE(scene->occluded({{2, 0, 0}, 0, {1, 0, 0}, 2.5f}, b));
    EXPECT_FALSE(scene->occluded({{9.5f, 0, 0}, 0, {1, 0, 0}, 5}, a));  // the second piece of A
    EXPECT_TRUE(scene->occluded({{9.5f, 0, 0}, 0, {1, 0, 0}, 5}, c));
    h = scene->intersect({{-2, 0, 0}, 0, {1, 0, 0}, 20}, a);  // through A, B, C, A
    ASSERT_TRUE(h.hit);
    EXPECT_EQ(h.user_id, b);
    EXPECT_NEAR(h.t, 5.0f, 0.05f);
    EXPECT_FALSE(scene->intersect({{9.5f, 0, 0}, 0, {1, 0, 0}, 5}, a).hit);
  }
}

// kAuto picks the two-pass strategy for mostly instanced scenes, the filter for flattened ones.
TEST(TraceScene, AutoIgnoreStrategyFollowsTheSceneKind) {
  TraceDevice device;
  TraceSceneBuilder builder(device);
  uint32_t p = builder.addPrototype(icosphere(1));
  builder.addInstance(p, Affine3f::translation({0, 0, 0}), 1);
  builder.addInstance(p, Affine3f::translation({3, 0, 0}), 2);
  builder.addMesh(box({5, 0, 0}, {6, 1, 1}), 3);
  EXPECT_EQ(builder.build()->ignoreStrategy(), IgnoreStrategy::kMaskThenFilter);
  builder.addMesh(box({5, 0, 0}, {6, 1, 1}), 3);
  EXPECT_EQ(builder.build()->ignoreStrategy(), IgnoreStrategy::kFilter);
  TraceSceneOptions forced;
  forced.ignore = IgnoreStrategy::kFilter;
  TraceSceneBuilder forced_builder(device, forced);
  p = forced_builder.addPrototype(icosphere(1));
  forced_builder.addInstance(p, Affine3f(), 1);
  EXPECT_EQ(forced_builder.build()->ignoreStrategy(), IgnoreStrategy::kFilter);
}

}  // namespace
}  // namespace proxyvis::test
