// lib/trace against an independent reference (brute-force Möller–Trumbore in double) on
// procedural meshes; instances against the same meshes flattened; batch and counters. Ignored
// user ids: ignore_ids_test.cpp; empty scenes, segment ends, bad input: trace_scene_edges_test.cpp.
#include <embree3/rtcore.h>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <limits>

#include "brute_force.h"
#include "test_meshes.h"
#include "trace/trace_scene.h"
#include "trace_compare.h"
#include "util/error.h"

namespace proxyvis::test {
namespace {

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

}  // namespace
}  // namespace proxyvis::test
