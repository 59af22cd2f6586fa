// The relaxation after a bounded collapse (proxies/shared/internal/relax_toward_input.h): vertex
// moves and edge flips shrink the proxy toward the input and never let the input out. Built into
// proxy_budget_tests, which the sanitizer build runs (the 2 % tightness targets of
// proxy_tight_tests are numbers, run in the Release suite only).
#include <gtest/gtest.h>

#include <random>

#include "mesh/validation.h"
#include "proxies/check/containment.h"
#include "proxies/shared/internal/face_crossing.h"
#include "proxies/shared/internal/input_bound.h"
#include "proxies/shared/internal/relax_toward_input.h"
#include "tests/proxies/check/check_shapes.h"

namespace proxyvis {
namespace {

// A box-shaped proxy whose top is a non-planar quad split along its ridge (corners 4 and 6 high,
// 5 and 7 low), around a smaller box. The relaxation moves the corners onto the input and flips
// edges where that removes volume: the top's diagonal, which no vertex move can change, ends up
// as the valley 5-7; every step keeps the input inside.
TEST(RelaxTowardInput, HugsTheInputAndFlipsTheRidgeWithoutLettingTheInputOut) {
  TriMesh tent;
  tent.source = "tent";
  tent.vertices = {{0, 0, 0}, {1, 0, 0},    {1, 1, 0}, {0, 1, 0},      // bottom
                   {0, 0, 1}, {1, 0, 0.6f}, {1, 1, 1}, {0, 1, 0.6f}};  // top: ridge 4-6
  tent.triangles = {{0, 2, 1}, {0, 3, 2},                              // bottom, facing -z
                    {4, 5, 6}, {4, 6, 7},                              // top, split along 4-6
                    {0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5},
                    {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  ASSERT_GT(tent.signedVolume(), 0);
  const TriMesh input = test::makeBox({0.3f, 0.3f, 0.1f}, {0.7f, 0.7f, 0.4f}, "input");
  ASSERT_EQ(checkContainment(input, tent).verdict, ContainmentVerdict::kContains);

  const cgal::InputBound bound(input);
  TriMesh relaxed = tent;
  EXPECT_GT(cgal::relaxTowardInput(relaxed, bound, 8, nullptr), 0u);
  EXPECT_EQ(checkContainment(input, relaxed).verdict, ContainmentVerdict::kContains);
  const MeshReport v = validateMesh(relaxed);
  EXPECT_TRUE(v.closed);
  EXPECT_TRUE(v.manifold);
  EXPECT_EQ(relaxed.numTriangles(), tent.numTriangles());
  auto hasEdge = [&](uint32_t a, uint32_t b) {
    for (const Triangle& t : relaxed.triangles)
      for (int k = 0; k < 3; ++k)
        if ((t[k] == a && t[(k + 1) % 3] == b) || (t[k] == b && t[(k + 1) % 3] == a)) return true;
    return false;
  };
  EXPECT_TRUE(hasEdge(5, 7)) << "the ridge was not flipped";
  EXPECT_FALSE(hasEdge(4, 6));
  // The proxy of 12 faces can be the input box itself, up to the float rounding of the moves.
  EXPECT_LT(relaxed.signedVolume(), 1.01 * input.signedVolume());
  EXPECT_GT(relaxed.signedVolume(), input.signedVolume());
}

// Not inlined into the test, as in the placer: a midpoint rounded to float. GCC 12 at -O2/-O3
// compiled the plain double(float(v)) of the three components into a copy.
[[gnu::noinline]] Vec3d roundedMidpoint(Vec3d a, Vec3d b) {
  return cgal::roundToFloat((a + b) * 0.5);
}

TEST(RoundToFloat, GivesPointsThatFloatStoresExactly) {
  // Read through volatiles so that the compiler cannot fold the rounding at compile time.
  volatile double in[6] = {4.2677521705627441, 14.336340665817261, -1.0441591739654541,
                           4.2678651809692383, 12.603463053703308, -2.2257871627807617};
  const Vec3d a(in[0], in[1], in[2]), b(in[3], in[4], in[5]);
  const Vec3d m = roundedMidpoint(a, b);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(m[k], double(float(m[k]))) << "component " << k;
    EXPECT_NEAR(m[k], (a[k] + b[k]) / 2, 1e-6);
  }
}

cgal::IdFace face(std::array<Vec3d, 3> p, std::array<uint32_t, 3> id) {
  cgal::IdFace f;
  for (int k = 0; k < 3; ++k) f.p[k] = cgal::Point3(p[k].x, p[k].y, p[k].z), f.id = id;
  return f;
}

// Faces that share corners meet there; whether they cross is decided from the shared corner.
TEST(FacesCross, SharedCornersAreNotCrossingsButFoldsThroughThemAre) {
  const Vec3d o(0, 0, 0);
  const auto a = face({o, Vec3d(2, 0, 0), Vec3d(0, 2, 0)}, {0, 1, 2});
  // One shared corner, the other face standing off the plane: no crossing.
  EXPECT_FALSE(cgal::facesCross(a, face({o, Vec3d(0, 0, 2), Vec3d(-1, -1, 1)}, {0, 3, 4})));
  // One shared corner, the other face passing through a's interior: a crossing.
  EXPECT_TRUE(cgal::facesCross(a, face({o, Vec3d(1, 1, -1), Vec3d(1, 1, 1)}, {0, 3, 4})));
  // One shared corner, the other face lying inside a, in its plane: a crossing.
  EXPECT_TRUE(cgal::facesCross(a, face({o, Vec3d(1, 0.5, 0), Vec3d(0.5, 1, 0)}, {0, 3, 4})));
  // A shared edge: a fold onto a's side in its plane crosses, the other side does not.
  EXPECT_TRUE(
      cgal::facesCross(a, face({Vec3d(2, 0, 0), Vec3d(0, 2, 0), Vec3d(0.5, 0.5, 0)}, {1, 2, 3})));
  EXPECT_FALSE(
      cgal::facesCross(a, face({Vec3d(2, 0, 0), Vec3d(0, 2, 0), Vec3d(2, 2, 0)}, {1, 2, 3})));
  EXPECT_FALSE(
      cgal::facesCross(a, face({Vec3d(2, 0, 0), Vec3d(0, 2, 0), Vec3d(0.5, 0.5, 1)}, {1, 2, 3})));
  // No shared corner: the plain triangle test.
  EXPECT_TRUE(cgal::facesCross(
      a, face({Vec3d(0.5, 0.5, -1), Vec3d(0.5, 0.5, 1), Vec3d(3, 3, 0)}, {5, 6, 7})));
  EXPECT_FALSE(
      cgal::facesCross(a, face({Vec3d(0, 0, 1), Vec3d(2, 0, 1), Vec3d(0, 2, 1)}, {5, 6, 7})));
  // A new face must be a real triangle.
  EXPECT_TRUE(cgal::facesCross(face({o, Vec3d(1, 0, 0), Vec3d(2, 0, 0)}, {0, 8, 9}), a));
}

// The rule of facesCross with CGAL's 3D predicates only: what its floating-point and 2D shortcuts
// must agree with.
bool facesCross3d(const cgal::IdFace& a, const cgal::IdFace& b) {
  using K = cgal::Kernel;
  int shared = 0;
  std::array<int, 3> in_b{-1, -1, -1};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (a.id[i] == b.id[j]) in_b[i] = j, ++shared;
  const K::Triangle_3 ta(a.p[0], a.p[1], a.p[2]), tb(b.p[0], b.p[1], b.p[2]);
  if (ta.is_degenerate()) return true;
  if (tb.is_degenerate()) return false;
  if (shared == 0) return CGAL::do_intersect(ta, tb);
  if (shared == 1) {
    const int i = in_b[0] >= 0 ? 0 : (in_b[1] >= 0 ? 1 : 2), j = in_b[i];
    return CGAL::do_intersect(K::Segment_3(a.p[(i + 1) % 3], a.p[(i + 2) % 3]), tb) ||
           CGAL::do_intersect(K::Segment_3(b.p[(j + 1) % 3], b.p[(j + 2) % 3]), ta);
  }
  const int i = in_b[0] < 0 ? 0 : (in_b[1] < 0 ? 1 : 2);
  int j = 0;
  while (j < 3 && (b.id[j] == a.id[(i + 1) % 3] || b.id[j] == a.id[(i + 2) % 3])) ++j;
  const cgal::Point3 &u = a.p[(i + 1) % 3], &w = a.p[(i + 2) % 3];
  return CGAL::coplanar(u, w, a.p[i], b.p[j]) &&
         CGAL::coplanar_orientation(u, w, a.p[i], b.p[j]) == CGAL::POSITIVE;
}

// Voxel-like faces: corners on a grid of step 0.1 (not exact in binary), all in one plane
// x_k = c (the 2D shortcut) or, one time in four, with one corner off it (the 3D path), sharing
// 0, 1 or 2 corners; collinear and repeated corners included. 20,000 pairs, fixed seed.
TEST(FacesCross, ShortcutsAgreeWithThe3DPredicatesOnGridFaces) {
  std::mt19937_64 rng(12);
  auto coord = [&] { return 0.1 * double(int(rng() % 7) - 3); };
  int counts[2][3] = {};  // [crossing][shared corners]
  for (int n = 0; n < 20000; ++n) {
    const int axis = int(rng() % 3);
    const double c = coord();
    auto point = [&] {
      Vec3d p(coord(), coord(), coord());
      p[axis] = c;
      return p;
    };
    std::array<Vec3d, 3> pa{point(), point(), point()}, pb{point(), point(), point()};
    std::array<uint32_t, 3> ib{3, 4, 5};
    const int shared = int(rng() % 3);
    for (int s = 0; s < shared; ++s) {  // b's corner s is a's corner (s + 1) % 3, reversed order
      const int k = (s + 1) % 3;
      pb[2 - s] = pa[k];
      ib[2 - s] = uint32_t(k);
    }
    if (rng() % 4 == 0) pb[rng() % 3][axis] += 0.1;  // off the plane: the 3D path
    const cgal::IdFace a = face(pa, {0, 1, 2}), b = face(pb, ib);
    const bool expected = facesCross3d(a, b);
    ASSERT_EQ(cgal::facesCross(a, b), expected) << "pair " << n;
    ++counts[expected][shared];
  }
  for (int shared = 0; shared < 3; ++shared)
    for (int crossing = 0; crossing < 2; ++crossing)
      EXPECT_GT(counts[crossing][shared], 100) << shared << " shared, crossing " << crossing;
}

TEST(FacesCross, DegenerateFacesAreFoundAsCGALFindsThem) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-1, 1);
  int degenerate = 0;
  for (int n = 0; n < 20000; ++n) {
    // One time in four on integers, where the collinear ones are exactly collinear.
    const bool grid = rng() % 4 == 0;
    auto value = [&] { return grid ? double(int(rng() % 17) - 8) : u(rng); };
    const Vec3d a(value(), value(), value()), b(value(), value(), value());
    const double t = grid ? double(int(rng() % 5) - 2) : (rng() % 2 ? 0.5 : u(rng));
    // On the line through a and b, up to rounding; or off it by 1e-12 or more.
    const Vec3d off = rng() % 2 ? Vec3d(0, 0, 0) : Vec3d(u(rng), u(rng), u(rng)) * 1e-12;
    const Vec3d c = a + (b - a) * t + off;
    const cgal::Point3 pa(a.x, a.y, a.z), pb(b.x, b.y, b.z), pc(c.x, c.y, c.z);
    const bool expected = CGAL::collinear(pa, pb, pc);
    ASSERT_EQ(cgal::isDegenerate(pa, pb, pc), expected) << "triangle " << n;
    degenerate += expected;
  }
  EXPECT_GT(degenerate, 100);
}

}  // namespace
}  // namespace proxyvis
