// Tightness at 2 % of the input faces (docs/proxy_tightness.md): the outside wrap keeps the
// volume ratio <= 1.25 and the inside wrap >= 0.75 on the bunny and on the genus-3 part, whose
// tunnels must stay open; containment is proven by the exact check, run here on the result.
// The input-bounded collapse is tighter than the nested one and reduces erosion staircases.
#include <gtest/gtest.h>

#include "mesh/validation.h"
#include "proxies/check/containment.h"
#include "proxies/inside/inside_proxy.h"
#include "proxies/outside/outside_proxy.h"
#include "proxies/pipeline/proxy_pipeline.h"
#include "proxies/shared/bounded_simplify.h"
#include "proxies/shared/internal/input_bound.h"
#include "proxies/shared/internal/relax_toward_input.h"
#include "tests/proxies/check_shapes.h"
#include "tests/proxies/gen_test_util.h"

namespace proxyvis {
namespace {

using gen_test::genOptions;
using gen_test::mesh;

struct TightCase {
  const char* mesh;
  ProxyClass kind;
};
void PrintTo(const TightCase& c, std::ostream* os) {
  *os << c.mesh << ' ' << proxyClassName(c.kind);
}

class TightAtTwoPercent : public testing::TestWithParam<TightCase> {};

TEST_P(TightAtTwoPercent, WrapMeetsTheVolumeRatioTarget) {
  const TightCase& c = GetParam();
  const TriMesh& input = mesh(c.mesh);
  ProxyGenOptions o = genOptions(c.kind, "wrap", 0, 2000);
  o.ratio = 0.02;
  const ProxyGenResult r = generateProxy(input, o);
  ASSERT_TRUE(r.verified) << r.report.dump(2);
  // The budget, computed here as the pipeline documents it (2 % of the faces, at least 12).
  EXPECT_LE(r.proxy.numTriangles(), std::max<size_t>(12, input.numTriangles() / 50));
  const bool outside = c.kind == ProxyClass::kOutside;
  EXPECT_EQ(checkContainment(input, r.proxy).verdict,
            outside ? ContainmentVerdict::kContains : ContainmentVerdict::kContained);
  const double ratio = r.proxy.signedVolume() / input.signedVolume();
  if (outside) {
    EXPECT_GE(ratio, 1.0);
    EXPECT_LE(ratio, 1.25);
  } else {
    EXPECT_LE(ratio, 1.0);
    EXPECT_GE(ratio, 0.75);
  }
  // Tunnels stay open: the proxy has the input's genus.
  EXPECT_EQ(validateMesh(r.proxy).genus, validateMesh(input).genus);
}

INSTANTIATE_TEST_SUITE_P(BunnyAndGenus3, TightAtTwoPercent,
                         testing::Values(TightCase{"bunny.off", ProxyClass::kOutside},
                                         TightCase{"bunny.off", ProxyClass::kInside},
                                         TightCase{"hard/3holes.off", ProxyClass::kOutside},
                                         TightCase{"hard/3holes.off", ProxyClass::kInside}));

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

TEST(BoundedSimplify, InputBoundIsTighterThanNesting) {
  const TriMesh& input = mesh("bunny.off");
  const TriMesh wrap = makeWrapProxy(input);
  BoundedSimplifyOptions nested{input.numTriangles() / 50, BoundSide::kOutside};
  BoundedSimplifyOptions bounded = nested;
  bounded.bound = &input;
  const TriMesh a = simplifyBounded(wrap, nested);
  BoundedSimplifyStats stats;
  const TriMesh b = simplifyBounded(wrap, bounded, &stats);
  EXPECT_TRUE(stats.budget_reached);
  EXPECT_LE(b.numTriangles(), bounded.max_faces);
  EXPECT_EQ(checkContainment(input, b).verdict, ContainmentVerdict::kContains);
  // Measured: 1.34 nested, 1.22 bounded; require a clear gain, not the exact numbers.
  EXPECT_LT(b.signedVolume(), a.signedVolume() - 0.05 * input.signedVolume());
  // Cutting corners needs the input test: the bounded result is below the wrap's own volume
  // somewhere, i.e. not nested around it.
  EXPECT_NE(checkContainment(wrap, b).verdict, ContainmentVerdict::kContains);
}

TEST(BoundedSimplify, ReducesAnErosionStaircaseToItsBudget) {
  // The eroded voxel surface of the bunny (~40 k faces of axis-aligned steps): nested collapses
  // stall there (flat steps leave no feasible LP point); the input-bounded phase goes on.
  const TriMesh& input = mesh("bunny.off");
  const TriMesh voxels = makeErodeProxy(input);
  ASSERT_GT(voxels.numTriangles(), 10000u);
  BoundedSimplifyOptions o{input.numTriangles() / 50, BoundSide::kInside};
  o.bound = &input;
  BoundedSimplifyStats stats;
  const TriMesh small = simplifyBounded(voxels, o, &stats);
  EXPECT_TRUE(stats.budget_reached);
  EXPECT_LE(small.numTriangles(), o.max_faces);
  EXPECT_EQ(checkContainment(input, small).verdict, ContainmentVerdict::kContained);
  EXPECT_GT(small.signedVolume(), 0.5 * input.signedVolume());
}

}  // namespace
}  // namespace proxyvis
