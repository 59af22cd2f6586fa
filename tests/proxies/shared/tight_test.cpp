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
#include "tests/proxies/shared/gen_test_util.h"

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
  ASSERT_TRUE(r.verified) << nlohmann::json(r.report).dump(2);
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
