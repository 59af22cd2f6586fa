// Ray-sampled classification: Embree counts against an independent brute-force classification,
// the guarantees of synthetic outside / inside proxies, general proxies, mismatched pairs, and
// determinism across thread counts.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "proxies/check/pair_check.h"
#include "proxies/check/ray_classify.h"
#include "tests/proxies/check/check_shapes.h"
#include "tests/proxies/check/pair_check_util.h"

namespace proxyvis {
namespace {

using test::makeBox;
using test::makeSphere;
using test::transformed;

const Vec3f kCenter{0.25f, 0.5f, -1.0f};

TriMesh sphere() {
  return makeSphere(kCenter, 1.0f, 16, 8, "sphere");
}

// Moller & Trumbore, "Fast, minimum storage ray/triangle intersection" (1997), in double: does
// the segment a + t (b - a), t in [0, 1], cross the triangle?
bool segmentHitsTriangle(const Vec3d& a, const Vec3d& b, const Vec3d& p0, const Vec3d& p1,
                         const Vec3d& p2) {
  const Vec3d d = b - a, e1 = p1 - p0, e2 = p2 - p0;
  const Vec3d pv = cross(d, e2);
  const double det = dot(e1, pv);
  if (det == 0) return false;
  const Vec3d tv = a - p0;
  const double u = dot(tv, pv) / det;
  if (u < 0 || u > 1) return false;
  const Vec3d qv = cross(tv, e1);
  const double v = dot(d, qv) / det;
  if (v < 0 || u + v > 1) return false;
  const double t = dot(e2, qv) / det;
  return t >= 0 && t <= 1;
}

bool bruteOccluded(const TriMesh& m, const Segment& s) {
  const Vec3d a(s.org + s.tnear * s.dir), b(s.org + s.tfar * s.dir);
  for (const Triangle& t : m.triangles)
    if (segmentHitsTriangle(a, b, Vec3d(m.vertices[t[0]]), Vec3d(m.vertices[t[1]]),
                            Vec3d(m.vertices[t[2]])))
      return true;
  return false;
}

Classification classify(const TriMesh& original, const TriMesh& proxy, uint64_t n, uint64_t seed,
                        uint64_t keep_errors = 0) {
  TraceDevice device;
  auto build = [&](const TriMesh& m) {
    TraceSceneBuilder b(device);
    b.addMesh(m);
    return b.build();
  };
  auto o = build(original), p = build(proxy);
  // Batches of 4096: several, one partial.
  const ClassifyOptions opt{
      .segments = n, .batch = 4096, .max_error_segments = keep_errors, .quiet = true};
  return classifySegments(
      *o, *p, sphereSegments(enclosingSphere(original.bounds(), proxy.bounds()), seed), opt);
}

TEST(RayClassify, CountsEqualBruteForce) {
  // A sphere and a shifted, smaller copy: all four classes occur.
  const TriMesh original = sphere();
  const TriMesh proxy = transformed(original, kCenter, 0.8f, {0.4f, 0, 0}, "shifted");
  constexpr uint64_t kN = 10'000, kSeed = 5;
  const Sphere s = enclosingSphere(original.bounds(), proxy.bounds());
  ClassCounts brute;
  for (uint64_t i = 0; i < kN; ++i) {
    const Segment seg = sphereSegment(s.center, s.radius, kSeed, i);
    const bool o = bruteOccluded(original, seg), p = bruteOccluded(proxy, seg);
    ++(o ? (p ? brute.hh : brute.hm) : (p ? brute.mh : brute.mm));
  }
  const Classification c = classify(original, proxy, kN, kSeed);
  EXPECT_EQ(c.counts.hh, brute.hh);
  EXPECT_EQ(c.counts.hm, brute.hm);
  EXPECT_EQ(c.counts.mh, brute.mh);
  EXPECT_EQ(c.counts.mm, brute.mm);
  EXPECT_GT(brute.hm, 0u);
  EXPECT_GT(brute.mh, 0u);
}

TEST(RayClassify, ErrorSegmentsAreTheErrorClasses) {
  const TriMesh original = sphere();
  const TriMesh proxy = transformed(original, kCenter, 1.0f, {0.3f, 0, 0}, "shifted");
  const Classification c = classify(original, proxy, 20'000, 3, 100);
  ASSERT_EQ(c.errors.size(), std::min<uint64_t>(100, c.counts.hm + c.counts.mh));
  for (const ErrorSegment& e : c.errors) {
    Segment s{e.a, 0, e.b - e.a, 1};
    EXPECT_EQ(bruteOccluded(original, s), e.hm);
    EXPECT_EQ(bruteOccluded(proxy, s), !e.hm);
  }
}

TEST(RayClassify, SameCountsAtAnyThreadCount) {
  const TriMesh original = sphere();
  const TriMesh proxy = transformed(original, kCenter, 1.0f, {0.2f, 0.1f, 0}, "shifted");
  ClassCounts one, two;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = classify(original, proxy, 100'000, 11).counts;
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    two = classify(original, proxy, 100'000, 11).counts;
  }
  EXPECT_EQ(one, two);
  EXPECT_EQ(one.total(), 100'000u);
}

PairCheckReport check(const TriMesh& original, const TriMesh& proxy) {
  return test::testCheckPair(original, proxy, 1);
}

// A cube of half-side `half` about the sphere's centre, checked against the sphere: the exact
// verdict is `verdict`, the sampled class `sampled` (outside: no HM' and some MH'; inside: the
// reverse), and the two agree.
PairCheckReport expectCubeClass(float half, ContainmentVerdict verdict, SampledClass sampled) {
  const Vec3f h(half, half, half);
  const PairCheckReport r = check(sphere(), makeBox(kCenter - h, kCenter + h));
  EXPECT_EQ(r.exact.verdict, verdict) << r.exact.detail;
  const bool outside = sampled == SampledClass::kOutside;
  EXPECT_EQ(outside ? r.sampled.counts.hm : r.sampled.counts.mh, 0u);
  EXPECT_GT(outside ? r.sampled.counts.mh : r.sampled.counts.hm, 0u);
  EXPECT_EQ(r.sampled_class, sampled);
  EXPECT_FALSE(r.mismatch);
  return r;
}

TEST(PairCheck, BoundingBoxIsOutside) {
  const PairCheckReport r =
      expectCubeClass(1.1f, ContainmentVerdict::kContains, SampledClass::kOutside);
  EXPECT_GT(r.proxy.volume, r.original.volume);
}

TEST(PairCheck, InnerBoxIsInside) {
  expectCubeClass(0.4f, ContainmentVerdict::kContained, SampledClass::kInside);
}

TEST(PairCheck, ShiftedCopyIsGeneralAndExpectationsFail) {
  const TriMesh s = sphere();
  PairCheckOptions o = test::testCheckOptions(0);
  o.expect = ProxyClass::kOutside;
  const PairCheckReport r = checkPair(s, transformed(s, kCenter, 1.0f, {0.1f, 0, 0}, "shift"), o);
  EXPECT_EQ(r.exact.verdict, ContainmentVerdict::kIntersecting);
  EXPECT_EQ(r.sampled_class, SampledClass::kGeneral);
  ASSERT_TRUE(r.contradiction);
  EXPECT_TRUE(r.failed());
  EXPECT_NEAR(r.distance_original_to_proxy, 0.1, 0.02);
}

TEST(PairCheck, FarAwayProxyIsDisjoint) {
  const TriMesh s = sphere();
  const PairCheckReport r = check(s, transformed(s, kCenter, 1.0f, {20, 0, 0}, "far"));
  EXPECT_EQ(r.exact.verdict, ContainmentVerdict::kDisjoint);
  EXPECT_GT(r.sampled.counts.hm, 0u);
  EXPECT_GT(r.sampled.counts.mh, 0u);
}

TEST(PairCheck, OpenProxyIsUndecidableButSampled) {
  const TriMesh s = sphere();
  const TriMesh open = test::withHole(transformed(s, kCenter, 1.2f, {}, "big"), "open");
  const PairCheckReport r = check(s, open);
  EXPECT_EQ(r.exact.verdict, ContainmentVerdict::kUndecidable);
  EXPECT_EQ(r.sampled.counts.total(), 200'000u);
  EXPECT_FALSE(r.mismatch);
}

}  // namespace
}  // namespace proxyvis
