// --rays N means N classified segments: a generator that gives no segment for some indices is
// drawn from until N segments were classified (the lowest such indices, at any batch size), and
// stops after max_attempts indices with what it has, which checkPair reports as a shortfall.
#include <gtest/gtest.h>

#include "proxies/check/pair_check.h"
#include "proxies/check/ray_classify.h"
#include "tests/proxies/check/check_shapes.h"

namespace proxyvis {
namespace {

const Vec3f kCenter{0, 0, 0};

struct Pair {
  TriMesh original = test::makeSphere(kCenter, 1.0f, 16, 8, "sphere");
  TriMesh proxy = test::transformed(original, kCenter, 0.8f, {0.3f, 0, 0}, "shifted");
  TraceDevice device;
  std::unique_ptr<TraceScene> o = build(original), p = build(proxy);
  Sphere sphere = enclosingSphere(original.bounds(), proxy.bounds());
  std::unique_ptr<TraceScene> build(const TriMesh& m) {
    TraceSceneBuilder b(device);
    b.addMesh(m);
    return b.build();
  }
};

ClassifyOptions options(uint64_t n, uint64_t max_attempts, uint32_t batch) {
  return {.segments = n, .max_attempts = max_attempts, .batch = batch, .quiet = true};
}

TEST(ClassifyAttempts, DrawsUntilNSegmentsAreClassified) {
  Pair pair;
  const SegmentGenerator all = sphereSegments(pair.sphere, 11);
  // Only every third index gives a segment.
  const SegmentGenerator thirds = [&](uint64_t i, Segment& s) { return i % 3 == 0 && all(i, s); };
  // The same segments, every index valid: index j gives what `thirds` gives for 3 j.
  const SegmentGenerator dense = [&](uint64_t j, Segment& s) { return all(3 * j, s); };
  constexpr uint64_t kN = 1000;
  for (const uint32_t batch : {64u, 1000u, 4096u}) {
    const Classification c =
        classifySegments(*pair.o, *pair.p, thirds, options(kN, 1000 * kN, batch));
    EXPECT_EQ(c.counts.total(), kN) << batch;
    EXPECT_EQ(c.attempts, 3 * (kN - 1) + 1) << batch;  // the last one counted is 3 (N - 1)
    EXPECT_EQ(c.skipped, c.attempts - kN) << batch;
    const Classification d = classifySegments(*pair.o, *pair.p, dense, options(kN, 0, 128));
    EXPECT_EQ(c.counts.hh, d.counts.hh);
    EXPECT_EQ(c.counts.hm, d.counts.hm);
    EXPECT_EQ(c.counts.mh, d.counts.mh);
    EXPECT_EQ(c.counts.mm, d.counts.mm);
    EXPECT_GT(d.counts.hm, 0u);  // the pair has all classes: the comparison says something
    EXPECT_GT(d.counts.mh, 0u);
  }
}

TEST(ClassifyAttempts, StopsAtTheCapWithWhatItHas) {
  Pair pair;
  const SegmentGenerator all = sphereSegments(pair.sphere, 3);
  const SegmentGenerator few = [&](uint64_t i, Segment& s) { return i < 250 && all(i, s); };
  const Classification c = classifySegments(*pair.o, *pair.p, few, options(1000, 5000, 512));
  EXPECT_EQ(c.counts.total(), 250u);
  EXPECT_EQ(c.attempts, 5000u);
  EXPECT_EQ(c.skipped, 4750u);
}

TEST(ClassifyAttempts, PairCheckReportsTheShortfall) {
  Pair pair;
  const SegmentGenerator all = sphereSegments(pair.sphere, 3);
  PairCheckOptions po;
  po.rays = 400;
  po.max_attempts = 2000;
  po.quiet = true;
  po.distance_samples = 200;
  po.generator = [&](uint64_t i, Segment& s) { return i % 10 == 0 && all(i, s); };
  po.distribution_name = "test";
  const PairCheckReport r = checkPair(pair.original, pair.proxy, po);
  EXPECT_EQ(r.sampled.counts.total(), 200u);
  ASSERT_TRUE(r.shortfall);
  EXPECT_NE(r.shortfall->find("only 200 of 400"), std::string::npos) << *r.shortfall;
  // Enough attempts: exactly N, no shortfall.
  po.max_attempts = 4000;
  const PairCheckReport full = checkPair(pair.original, pair.proxy, po);
  EXPECT_EQ(full.sampled.counts.total(), 400u);
  EXPECT_FALSE(full.shortfall);
}

}  // namespace
}  // namespace proxyvis
