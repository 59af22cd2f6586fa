// lib/trace against an independent reference (brute-force Möller–Trumbore in double) on
// procedural meshes; instances against the same meshes flattened; batch, counters, ignore ids,
// empty scenes and bad input.
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
#include "util/error.h"

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

constexpr uint64_t kSeed = 20140623;

std::unique_ptr<TraceScene> flatScene(TraceDevice& device, const TriMesh& mesh,
                                      const TraceSceneOptions& options = {}) {
  TraceSceneBuilder builder(device, options);
  builder.addMesh(mesh, 7);
  return builder.build();
}

// Disagreements with the double-precision reference are allowed only where the segment passes
// within eps of an edge, vertex or its own endpoint (float rounding decides those), and only few.
// eps = 1e-5 of the scene diagonal: float coordinates carry ~6e-8 relative error, and Embree's
// float edge tests lose a few more bits; explained disagreements measured here sit far inside it.
void expectAgreement(const OcclusionAgreement& a, size_t max_disagreements) {
  SCOPED_TRACE("seed " + std::to_string(kSeed));
  EXPECT_EQ(a.unexplained, 0u) << "first unexplained segment: "
                               << (a.unexplained_indices.empty() ? 0 : a.unexplained_indices[0]);
  EXPECT_LE(a.disagreements, max_disagreements);
  // The test must be able to fail: both answers occur often.
  EXPECT_GT(a.occluded, a.segments / 20);
  EXPECT_LT(a.occluded, a.segments - a.segments / 20);
  std::printf("[ info ] %zu segments, %zu occluded, %zu disagreements (%zu unexplained)\n",
              a.segments, a.occluded, a.disagreements, a.unexplained);
}

// The classifier that explains disagreements must itself discriminate, or the agreement tests
// could not fail: segments through an edge, a vertex or ending on a face are "near a boundary",
// segments through the middle of faces or far away are not.
TEST(BruteForce, NearBoundaryClassifiesEdgesVerticesAndEndpoints) {
  TriMesh b = box({0, 0, 0}, {1, 1, 1});
  BruteForceMesh ref(b);
  const double eps = 1e-5;
  EXPECT_TRUE(ref.nearBoundary({{-1, 0.5f, 0.5f}, 0, {3, 0, 0}, 1}, eps));      // face diagonal
  EXPECT_TRUE(ref.nearBoundary({{-1, 0, 0.3f}, 0, {3, 0, 0}, 1}, eps));         // box edge
  EXPECT_TRUE(ref.nearBoundary({{-1, 1, 1}, 0, {3, 0, 0}, 1}, eps));            // box corner
  EXPECT_TRUE(ref.nearBoundary({{-1, 0.3f, 0.6f}, 0, {1, 0, 0}, 1}, eps));      // ends on a face
  EXPECT_TRUE(ref.nearBoundary({{-1, 0.3f, -0.5f}, 0, {2, 0, 1}, 1}, eps));     // enters on an edge
  EXPECT_FALSE(ref.nearBoundary({{-1, 0.3f, 0.6f}, 0, {3, 0, 0}, 1}, eps));     // through two faces
  EXPECT_FALSE(ref.nearBoundary({{-1, 0.3f, 0.6f}, 0, {0.5f, 0, 0}, 1}, eps));  // stops short
  EXPECT_FALSE(ref.nearBoundary({{-1, 2, 2}, 0, {3, 0, 0}, 1}, eps));           // far away
  EXPECT_TRUE(ref.occluded({{-1, 0.3f, 0.6f}, 0, {3, 0, 0}, 1}));
  EXPECT_FALSE(ref.occluded({{-1, 0.3f, 0.6f}, 0, {0.5f, 0, 0}, 1}));
  BruteHit h = ref.intersect({{-1, 0.3f, 0.6f}, 0, {3, 0, 0}, 1});
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.t, 1.0 / 3.0, 1e-12);
  EXPECT_TRUE(h.prim == 8 || h.prim == 9);  // the x = 0 face
}

TEST(TraceScene, IcosphereOcclusionMatchesBruteForce) {
  TraceDevice device;
  TriMesh mesh = icosphere(4);  // 5120 triangles
  auto scene = flatScene(device, mesh);
  BruteForceMesh ref(mesh);
  auto segs = randomSegments(grown(mesh.bounds(), 0.3f), kSeed, 20000);
  expectAgreement(compareOcclusion(*scene, ref, segs, 1e-5 * mesh.diagonal()), 5);
}

TEST(TraceScene, TriangleSoupOcclusionMatchesBruteForce) {
  TraceDevice device;
  TriMesh mesh = triangleSoup(3000, {0, 0, 0}, {1, 1, 1}, 0.15f, kSeed);
  auto scene = flatScene(device, mesh);
  BruteForceMesh ref(mesh);
  auto segs = randomSegments(grown(mesh.bounds(), 0.2f), kSeed + 1, 20000);
  expectAgreement(compareOcclusion(*scene, ref, segs, 1e-5 * mesh.diagonal()), 5);
}

TEST(TraceScene, RobustFlagAgreesToo) {
  TraceDevice device;
  TriMesh mesh = icosphere(3);
  TraceSceneOptions options;
  options.robust = true;
  options.high_quality = false;
  auto scene = flatScene(device, mesh, options);
  BruteForceMesh ref(mesh);
  auto segs = randomSegments(grown(mesh.bounds(), 0.3f), kSeed + 2, 20000);
  expectAgreement(compareOcclusion(*scene, ref, segs, 1e-5 * mesh.diagonal()), 5);
}

TEST(TraceScene, ClosestHitMatchesBruteForce) {
  TraceDevice device;
  TriMesh mesh = triangleSoup(2000, {0, 0, 0}, {1, 1, 1}, 0.2f, kSeed + 3);
  auto scene = flatScene(device, mesh);
  BruteForceMesh ref(mesh);
  const double eps = 1e-5 * mesh.diagonal();
  auto segs = randomSegments(grown(mesh.bounds(), 0.2f), kSeed + 4, 5000);
  size_t hits = 0, ambiguous = 0;
  for (size_t i = 0; i < segs.size(); ++i) {
    Hit h = scene->intersect(segs[i]);
    BruteHit b = ref.intersect(segs[i]);
    if (h.hit != b.hit || (h.hit && h.prim_id != b.prim)) {
      ++ambiguous;
      EXPECT_TRUE(ref.ambiguousClosest(segs[i], eps)) << "segment " << i;
      continue;
    }
    if (!h.hit) continue;
    ++hits;
    const double len = length(Vec3d(segs[i].dir));
    EXPECT_NEAR(h.t, b.t, eps / len) << "segment " << i;
    EXPECT_EQ(h.geom_id, 0u);
    EXPECT_EQ(h.instance_id, kInvalidId);
    EXPECT_EQ(h.user_id, 7u);
    // Barycentrics reproduce the hit point.
    const Triangle& t = mesh.triangles[h.prim_id];
    Vec3d p = Vec3d(mesh.vertices[t[0]]) * (1.0 - h.u - h.v) +
              Vec3d(mesh.vertices[t[1]]) * double(h.u) + Vec3d(mesh.vertices[t[2]]) * double(h.v);
    Vec3d q = Vec3d(segs[i].org) + Vec3d(segs[i].dir) * double(h.t);
    EXPECT_LT(length(p - q), 10 * eps) << "segment " << i;
    // Ng is the winding normal of the triangle hit.
    Vec3d n = cross(Vec3d(mesh.vertices[t[1]]) - Vec3d(mesh.vertices[t[0]]),
                    Vec3d(mesh.vertices[t[2]]) - Vec3d(mesh.vertices[t[0]]));
    EXPECT_GT(dot(normalize(n), normalize(Vec3d(h.ng))), 0.9999) << "segment " << i;
  }
  EXPECT_GT(hits, segs.size() / 4);
  EXPECT_LE(ambiguous, 3u);
}

// Instances must answer like the meshes flattened with their transforms applied (Embree
// transforms the ray instead of the mesh, so near-edge cases may differ).
TEST(TraceScene, InstancesMatchFlattenedTransformedMeshes) {
  TraceDevice device;
  TriMesh sphere = icosphere(3);
  TriMesh soup = triangleSoup(500, {-1, -1, -1}, {1, 1, 1}, 0.3f, kSeed + 5);
  std::vector<Affine3f> xfs = {
      makeTransform(normalize(Vec3f(1, 2, 3)), 0.7f, 1.5f, {3, 0, 0}),
      makeTransform(normalize(Vec3f(0, 0, 1)), 2.0f, 0.5f, {0, 3, 0}),
      makeTransform(normalize(Vec3f(1, 0, 0)), -1.0f, -1.0f, {0, 0, 3}),  // mirrored
      Affine3f::translation({-3, -3, 0})};
  TraceSceneBuilder inst_builder(device), flat_builder(device);
  uint32_t p_sphere = inst_builder.addPrototype(sphere), p_soup = inst_builder.addPrototype(soup);
  std::vector<TriMesh> flat;
  for (size_t k = 0; k < xfs.size(); ++k) {
    const TriMesh& proto = (k % 2) ? soup : sphere;
    EXPECT_EQ(inst_builder.addInstance((k % 2) ? p_soup : p_sphere, xfs[k], uint32_t(100 + k)), k);
    flat.push_back(transformed(proto, xfs[k]));
    EXPECT_EQ(flat_builder.addMesh(flat.back(), uint32_t(100 + k)), k);
  }
  auto inst = inst_builder.build();
  auto flat_scene = flat_builder.build();
  EXPECT_EQ(inst->triangleCount(), flat_scene->triangleCount());
  EXPECT_EQ(inst->triangleCount(), 2 * sphere.numTriangles() + 2 * soup.numTriangles());

  TriMesh all;
  for (const TriMesh& m : flat) {
    uint32_t base = uint32_t(all.vertices.size());
    all.vertices.insert(all.vertices.end(), m.vertices.begin(), m.vertices.end());
    for (Triangle t : m.triangles) all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  // Bounds: contain the flattened geometry.
  Bounds3f b = inst->bounds(), exact = all.bounds();
  for (int a = 0; a < 3; ++a) {
    EXPECT_LE(b.lo[a], exact.lo[a]);
    EXPECT_GE(b.hi[a], exact.hi[a]);
  }
  BruteForceMesh ref(all);
  const double eps = 1e-5 * all.diagonal();
  auto segs = randomSegments(grown(exact, 0.1f), kSeed + 6, 20000);
  OcclusionAgreement a = compareOcclusion(*inst, ref, segs, eps);
  expectAgreement(a, 5);
  std::vector<uint8_t> o1(segs.size()), o2(segs.size());
  inst->occluded(segs, o1);
  flat_scene->occluded(segs, o2);
  size_t differ = 0;
  for (size_t i = 0; i < segs.size(); ++i)
    if (o1[i] != o2[i]) {
      ++differ;
      EXPECT_TRUE(ref.nearBoundary(segs[i], eps)) << "segment " << i;
    }
  EXPECT_LE(differ, 5u);

  // Closest hits: same t, triangle, ids and world-space normal direction.
  size_t hits = 0;
  for (size_t i = 0; i < 3000; ++i) {
    Hit hi = inst->intersect(segs[i]), hf = flat_scene->intersect(segs[i]);
    if (hi.hit != hf.hit || (hi.hit && (hi.prim_id != hf.prim_id || hi.user_id != hf.user_id))) {
      EXPECT_TRUE(ref.ambiguousClosest(segs[i], eps)) << "segment " << i;
      continue;
    }
    if (!hi.hit) continue;
    ++hits;
    const uint32_t k = hf.geom_id;
    EXPECT_EQ(hi.instance_id, k);
    EXPECT_EQ(hi.geom_id, (k % 2) ? p_soup : p_sphere);
    EXPECT_EQ(hi.user_id, 100 + k);
    EXPECT_EQ(hf.instance_id, kInvalidId);
    EXPECT_NEAR(hi.t, hf.t, 1e-4);
    EXPECT_GT(dot(normalize(Vec3d(hi.ng)), normalize(Vec3d(hf.ng))), 0.9999) << "segment " << i;
  }
  EXPECT_GT(hits, 300u);
}

TEST(TraceScene, BatchEqualsSingleAtAnyThreadCount) {
  TraceDevice device;
  TriMesh mesh = triangleSoup(2000, {0, 0, 0}, {1, 1, 1}, 0.2f, kSeed + 7);
  auto scene = flatScene(device, mesh);
  auto segs = randomSegments(grown(mesh.bounds(), 0.2f), kSeed + 8, 30000);
  std::vector<uint8_t> one(segs.size()), two(segs.size());
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    scene->occluded(segs, one);
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    scene->occluded(segs, two);
  }
  EXPECT_EQ(one, two);
  size_t occluded = 0;
  for (size_t i = 0; i < segs.size(); ++i) {
    ASSERT_EQ(scene->occluded(segs[i]), one[i] != 0) << "segment " << i;
    occluded += one[i];
  }
  EXPECT_GT(occluded, 1000u);
  // Ignoring the only object hides everything, in either strategy; ignoring another id nothing.
  std::vector<uint8_t> ign(segs.size());
  scene->occluded(segs, ign, 7);
  for (size_t i = 0; i < segs.size(); ++i) ASSERT_EQ(ign[i], 0) << "segment " << i;
  scene->occluded(segs, ign, 8);
  EXPECT_EQ(ign, one);
  TraceSceneOptions mask_first;
  mask_first.ignore = IgnoreStrategy::kMaskThenFilter;
  auto scene2 = flatScene(device, mesh, mask_first);
  scene2->occluded(segs, ign, 7);
  for (size_t i = 0; i < segs.size(); ++i) ASSERT_EQ(ign[i], 0) << "segment " << i;
  scene2->occluded(segs, ign, 8);
  EXPECT_EQ(ign, one);
}

TEST(TraceScene, CountersCountEveryRay) {
  TraceDevice device;
  auto scene = flatScene(device, icosphere(2));
  EXPECT_EQ(scene->raysTraced(), 0u);
  auto segs = randomSegments(grown(scene->bounds(), 0.5f), kSeed + 9, 12345);
  std::vector<uint8_t> out(segs.size());
  scene->occluded(segs, out);
  EXPECT_EQ(scene->raysTraced(), 12345u);
  for (int i = 0; i < 10; ++i) scene->occluded(segs[i]);
  for (int i = 0; i < 5; ++i) scene->intersect(segs[i]);
  scene->occluded(segs[0], 7);
  EXPECT_EQ(scene->raysTraced(), 12345u + 16u);
  scene->resetCounters();
  EXPECT_EQ(scene->raysTraced(), 0u);
  scene->occluded(std::span<const Segment>(segs).first(100), std::span<uint8_t>(out).first(100));
  EXPECT_EQ(scene->raysTraced(), 100u);
}

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

TEST(TraceScene, EmptySceneOccludesNothing) {
  TraceDevice device;
  TraceSceneBuilder builder(device);
  auto scene = builder.build();
  EXPECT_EQ(scene->triangleCount(), 0u);
  EXPECT_EQ(scene->geometryCount(), 0u);
  EXPECT_TRUE(scene->bounds().empty());
  Segment s{{0, 0, 0}, 0, {1, 1, 1}, std::numeric_limits<float>::infinity()};
  EXPECT_FALSE(scene->occluded(s));
  EXPECT_FALSE(scene->intersect(s).hit);
  std::vector<Segment> segs(1000, s);
  std::vector<uint8_t> out(segs.size(), 1);
  scene->occluded(segs, out);
  for (uint8_t o : out) EXPECT_EQ(o, 0);
  // An empty mesh is allowed and also blocks nothing.
  TriMesh empty;
  empty.source = "empty";
  builder.addMesh(empty, 1);
  auto scene2 = builder.build();
  EXPECT_EQ(scene2->geometryCount(), 1u);
  EXPECT_FALSE(scene2->occluded(s));
}

TEST(TraceScene, BuilderIsReusableAfterBuild) {
  TraceDevice device;
  TraceSceneBuilder builder(device);
  builder.addMesh(box({0, 0, 0}, {1, 1, 1}));
  auto a = builder.build();
  auto b = builder.build();
  Segment s{{-1, 0.5f, 0.5f}, 0, {3, 0, 0}, 1};
  EXPECT_TRUE(a->occluded(s));
  EXPECT_FALSE(b->occluded(s));
  EXPECT_EQ(a->triangleCount(), 12u);
  EXPECT_EQ(b->triangleCount(), 0u);
}

TEST(TraceScene, SegmentEndsAreRespected) {
  TraceDevice device;
  auto scene = flatScene(device, box({0, 0, 0}, {1, 1, 1}));
  // The box face x=0 lies at t = 1 of a segment from x=-1 with dir (1,0,0).
  EXPECT_FALSE(scene->occluded({{-1, 0.3f, 0.4f}, 0, {1, 0, 0}, 0.999f}));
  EXPECT_TRUE(scene->occluded({{-1, 0.3f, 0.4f}, 0, {1, 0, 0}, 1.001f}));
  EXPECT_FALSE(scene->occluded({{-1, 0.3f, 0.4f}, 2.001f, {1, 0, 0}, 5}));  // starts past x=1
  EXPECT_TRUE(scene->occluded({{-1, 0.3f, 0.4f}, 1.999f, {1, 0, 0}, 5}));
  EXPECT_FALSE(scene->occluded({{-1, 0.3f, 0.4f}, 3, {1, 0, 0}, 2}));  // tnear > tfar: empty
  // A long direction: t is in units of dir, not of length.
  Hit h = scene->intersect({{-1, 0.3f, 0.4f}, 0, {10, 0, 0}, 1});
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.t, 0.1f, 1e-6f);
}

TEST(TraceScene, InvalidSegmentsThrowErrors) {
  TraceDevice device;
  auto scene = flatScene(device, icosphere(1));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_THROW(scene->occluded(Segment{{nan, 0, 0}, 0, {1, 0, 0}, 1}), Error);
  EXPECT_THROW(scene->occluded(Segment{{0, 0, 0}, 0, {1, inf, 0}, 1}), Error);
  EXPECT_THROW(scene->occluded(Segment{{0, 0, 0}, nan, {1, 0, 0}, 1}), Error);
  EXPECT_THROW(scene->occluded(Segment{{0, 0, 0}, 0, {1, 0, 0}, nan}), Error);
  EXPECT_THROW(scene->intersect(Segment{{0, 0, -inf}, 0, {1, 0, 0}, 1}), Error);
  EXPECT_NO_THROW(scene->occluded(Segment{{0, 0, 0}, 0, {1, 0, 0}, inf}));  // a ray
  auto segs = randomSegments({{-2, -2, -2}, {2, 2, 2}}, kSeed, 5000);
  segs[4321].dir.y = nan;
  segs[4400].org.x = inf;
  std::vector<uint8_t> out(segs.size());
  try {
    scene->occluded(segs, out);
    FAIL() << "no Error for a NaN segment";
  } catch (const Error& e) {
    // The first invalid index, whatever thread found which.
    EXPECT_NE(std::string(e.what()).find("4321"), std::string::npos) << e.what();
  }
}

TEST(TraceScene, BadMeshesAndInstancesThrowErrors) {
  TraceDevice device;
  TraceSceneBuilder builder(device);
  TriMesh bad = box({0, 0, 0}, {1, 1, 1});
  bad.source = "bad_index.obj";
  bad.triangles[3][1] = 8;
  try {
    builder.addMesh(bad);
    FAIL() << "no Error for an index out of range";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bad_index.obj"), std::string::npos) << e.what();
  }
  TriMesh nan_mesh = box({0, 0, 0}, {1, 1, 1});
  nan_mesh.vertices[2].z = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(builder.addPrototype(nan_mesh), Error);
  EXPECT_THROW(builder.addInstance(0, Affine3f()), Error);  // no prototype yet
  uint32_t p = builder.addPrototype(box({0, 0, 0}, {1, 1, 1}));
  Affine3f xf;
  xf.m[1][2] = std::numeric_limits<float>::infinity();
  EXPECT_THROW(builder.addInstance(p, xf), Error);
  // The builder still works after the errors.
  builder.addInstance(p, Affine3f::translation({5, 0, 0}));
  auto scene = builder.build();
  EXPECT_EQ(scene->triangleCount(), 12u);
  EXPECT_TRUE(scene->occluded({{4, 0.5f, 0.5f}, 0, {3, 0, 0}, 1}));
}

TEST(TraceScene, TriangleCountAndBoundsCountInstances) {
  TraceDevice device;
  TraceSceneBuilder builder(device);
  uint32_t p = builder.addPrototype(icosphere(2));  // 320 triangles
  for (int i = 0; i < 50; ++i) builder.addInstance(p, Affine3f::translation({3.0f * i, 0, 0}), i);
  builder.addMesh(box({-5, -5, -5}, {-4, -4, -4}));
  auto scene = builder.build();
  EXPECT_EQ(scene->triangleCount(), 50u * 320u + 12u);
  EXPECT_EQ(scene->geometryCount(), 51u);
  EXPECT_FLOAT_EQ(scene->bounds().lo.x, -5);
  EXPECT_NEAR(scene->bounds().hi.x, 3.0f * 49 + 1, 1e-4);
  // Every instance is really there.
  for (int i = 0; i < 50; ++i) {
    Hit h = scene->intersect({{3.0f * i, 0, -5}, 0, {0, 0, 1}, 10});
    ASSERT_TRUE(h.hit);
    EXPECT_EQ(h.user_id, uint32_t(i));
    EXPECT_EQ(h.instance_id, uint32_t(i));
  }
}

TEST(TraceDevice, ReportsEmbreeErrorsAsMessages) {
  TraceDevice device;
  EXPECT_EQ(device.takeErrors(), "");
  // An invalid call on the device (a buffer slot that triangles do not have) must become a
  // message, and throwIfError an Error, instead of a silent failure.
  RTCGeometry geom = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 7, RTC_FORMAT_FLOAT3, 12, 3);
  rtcReleaseGeometry(geom);
  std::string messages = device.takeErrors();
  EXPECT_NE(messages.find("RTC_ERROR_INVALID_ARGUMENT"), std::string::npos) << messages;
  EXPECT_EQ(device.takeErrors(), "");
  geom = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 7, RTC_FORMAT_FLOAT3, 12, 3);
  rtcReleaseGeometry(geom);
  EXPECT_THROW(device.throwIfError("testing"), Error);
}

}  // namespace
}  // namespace proxyvis::test

namespace proxyvis::test {
namespace {

// addMesh(mesh, to_world, id) places the vertices straight into Embree's buffer: the scene must
// equal the one built from the transformed copy (the same bits, so the same answers and bounds),
// and a transform that overflows a vertex is refused.
TEST(TraceScene, PlacedMeshEqualsItsTransformedCopy) {
  TraceDevice device;
  const TriMesh soup = triangleSoup(300, {-1, -1, -1}, {1, 1, 1}, 0.3f, kSeed + 21);
  const Affine3f xf = makeTransform(normalize(Vec3f(1, 2, 3)), 0.7f, 1.5f, {3, 0, 1});
  TraceSceneBuilder placed_builder(device), copy_builder(device);
  EXPECT_EQ(placed_builder.addMesh(soup, xf, 5), 0u);
  copy_builder.addMesh(transformed(soup, xf), 5);
  const auto placed = placed_builder.build(), copy = copy_builder.build();
  EXPECT_EQ(placed->triangleCount(), copy->triangleCount());
  const Bounds3f a = placed->bounds(), b = copy->bounds();
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(a.lo[k], b.lo[k]);
    EXPECT_EQ(a.hi[k], b.hi[k]);
  }
  const auto segs = randomSegments(grown(b, 0.2f), kSeed + 22, 5000);
  uint64_t hits = 0;
  for (const Segment& s : segs) {
    const Hit h1 = placed->intersect(s), h2 = copy->intersect(s);
    ASSERT_EQ(h1.hit, h2.hit);
    if (!h1.hit) continue;
    ++hits;
    EXPECT_EQ(h1.t, h2.t);
    EXPECT_EQ(h1.prim_id, h2.prim_id);
    EXPECT_EQ(h1.user_id, 5u);
    EXPECT_TRUE(placed->occluded(s));
    EXPECT_FALSE(placed->occluded(s, 5));  // its own user id is ignored
  }
  EXPECT_GT(hits, 100u);
  TraceSceneBuilder bad(device);
  Affine3f huge = Affine3f::translation({0, 0, 0});
  huge.m[0][0] = 3e38f;  // finite entries whose image of a vertex overflows
  huge.m[0][3] = 3e38f;
  EXPECT_THROW(bad.addMesh(soup, huge, 1), Error);
}

}  // namespace
}  // namespace proxyvis::test
