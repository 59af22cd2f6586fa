// Exact containment on shapes whose relation is known by construction (a sphere, boxes around
// and inside it, shifted and far-away copies), plus bad input.
#include "proxies/check/containment.h"

#include <gtest/gtest.h>

#include "tests/proxies/check/check_shapes.h"
#include "util/error.h"

namespace proxyvis {
namespace {

using test::makeBox;
using test::makeSphere;
using test::transformed;
using test::withHole;

const Vec3f kCenter{0.5f, -0.25f, 1.0f};

TriMesh sphere() {
  return makeSphere(kCenter, 1.0f, 32, 16, "sphere");
}

TEST(Containment, BoundingBoxContainsSphere) {
  // The box is 1 % larger than the sphere's radius in every direction: no contact.
  TriMesh box = makeBox(kCenter - Vec3f(1.01f, 1.01f, 1.01f), kCenter + Vec3f(1.01f, 1.01f, 1.01f));
  ContainmentResult r = checkContainment(sphere(), box);
  EXPECT_EQ(r.verdict, ContainmentVerdict::kContains) << r.detail;
  EXPECT_TRUE(r.original_closed);
  EXPECT_TRUE(r.proxy_closed);
  EXPECT_EQ(r.intersecting_face_pairs, 0u);
}

TEST(Containment, ScaledUpCopyContains) {
  TriMesh s = sphere();
  ContainmentResult r = checkContainment(s, transformed(s, kCenter, 1.05f, {}, "bigger"));
  EXPECT_EQ(r.verdict, ContainmentVerdict::kContains) << r.detail;
}

TEST(Containment, SmallBoxDeepInsideIsContained) {
  // Inscribed cube of a unit sphere has half-edge 1/sqrt(3) = 0.577; 0.5 keeps a margin above the
  // faceting error of a 32x16 sphere (cos(pi/16) = 0.98).
  TriMesh box = makeBox(kCenter - Vec3f(0.5f, 0.5f, 0.5f), kCenter + Vec3f(0.5f, 0.5f, 0.5f));
  ContainmentResult r = checkContainment(sphere(), box);
  EXPECT_EQ(r.verdict, ContainmentVerdict::kContained) << r.detail;
}

TEST(Containment, ShiftedCopyIntersects) {
  TriMesh s = sphere();
  ContainmentResult r = checkContainment(s, transformed(s, kCenter, 1.0f, {0.3f, 0, 0}, "shift"));
  EXPECT_EQ(r.verdict, ContainmentVerdict::kIntersecting);
  EXPECT_GT(r.intersecting_face_pairs, 0u);
  EXPECT_NE(r.detail.find("intersecting"), std::string::npos) << r.detail;
}

TEST(Containment, IdenticalCopyTouchesEverywhere) {
  // Equal surfaces touch: not a strict containment either way.
  TriMesh s = sphere();
  ContainmentResult r = checkContainment(s, s);
  EXPECT_EQ(r.verdict, ContainmentVerdict::kIntersecting);
  EXPECT_GE(r.intersecting_face_pairs, s.numTriangles());
}

TEST(Containment, FarAwayCopyIsDisjoint) {
  TriMesh s = sphere();
  ContainmentResult r = checkContainment(s, transformed(s, kCenter, 1.0f, {10, 0, 0}, "far"));
  EXPECT_EQ(r.verdict, ContainmentVerdict::kDisjoint);
  EXPECT_NE(r.detail.find("mismatched"), std::string::npos) << r.detail;
}

TEST(Containment, CavityIsNotContainment) {
  // The "proxy" is a big box with a small inverted box inside it (a solid with a cavity). The
  // sphere lies in the solid part, but the cavity lies inside the sphere: a segment starting in
  // the cavity could hit the sphere without hitting the proxy, so this is no containment.
  TriMesh proxy = makeBox(kCenter - Vec3f(2, 2, 2), kCenter + Vec3f(2, 2, 2), "shell");
  TriMesh inner = makeBox(kCenter - Vec3f(0.2f, 0.2f, 0.2f), kCenter + Vec3f(0.2f, 0.2f, 0.2f));
  const uint32_t off = uint32_t(proxy.vertices.size());
  proxy.vertices.insert(proxy.vertices.end(), inner.vertices.begin(), inner.vertices.end());
  for (Triangle t : inner.triangles)
    proxy.triangles.push_back({t[0] + off, t[2] + off, t[1] + off});
  ContainmentResult r = checkContainment(sphere(), proxy);
  EXPECT_EQ(r.verdict, ContainmentVerdict::kDisjoint) << r.detail;
}

TEST(Containment, OpenProxyIsUndecidable) {
  TriMesh s = sphere();
  ContainmentResult r =
      checkContainment(s, withHole(transformed(s, kCenter, 1.1f, {}, "big"), "open"));
  EXPECT_EQ(r.verdict, ContainmentVerdict::kUndecidable);
  EXPECT_FALSE(r.proxy_closed);
  EXPECT_NE(r.detail.find("not closed"), std::string::npos) << r.detail;
}

TEST(Containment, OpenOriginalInsideClosedProxyIsContained) {
  TriMesh open = withHole(sphere(), "open original");
  TriMesh box = makeBox(kCenter - Vec3f(2, 2, 2), kCenter + Vec3f(2, 2, 2));
  ContainmentResult r = checkContainment(open, box);
  EXPECT_EQ(r.verdict, ContainmentVerdict::kContains) << r.detail;
  EXPECT_FALSE(r.original_closed);
}

TEST(Containment, OpenOriginalCannotContain) {
  TriMesh open = withHole(sphere(), "open original");
  TriMesh box = makeBox(kCenter - Vec3f(0.3f, 0.3f, 0.3f), kCenter + Vec3f(0.3f, 0.3f, 0.3f));
  ContainmentResult r = checkContainment(open, box);
  EXPECT_EQ(r.verdict, ContainmentVerdict::kDisjoint) << r.detail;
}

TEST(Containment, UnweldedClosedMeshIsClosed) {
  // Every triangle with its own three vertex records (as many PLY exporters write): exactly equal
  // positions are welded, so the box is still closed.
  TriMesh box = makeBox(kCenter - Vec3f(3, 3, 3), kCenter + Vec3f(3, 3, 3));
  TriMesh soup;
  soup.source = "soup";
  for (Triangle t : box.triangles) {
    const uint32_t base = uint32_t(soup.vertices.size());
    for (uint32_t i : t) soup.vertices.push_back(box.vertices[i]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  ContainmentResult r = checkContainment(sphere(), soup);
  EXPECT_TRUE(r.proxy_closed);
  EXPECT_EQ(r.verdict, ContainmentVerdict::kContains) << r.detail;
}

TEST(Containment, DegenerateTriangleCrossingIsFound) {
  // A collinear (zero-area) sliver added to the original, reaching through the proxy's surface:
  // exact triangle-triangle tests reject degenerate triangles, so it is tested edge by edge.
  TriMesh original = sphere();
  const uint32_t n = uint32_t(original.vertices.size());
  original.vertices.push_back(kCenter);
  original.vertices.push_back(kCenter + Vec3f(1, 0, 0));
  original.vertices.push_back(kCenter + Vec3f(3, 0, 0));
  original.triangles.push_back({n, n + 1, n + 2});
  TriMesh box = makeBox(kCenter - Vec3f(2, 2, 2), kCenter + Vec3f(2, 2, 2));
  ContainmentResult r = checkContainment(original, box);
  EXPECT_EQ(r.verdict, ContainmentVerdict::kIntersecting) << r.detail;
  EXPECT_EQ(r.intersecting_face_pairs, 2u);  // the two triangles of the box's +x face
}

TEST(Containment, EmptyMeshIsAnError) {
  TriMesh empty;
  empty.source = "empty.ply";
  EXPECT_THROW(checkContainment(sphere(), empty), Error);
  EXPECT_THROW(checkContainment(empty, sphere()), Error);
}

TEST(Containment, IndexOutOfRangeIsAnError) {
  TriMesh bad = sphere();
  bad.triangles.push_back({0, 1, 100000});
  EXPECT_THROW(checkContainment(sphere(), bad), Error);
}

TEST(Containment, Names) {
  EXPECT_STREQ(containmentName(ContainmentVerdict::kContains), "contains");
  EXPECT_STREQ(containmentName(ContainmentVerdict::kContained), "contained");
  EXPECT_STREQ(containmentName(ContainmentVerdict::kIntersecting), "intersecting");
  EXPECT_STREQ(containmentName(ContainmentVerdict::kDisjoint), "disjoint");
  EXPECT_STREQ(containmentName(ContainmentVerdict::kUndecidable), "undecidable");
}

}  // namespace
}  // namespace proxyvis
