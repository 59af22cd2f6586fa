// Outside proxies: every method on every closed mesh of data/ (dragon only for a few cases: it
// is the 100 k-face one) keeps containment, proven by the exact CGAL check, with and without a
// face budget; open non-manifold foliage is wrapped; the hull is pushed off the surface.
#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

#include "proxies/check/containment.h"
#include "proxies/outside/outside_proxy.h"
#include "proxies/pipeline/proxy_pipeline.h"
#include "proxies/shared/bounded_simplify.h"
#include "tests/proxies/shared/gen_test_util.h"
#include "util/error.h"

namespace proxyvis {
namespace {

using gen_test::genOptions;
using gen_test::mesh;
// The size of a case is the wrap's alpha (fraction of the diagonal).
using Case = gen_test::ContainmentCase;

class OutsideContainment : public testing::TestWithParam<Case> {};

TEST_P(OutsideContainment, ExactCheckProvesContainment) {
  if (gen_test::skippedUnderSanitizers(GetParam().mesh)) GTEST_SKIP() << "Release suite only";
  const auto [o, r] = gen_test::runContainmentCase(
      GetParam(), ProxyClass::kOutside, &ProxyGenOptions::alpha, ContainmentVerdict::kContains);
  if (o.max_faces > 0) {
    EXPECT_LE(r.proxy.numTriangles(), o.max_faces);
  }
  EXPECT_GE(*r.report.volume_ratio, 1.0);
  EXPECT_EQ(r.report.faces, r.proxy.numTriangles());
}

INSTANTIATE_TEST_SUITE_P(
    ClosedMeshes, OutsideContainment,
    testing::Values(Case{"bunny.off", "hull", 0, 0}, Case{"bunny.off", "hull", 0.02, 0},
                    Case{"bunny.off", "wrap", 0, 0}, Case{"bunny.off", "wrap", 0.05, 0},
                    Case{"bunny.off", "wrap", 0.02, 1.0 / 20},
                    Case{"spot_triangulated.obj", "hull", 0.05, 0},
                    Case{"spot_triangulated.obj", "wrap", 0, 1.0 / 30},
                    Case{"spot_triangulated.obj", "wrap", 0.03, 0},
                    Case{"dragon.drc", "hull", 0, 0}, Case{"dragon.drc", "wrap", 0.02, 0},
                    Case{"bunny.off", "convex-parts", 0, 0},
                    Case{"bunny.off", "convex-parts", 0.02, 0},
                    Case{"spot_triangulated.obj", "convex-parts", 0.02, 0}));

// The union of convex pieces against the single hull: each piece is the hull of the input in one
// cell of a partition of space, so the union is tighter; and it is proved by the exact check.
TEST(OutsideConvexParts, UnionIsTighterThanTheHullAndContainsTheInput) {
  for (const char* name : {"hard/cow.off", "hard/3holes.off", "spot_triangulated.obj"}) {
    SCOPED_TRACE(name);
    const TriMesh& input = mesh(name);
    ConvexPartsOptions options;
    options.max_parts = 8;
    ConvexPartsStats stats;
    const TriMesh parts = makeConvexPartsProxy(input, options, &stats);
    EXPECT_GE(stats.parts, 2u);
    EXPECT_LE(stats.parts, 8u);
    EXPECT_EQ(checkContainment(input, parts).verdict, ContainmentVerdict::kContains);
    const double hull = makeHullProxy(input).signedVolume();
    EXPECT_LT(parts.signedVolume(), 0.95 * hull);
    EXPECT_GT(parts.signedVolume(), input.signedVolume());
  }
}

TEST(OutsideConvexParts, OnePartIsTheGrownHull) {
  const TriMesh& input = mesh("bunny.off");
  ConvexPartsOptions options;
  options.max_parts = 1;
  ConvexPartsStats stats;
  const TriMesh one = makeConvexPartsProxy(input, options, &stats);
  EXPECT_EQ(stats.parts, 1u);
  EXPECT_EQ(checkContainment(input, one).verdict, ContainmentVerdict::kContains);
  // One piece of at most 96 faces around the hull: more volume than the hull, not much more.
  const double hull = makeHullProxy(input).signedVolume();
  EXPECT_LE(one.numTriangles(), 96u);
  EXPECT_GT(one.signedVolume(), hull);
  EXPECT_LT(one.signedVolume(), hull * 1.25);
}

// Two runs in one process see different heap layouts, which CGAL's quickhull and corefinement
// order by: the pieces' hulls must not depend on them (the cut planes make coplanar facets).
TEST(OutsideConvexParts, SameInputSameProxy) {
  const TriMesh& input = mesh("hard/cow.off");
  ConvexPartsOptions options;
  options.max_parts = 6;
  const TriMesh a = makeConvexPartsProxy(input, options);
  std::vector<TriMesh> noise(50, input);  // moves the heap between the runs
  const TriMesh b = makeConvexPartsProxy(input, options);
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  EXPECT_TRUE(a.vertices == b.vertices);
  EXPECT_TRUE(a.triangles == b.triangles);
}

TEST(OutsideConvexParts, PartsOutOfRangeAreRefused) {
  ConvexPartsOptions options;
  options.max_parts = 0;
  EXPECT_THROW(makeConvexPartsProxy(mesh("bunny.off"), options), Error);
  options.max_parts = kMaxConvexParts + 1;
  EXPECT_THROW(makeConvexPartsProxy(mesh("bunny.off"), options), Error);
}

TEST(OutsideHull, UnpushedHullTouchesTheSurface) {
  // Why HullOptions::epsilon exists: CGAL's hull faces lie on input faces, which the exact
  // test reports as intersecting; the pushed hull is strictly outside.
  const TriMesh& input = mesh("bunny.off");
  HullOptions touching;
  touching.epsilon = 0;
  EXPECT_EQ(checkContainment(input, makeHullProxy(input, touching)).verdict,
            ContainmentVerdict::kIntersecting);
  EXPECT_EQ(checkContainment(input, makeHullProxy(input)).verdict, ContainmentVerdict::kContains);
}

TEST(OutsideFoliage, OpenNonManifoldLeavesAreWrapped) {
  // Leaf cards: open, unshared vertices, nothing closed. The wrap needs no closed input and must
  // contain every vertex (checkContainment's definition for an open original).
  const TriMesh& input = mesh("YELLOWFLOWER1.ply");
  const ProxyGenResult r = generateProxy(input, genOptions(ProxyClass::kOutside, "", 0, 2000));
  EXPECT_FALSE(r.report.input.closed);
  EXPECT_TRUE(r.verified) << nlohmann::json(r.report).dump(2);
  EXPECT_EQ(checkContainment(input, r.proxy).verdict, ContainmentVerdict::kContains);
  EXPECT_FALSE(r.report.volume_ratio);  // the open original has no volume
}

TEST(OutsideBudget, BoundedSimplifyOnlyGrowsTheVolume) {
  const TriMesh& input = mesh("bunny.off");
  const TriMesh wrap = makeWrapProxy(input);
  BoundedSimplifyStats stats;
  const TriMesh small =
      simplifyBounded(wrap, {wrap.numTriangles() / 10, BoundSide::kOutside}, &stats);
  EXPECT_TRUE(stats.budget_reached);
  EXPECT_LE(small.numTriangles(), wrap.numTriangles() / 10);
  EXPECT_GT(stats.collapses, 0u);
  EXPECT_GE(small.signedVolume(), wrap.signedVolume());
  // Not checked against `wrap`: kept faces are shared with it (touching). Against the input:
  EXPECT_EQ(checkContainment(input, small).verdict, ContainmentVerdict::kContains);
}

TEST(OutsideOptions, BadParametersAreErrors) {
  const TriMesh& input = mesh("bunny.off");
  WrapOptions w;
  w.alpha = 0;
  EXPECT_THROW(makeWrapProxy(input, w), Error);
  EXPECT_THROW(makeHullProxy(TriMesh{}), Error);
  ProxyGenOptions o;
  o.method = "qem";  // not an outside method
  EXPECT_THROW(generateProxy(input, o), Error);
}

}  // namespace
}  // namespace proxyvis
