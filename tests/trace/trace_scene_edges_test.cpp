// lib/trace at its edges: empty scenes, a reused builder, segment ends, invalid segments, bad
// meshes and instances, counts and bounds with instances, Embree's errors as messages, and a
// placed mesh equal to its transformed copy.
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
