// Inside proxies: the seeded inner wrap and the erosion on the closed meshes of data/, with and
// without a budget, proven by the exact check; open input gives the documented Error unless
// holes are filled (bun_zipper: 223 boundary edges, MANIFEST.md).
#include <gtest/gtest.h>

#include <string>

#include "mesh/validation.h"
#include "proxies/check/containment.h"
#include "proxies/inside/inside_proxy.h"
#include "proxies/pipeline/proxy_pipeline.h"
#include "tests/proxies/shared/gen_test_util.h"
#include "util/error.h"

namespace proxyvis {
namespace {

using gen_test::genOptions;
using gen_test::mesh;
// The size of a case is the wrap's offset (fraction of the diagonal).
using Case = gen_test::ContainmentCase;

class InsideContainment : public testing::TestWithParam<Case> {};

TEST_P(InsideContainment, ExactCheckProvesContainment) {
  if (gen_test::skippedUnderSanitizers(GetParam().mesh)) GTEST_SKIP() << "Release suite only";
  const auto [o, r] = gen_test::runContainmentCase(
      GetParam(), ProxyClass::kInside, &ProxyGenOptions::offset, ContainmentVerdict::kContained);
  if (o.max_faces > 0 && *r.report.budget_reached) {
    EXPECT_LE(r.proxy.numTriangles(), o.max_faces);
  }
  const double ratio = *r.report.volume_ratio;
  EXPECT_GT(ratio, 0.3);
  EXPECT_LE(ratio, 1.0);
  if (GetParam().volume_ratio_bound > 0) {
    EXPECT_GE(ratio, GetParam().volume_ratio_bound);
  }
}

// The dragon's 2 % budget (2,000 faces) was met by nested collapses alone; the tight ones after
// them are what bring it to 0.856 (0.841 without), which its case guards.
INSTANTIATE_TEST_SUITE_P(ClosedMeshes, InsideContainment,
                         testing::Values(Case{"bunny.off", "wrap", 0, 0},
                                         Case{"bunny.off", "wrap", 0.05, 1.0 / 300},
                                         Case{"spot_triangulated.obj", "wrap", 0.03, 0},
                                         Case{"bunny.off", "erode", 0, 0},
                                         Case{"spot_triangulated.obj", "erode", 0, 0},
                                         Case{"bunny.off", "erode", 0.05, 0},
                                         Case{"dragon.drc", "wrap", 0.02, 0, 0.85}));

struct BudgetCase {
  const char* mesh;
  const char* method;
  size_t max_faces;
};
void PrintTo(const BudgetCase& c, std::ostream* os) {
  *os << c.mesh << ' ' << c.method << " max_faces " << c.max_faces;
}

class InsideBudget : public testing::TestWithParam<BudgetCase> {};

TEST_P(InsideBudget, IsRespected) {
  const BudgetCase c = GetParam();
  if (gen_test::skippedUnderSanitizers(c.mesh)) GTEST_SKIP() << "Release suite only";
  const ProxyGenResult r =
      generateProxy(mesh(c.mesh), genOptions(ProxyClass::kInside, c.method, c.max_faces, 1000));
  EXPECT_TRUE(*r.report.budget_reached) << nlohmann::json(r.report).dump(2);
  EXPECT_LE(r.proxy.numTriangles(), c.max_faces);
  EXPECT_TRUE(r.verified);
}

// Erode: the voxel surface has ~40 k faces; the inward collapse must bring it to the budget
// without self-intersections (the 2-ring filter) and keep it inside.
INSTANTIATE_TEST_SUITE_P(Methods, InsideBudget,
                         testing::Values(BudgetCase{"spot_triangulated.obj", "erode", 1500},
                                         BudgetCase{"bunny.off", "wrap", 300}));

TEST(InsideOpenInput, IsAnErrorNamingBoundaryEdges) {
  const TriMesh& input = mesh("bun_zipper.ply");
  ProxyGenOptions o;
  o.kind = ProxyClass::kInside;
  try {
    generateProxy(input, o);
    FAIL() << "an open mesh must not give an inside proxy";
  } catch (const CheckFailed&) {
    FAIL() << "expected a bad-input Error, got CheckFailed";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("223 boundary edges"), std::string::npos) << what;
    EXPECT_NE(what.find("--fill-holes"), std::string::npos) << what;
    EXPECT_NE(what.find("--kind outside"), std::string::npos) << what;
    EXPECT_EQ(e.exitCode(), kExitBadInput);
  }
  EXPECT_EQ(validateMesh(input).boundary_edges, 223u);
}

TEST(InsideOpenInput, FillHolesMakesBunZipperWork) {
  const TriMesh& input = mesh("bun_zipper.ply");
  size_t holes = 0;
  const TriMesh filled = fillHoles(input, &holes);
  EXPECT_EQ(validateMesh(filled).boundary_edges, 0u);
  EXPECT_GT(holes, 0u);
  ProxyGenOptions o = genOptions(ProxyClass::kInside, "", 0, 2000);
  o.fill_holes = true;
  const ProxyGenResult r = generateProxy(input, o);
  EXPECT_TRUE(r.verified) << nlohmann::json(r.report).dump(2);
  // Inside the filled mesh, but rays through the holes reach it: written as general.
  EXPECT_EQ(r.report.written_class, ProxyClass::kGeneral);
  EXPECT_EQ(checkContainment(filled, r.proxy).verdict, ContainmentVerdict::kContained);
  EXPECT_EQ(*r.report.holes_filled, holes);
}

TEST(InsideErode, ErosionShrinksTheVolume) {
  // More erosion leaves less inside: a property, not a stored number.
  const TriMesh& input = mesh("spot_triangulated.obj");
  ErodeOptions small, large;
  small.erosion = small.voxel;
  large.erosion = 3 * large.voxel;
  const double v_small = makeErodeProxy(input, small).signedVolume();
  const double v_large = makeErodeProxy(input, large).signedVolume();
  EXPECT_GT(v_small, v_large);
  EXPECT_LT(v_small, input.signedVolume());
  ErodeOptions everything;
  everything.erosion = 1.0;  // the whole diagonal: nothing can be left
  EXPECT_THROW(makeErodeProxy(input, everything), Error);
}

}  // namespace
}  // namespace proxyvis
