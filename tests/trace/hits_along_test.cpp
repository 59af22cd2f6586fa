// TraceScene::hitsAlong: every user id a segment crosses, once, with its nearest crossing, for
// flattened meshes and instances alike, compared with one closest-hit query per object.
// TraceScene::crossedGroups: the groups of listed user ids a segment crosses, as hitsAlong finds
// them, with its ray masks and early stop.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "test_meshes.h"
#include "trace/trace_scene.h"
#include "util/rng.h"

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

// 100 spheres on a 10 x 10 grid (half flattened, half instanced; plain and robust tracing);
// random segments through them, random candidate lists in 1-4 groups.
TEST(CrossedGroups, AgreesWithHitsAlong) {
  TraceDevice device;
  const TriMesh sphere = icosphere(2, {}, 1.0f);
  for (bool robust : {false, true}) {
    TraceSceneOptions options;
    options.robust = robust;
    TraceSceneBuilder builder(device, options);
    const uint32_t proto = builder.addPrototype(sphere);
    for (uint32_t i = 0; i < 100; ++i) {
      const Affine3f xf = makeTransform({0, 1, 0}, 0.1f * float(i), 0.8f,
                                        {3.0f * float(i % 10), 0, 3.0f * float(i / 10)});
      if (i % 2)
        builder.addInstance(proto, xf, i);
      else
        builder.addMesh(sphere, xf, i);
    }
    const auto scene = builder.build();
    Rng rng(5, robust ? 1 : 0);
    int crossed = 0, missed = 0;
    for (int k = 0; k < 2000; ++k) {
      const Vec3f a(30 * rng.uniformFloat() - 1, 2 * rng.uniformFloat() - 1,
                    30 * rng.uniformFloat() - 1);
      const Vec3f b(30 * rng.uniformFloat() - 1, 2 * rng.uniformFloat() - 1,
                    30 * rng.uniformFloat() - 1);
      const Segment s = Segment::between(a, b);
      std::vector<TraceScene::UserHit> all;
      scene->hitsAlong(s, all);
      const size_t groups = 1 + size_t(rng.uniformFloat() * 4);
      std::vector<TraceScene::Candidate> candidates;
      std::vector<uint8_t> expected(groups, 0);
      for (uint32_t id = 0; id < 100; ++id) {
        if (rng.uniformFloat() > 0.1f) continue;
        const uint32_t g = uint32_t(rng.uniformFloat() * float(groups)) % uint32_t(groups);
        candidates.push_back({id, g});
        for (const TraceScene::UserHit& h : all)
          if (h.user_id == id) expected[g] = 1;
      }
      const size_t expected_count = size_t(std::count(expected.begin(), expected.end(), 1));
      std::vector<uint8_t> found(groups, 7);
      ASSERT_EQ(scene->crossedGroups(s, candidates, found, groups), expected_count);
      ASSERT_EQ(found, expected) << "segment " << k;
      ASSERT_EQ(scene->crossedGroups(s, candidates, found, 1), std::min<size_t>(expected_count, 1));
      EXPECT_EQ(scene->crossedGroups(s, candidates, found, 0), 0u);
      (expected_count ? crossed : missed)++;
    }
    EXPECT_GE(crossed, 200);
    EXPECT_GE(missed, 200);
  }
}

TEST(CrossedGroups, NoCandidatesCrossNothing) {
  TraceDevice device;
  TraceSceneBuilder builder(device);
  builder.addMesh(icosphere(1, {}, 1.0f), 3);
  const auto scene = builder.build();
  std::vector<uint8_t> found(1, 1);
  const Segment s = Segment::between(Vec3f(-2, 0, 0), Vec3f(2, 0, 0));
  EXPECT_EQ(scene->crossedGroups(s, {}, found, 1), 0u);
  EXPECT_EQ(found[0], 0);
  const std::vector<TraceScene::Candidate> other = {{4, 0}};  // an id with no geometry
  EXPECT_EQ(scene->crossedGroups(s, other, found, 1), 0u);
  const std::vector<TraceScene::Candidate> it = {{3, 0}};
  EXPECT_EQ(scene->crossedGroups(s, it, found, 1), 1u);
  EXPECT_EQ(found[0], 1);
}

}  // namespace
}  // namespace proxyvis::test
