// BoxIndex against a brute-force slab test in double: every label whose box a random segment
// meets, with the entry t, and every such box (boxesAlong); segments that start or end inside a
// box count.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "distributed/box_index.h"
#include "util/rng.h"

namespace proxyvis {
namespace {

// Entry t of the segment into the box, or -1 if it misses, in double.
double slab(const Segment& s, const Bounds3f& b) {
  double t0 = s.tnear, t1 = s.tfar;
  for (int a = 0; a < 3; ++a) {
    const double o = s.org[a], d = s.dir[a];
    if (d == 0) {
      if (o < b.lo[a] || o > b.hi[a]) return -1;
      continue;
    }
    double ta = (b.lo[a] - o) / d, tb = (b.hi[a] - o) / d;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return -1;
  }
  return t0;
}

TEST(BoxIndex, AgreesWithBruteForceSlabs) {
  TraceDevice device;
  Rng rng(11, 0);
  std::vector<LabelledBox> boxes;
  for (int i = 0; i < 200; ++i) {
    LabelledBox lb;
    const Vec3f c(10 * rng.uniformFloat(), 10 * rng.uniformFloat(), 10 * rng.uniformFloat());
    const Vec3f h(0.1f + rng.uniformFloat(), 0.1f + rng.uniformFloat(), 0.1f + rng.uniformFloat());
    lb.box.extend(c - h);
    lb.box.extend(c + h);
    lb.label = uint32_t(i % 7);
    lb.id = uint32_t(1000 + i);
    boxes.push_back(lb);
  }
  const BoxIndex index(device, boxes, 0.0f);
  int inside_starts = 0, compared = 0;
  for (int k = 0; k < 3000; ++k) {
    Segment s;
    s.org = Vec3f(10 * rng.uniformFloat(), 10 * rng.uniformFloat(), 10 * rng.uniformFloat());
    s.dir =
        Vec3f(8 * rng.uniformFloat() - 4, 8 * rng.uniformFloat() - 4, 8 * rng.uniformFloat() - 4);
    s.tnear = 0;
    s.tfar = 1;
    std::map<uint32_t, double> expected, expected_boxes;
    for (const LabelledBox& lb : boxes) {
      const double t = slab(s, lb.box);
      if (t < 0) continue;
      expected_boxes[lb.id] = t;
      if (t == 0) ++inside_starts;
      auto it = expected.find(lb.label);
      if (it == expected.end() || t < it->second) expected[lb.label] = t;
    }
    std::vector<LabelEntry> got = {{99, 5.0f}};  // an earlier entry is left alone
    index.labelsAlong(s, got);
    ASSERT_EQ(got[0].label, 99u);
    got.erase(got.begin());
    // Float against double may disagree only for grazing segments; none of these is.
    ASSERT_EQ(got.size(), expected.size()) << "segment " << k;
    for (const LabelEntry& e : got) {
      ASSERT_TRUE(expected.count(e.label)) << "label " << e.label;
      EXPECT_NEAR(e.t, expected[e.label], 1e-4);
      ++compared;
    }
    // boxesAlong: every box once, with its label and entry t.
    std::vector<BoxIndex::BoxEntry> per_box;
    index.boxesAlong(s, per_box);
    ASSERT_EQ(per_box.size(), expected_boxes.size()) << "segment " << k;
    for (const BoxIndex::BoxEntry& e : per_box) {
      ASSERT_TRUE(expected_boxes.count(e.id)) << "box " << e.id;
      EXPECT_EQ(e.label, uint32_t((e.id - 1000) % 7));
      EXPECT_NEAR(e.t, expected_boxes[e.id], 1e-4);
    }
  }
  EXPECT_GT(inside_starts, 10);  // segments starting inside boxes were exercised
  EXPECT_GT(compared, 1000);
}

TEST(BoxIndex, PadGrowsEveryBox) {
  TraceDevice device;
  LabelledBox lb;
  lb.box.extend(Vec3f(0, 0, 0));
  lb.box.extend(Vec3f(1, 1, 1));
  const BoxIndex tight(device, {lb}, 0.0f), padded(device, {lb}, 0.01f);
  // A segment passing 0.005 above the top face.
  const Segment s = Segment::between(Vec3f(-1, 1.005f, 0.5f), Vec3f(2, 1.005f, 0.5f));
  std::vector<LabelEntry> a, b;
  tight.labelsAlong(s, a);
  padded.labelsAlong(s, b);
  EXPECT_TRUE(a.empty());
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].label, lb.label);
}

TEST(BoxIndex, EmptyIndexReportsNothing) {
  TraceDevice device;
  const BoxIndex index(device, {}, 0.0f);
  std::vector<LabelEntry> out;
  index.labelsAlong(Segment::between(Vec3f(0, 0, 0), Vec3f(1, 1, 1)), out);
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace proxyvis
