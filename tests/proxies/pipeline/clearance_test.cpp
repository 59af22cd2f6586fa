// The clearance (docs/clearance.md) on a synthetic case built so that the two readings of a
// text file disagree: a box whose top has a dent vertex D given as a decimal that rounds to float
// above a plane and to double below it, and an inside proxy whose top face passes through that
// plane, within an ulp of the float reading. Proved in the float reading alone, the proxy is
// wrong in the double one; moved away by the clearance it holds in both, and generateProxy,
// given both readings, writes a proxy that holds in both.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "mesh/io/double_reading.h"
#include "mesh/io/mesh_io.h"
#include "proxies/check/containment.h"
#include "proxies/check/scene_segments.h"
#include "proxies/pipeline/clearance.h"
#include "proxies/pipeline/proxy_pipeline.h"
#include "tests/support/sanitizer_build.h"
#include "tests/support/scratch_dir.h"

namespace proxyvis {
namespace {

// Floats just below 1 are 2^-24 apart.
constexpr double kUlp = 1.0 / (1 << 24);
// The proxy's inset from the box's sides, and its top's heights at two opposite corners.
constexpr double kInset = 1.0 / 256;
constexpr double kTopLow = 1 - 2 * kUlp, kTopHigh = 1 - kUlp;
// The dent's position on the proxy top's diagonal, and the proxy's height there: a quarter of
// the way from (inset, inset) at 1 - ulp to (1 - inset, 1 - inset) at 1 - 2 ulp, about 1 - 1.25
// ulp: between two floats, where a float's rounding cannot reach.
constexpr double kDentXY = 0.25;
constexpr double kWeight = (kDentXY - kInset) / (1 - 2 * kInset);
const double kProxyAtDent = kTopHigh + (kTopLow - kTopHigh) * kWeight;
// D's height as written in the file: 1 - 1.4 ulp. Rounded to float: 1 - ulp (0.4 ulp away,
// against 0.6 for 1 - 2 ulp), above the proxy; read in double: below it.
const std::string kDentText = "0.99999991655349731445";

// The box [0,1]^3; its top is a fan of four triangles around D (vertex 8).
void writeInput(const std::filesystem::path& file) {
  std::ofstream out(file);
  out << "OFF\n9 14 0\n"
         "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"  // bottom 0-3
         "0 0 1\n1 0 1\n1 1 1\n0 1 1\n"  // top corners 4-7
      << "0.25 0.25 " << kDentText << "\n"
      << "3 0 2 1\n3 0 3 2\n"                     // bottom (outward: -z)
      << "3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n"   // sides
      << "3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n"   //
      << "3 4 5 8\n3 5 6 8\n3 6 7 8\n3 7 4 8\n";  // top fan around D
}

// The inside proxy: the box inset by kInset on its sides and bottom, its top two triangles split
// along the diagonal through D, at kTopHigh at (inset, inset) and kTopLow at the opposite corner.
TriMesh tightProxy() {
  const float a = float(kInset), b = float(1 - kInset);
  TriMesh m;
  m.source = "tight proxy";
  m.vertices = {{a, a, a},
                {b, a, a},
                {b, b, a},
                {a, b, a},
                {a, a, float(kTopHigh)},
                {b, a, float(kTopHigh - kUlp / 2)},
                {b, b, float(kTopLow)},
                {a, b, float(kTopHigh - kUlp / 2)}};
  // kTopHigh - ulp/2 is no float: the side corners round to a neighbour, any is fine (they are
  // far below the input's top there); the diagonal's two corners are exact.
  m.vertices[5].z = m.vertices[7].z = float(kTopHigh);
  m.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5},
                 {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}, {4, 5, 6}, {4, 6, 7}};
  return m;
}

class Clearance : public testing::Test {
 protected:
  void SetUp() override {
    writeInput(file_);
    input_ = loadMesh(file_);
    in_double_ = readDoublePositions(file_, input_);
  }
  test::ScratchDir dir_;
  std::filesystem::path file_ = dir_.path() / "dented_box.off";
  TriMesh input_;
  std::vector<Vec3d> in_double_;
};

ContainmentResult inDouble(const TriMesh& input, const std::vector<Vec3d>& positions,
                           const TriMesh& proxy) {
  ContainmentOptions o;
  o.original_positions = &positions;
  return checkContainment(input, proxy, o);
}

TEST_F(Clearance, TheDentRoundsToOppositeSidesOfTheProxyTop) {
  ASSERT_EQ(input_.vertices.size(), 9u);
  const double as_float = input_.vertices[8].z, as_double = in_double_[8].z;
  EXPECT_EQ(as_float, kTopHigh);  // rounded up to 1 - ulp
  EXPECT_EQ(as_double, std::strtod(kDentText.c_str(), nullptr));
  EXPECT_GT(as_float, kProxyAtDent);                        // above the proxy's top ...
  EXPECT_LT(as_double, kProxyAtDent);                       // ... and below it
  EXPECT_NEAR(kProxyAtDent, 1 - 1.25 * kUlp, 0.01 * kUlp);  // between two floats
  // Every other vertex reads the same both ways (short decimals).
  for (size_t i = 0; i < 8; ++i) EXPECT_EQ(Vec3d(input_.vertices[i]), in_double_[i]) << i;
}

TEST_F(Clearance, WithinAnUlpTheClassHoldsInOneReadingOnly) {
  const TriMesh proxy = tightProxy();
  const ContainmentResult f = checkContainment(input_, proxy);
  EXPECT_EQ(f.verdict, ContainmentVerdict::kContained) << f.detail;
  const ContainmentResult d = inDouble(input_, in_double_, proxy);
  EXPECT_NE(d.verdict, ContainmentVerdict::kContained) << d.detail;
}

TEST_F(Clearance, MovedAwayByTheClearanceItHoldsInBoth) {
  const double clearance = clearanceDistance(input_, std::nullopt, std::nullopt);
  EXPECT_DOUBLE_EQ(clearance, kDefaultClearanceUlps * std::ldexp(1.0, -23));  // ulp at 1
  const TriMesh proxy = pushedAway(tightProxy(), ProxyClass::kInside, clearance);
  ContainmentOptions o;
  o.separation_cap = 2 * clearance;
  const ContainmentResult f = checkContainment(input_, proxy, o);
  EXPECT_EQ(f.verdict, ContainmentVerdict::kContained) << f.detail;
  ASSERT_TRUE(f.separation.has_value());
  EXPECT_GE(*f.separation, clearance);
  EXPECT_EQ(inDouble(input_, in_double_, proxy).verdict, ContainmentVerdict::kContained);
}

TEST_F(Clearance, TheTightProxyHasLessSeparationThanTheClearance) {
  ContainmentOptions o;
  o.separation_cap = 1;
  const ContainmentResult f = checkContainment(input_, tightProxy(), o);
  ASSERT_TRUE(f.separation.has_value());
  // The dent is 0.25 ulp above the proxy's top: a distance that double arithmetic cannot resolve
  // from coordinates of 1 (its square, 2e-16, is the squared coordinates' rounding), measured as
  // about 0; far below the clearance, which it resolves to 1e-4.
  EXPECT_LT(*f.separation, kUlp);
  EXPECT_LT(*f.separation, clearanceDistance(input_, std::nullopt, std::nullopt) / 10);
}

TEST_F(Clearance, GenerateProxyProvesBothReadingsAndReportsTheClearance) {
  for (const ProxyClass kind : {ProxyClass::kOutside, ProxyClass::kInside}) {
    ProxyGenOptions o;
    o.kind = kind;
    o.max_faces = 12;
    o.hausdorff_samples = 200;
    o.input_double = &in_double_;
    const ProxyGenResult r = generateProxy(input_, o);
    ASSERT_TRUE(r.verified) << proxyClassName(kind);
    const ProxyChecks& c = r.report.checks;
    ASSERT_TRUE(c.clearance && c.separation && c.containment_double);
    EXPECT_GE(*c.separation, *c.clearance);
    EXPECT_EQ(*c.containment_double, *c.containment);
    EXPECT_EQ(r.report.parameters.clearance_ulps, kDefaultClearanceUlps);
    const ContainmentVerdict want = expectedVerdict(kind);
    EXPECT_EQ(checkContainment(input_, r.proxy).verdict, want);
    EXPECT_EQ(inDouble(input_, in_double_, r.proxy).verdict, want);
  }
}

TEST(ClearanceUlp, IsTheFloatSpacingAtTheMagnitude) {
  EXPECT_EQ(floatUlp(1.0), std::ldexp(1.0, -23));
  EXPECT_EQ(floatUlp(0.75), std::ldexp(1.0, -24));
  EXPECT_EQ(floatUlp(-3.0), std::ldexp(1.0, -22));
  EXPECT_EQ(floatUlp(1e6), double(std::nextafter(1e6f, 2e6f) - 1e6f));
  EXPECT_GT(floatUlp(0.0), 0.0);
  EXPECT_EQ(clearanceDistance(TriMesh{}, 0.5, std::nullopt), 0.5);
}

}  // namespace
}  // namespace proxyvis

namespace proxyvis {
namespace {

// A placement that rounds hard: a rotation, a non-uniform scale and a translation far larger
// than the mesh (its placed coordinates have ulps thousands of times the mesh's own).
Affine3f hardPlacement() {
  const float c = std::cos(0.5f), s = std::sin(0.5f);
  Affine3f t;
  const float rows[3][4] = {
      {2 * c, -0.5f * s, 0, 1000}, {2 * s, 0.5f * c, 0, -500}, {0, 0, 1.25f, 250}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) t.m[i][j] = rows[i][j];
  return t;
}

TEST(PlacedClearance, GrowsWithThePlacementsMagnitudeAndShrinkingScale) {
  TriMesh unit;
  unit.vertices = {{1, 1, 1}, {-1, -1, -1}};
  // Within 1e-6: the smallest scale is taken a hair smaller than computed, and a rotation in
  // float is orthogonal to about 1e-7.
  auto near = [](double got, double want) { EXPECT_NEAR(got / want, 1.0, 1e-6); };
  near(placementClearance(unit, Affine3f{}, 8), 8 * floatUlp(1.0));
  near(placementClearance(unit, Affine3f::translation({1000, 0, 0}), 8), 8 * floatUlp(1001.0));
  // Scaled down by 4: the placed ulps are 4 times larger in the mesh's units.
  near(placementClearance(unit, Affine3f::scaling({0.25f, 0.25f, 0.25f}), 8),
       8 * floatUlp(0.25) * 4);
  // Non-uniform: the smallest scale (0.5) counts, whatever the rotation.
  Affine3f t = Affine3f::scaling({2, 0.5f, 1});
  near(placementClearance(unit, t, 8), 8 * floatUlp(2.0) * 2);
  const float c = std::cos(0.3f), s = std::sin(0.3f);
  Affine3f r;  // the same scales, rotated about z
  r.m[0][0] = 2 * c, r.m[0][1] = -0.5f * s, r.m[1][0] = 2 * s, r.m[1][1] = 0.5f * c;
  near(placementClearance(unit, r, 1), floatUlp(2 * c + 0.5 * s) / 0.5);
  EXPECT_EQ(placementClearance(unit, Affine3f::scaling({1, 1, 0}), 8), 0.0);  // singular
}

// Proxies generated for a placement keep their class on the placed float copies.
TEST(PlacedClearance, PlacedCopiesKeepTheClass) {
  // Two CGAL-heavy generations (90 s under ASan): the Release suite runs it; the sanitizer build
  // runs the same code on the synthetic box above.
  if (test::kSanitizerBuild) GTEST_SKIP() << "Release suite only";
  const TriMesh input = loadMesh(std::filesystem::path(PROXYVIS_DATA_DIR) / "hard" / "cow.off");
  const Affine3f place = hardPlacement();
  for (const ProxyClass kind : {ProxyClass::kOutside, ProxyClass::kInside}) {
    ProxyGenOptions o;
    o.kind = kind;
    o.max_faces = 200;
    o.hausdorff_samples = 200;
    o.placements = {place};
    const ProxyGenResult r = generateProxy(input, o);
    ASSERT_TRUE(r.verified) << proxyClassName(kind);
    EXPECT_GE(*r.report.checks.clearance, placementClearance(input, place, 8));
    const ContainmentResult placed =
        checkContainment(transformedMesh(input, place), transformedMesh(r.proxy, place));
    EXPECT_EQ(placed.verdict, expectedVerdict(kind)) << proxyClassName(kind) << placed.detail;
  }
}

}  // namespace
}  // namespace proxyvis
