// TraceScene::hitsAlong: every user id a segment crosses, once, with its nearest crossing, for
// flattened meshes and instances alike, compared with one closest-hit query per object.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "test_meshes.h"
#include "trace/trace_scene.h"

namespace proxyvis::test {
namespace {

TEST(HitsAlong, EveryObjectOnceWithItsNearestCrossing) {
  TraceDevice device;
  const TriMesh sphere = icosphere(2, {}, 1.0f);
  // Ten spheres in a row along x (ids 100..109), half flattened, half instanced.
  TraceSceneBuilder all(device);
  const uint32_t proto = all.addPrototype(sphere);
  std::vector<std::unique_ptr<TraceScene>> single;
  std::vector<Affine3f> placements;
  for (int i = 0; i < 10; ++i) {
    const Affine3f xf = makeTransform({0, 1, 0}, 0.3f * float(i), 1.0f, {3.0f * float(i), 0, 0});
    placements.push_back(xf);
    if (i % 2)
      all.addInstance(proto, xf, 100u + uint32_t(i));
    else
      all.addMesh(sphere, xf, 100u + uint32_t(i));
    TraceSceneBuilder one(device);
    one.addMesh(sphere, xf, 100u + uint32_t(i));
    single.push_back(one.build());
  }
  const auto scene = all.build();
  int checked = 0;
  for (float y : {0.0f, 0.5f, 0.95f, 1.2f}) {
    // From inside the first sphere to past the last one.
    const Segment s = Segment::between(Vec3f(0, y, 0.1f), Vec3f(30, y, 0.1f));
    std::vector<TraceScene::UserHit> got = {{7, 0.5f}};  // earlier entries are left alone
    scene->hitsAlong(s, got);
    ASSERT_EQ(got[0].user_id, 7u);
    got.erase(got.begin());
    std::map<uint32_t, float> expected;
    for (int i = 0; i < 10; ++i) {
      const Hit h = single[size_t(i)]->intersect(s);
      if (h.hit) expected[100u + uint32_t(i)] = h.t;
    }
    ASSERT_EQ(got.size(), expected.size()) << "y = " << y;
    for (const auto& h : got) {
      ASSERT_TRUE(expected.count(h.user_id));
      EXPECT_NEAR(h.t, expected[h.user_id], 1e-5f);
      ++checked;
    }
    if (y < 0.6f) {
      EXPECT_EQ(got.size(), 10u);  // the segment starts inside sphere 0: its exit counts
    }
    if (y > 1) {
      EXPECT_TRUE(got.empty());
    }
  }
  EXPECT_GE(checked, 30);
}

}  // namespace
}  // namespace proxyvis::test
