// A class proxy-gen writes holds for the INPUT mesh. Constructed cases whose answers are known by
// hand (two boxes sharing one edge: watertight, not manifold; a "theta" surface, three fans on one
// triangle loop: no boundary but odd edges; a hollow box), and the real meshes that broke it:
// cow.off (one non-manifold edge, four faces) gets verified inside proxies; camelhead.off (an
// open cut) with --fill-holes gets class general, and sampled segments show why.
#include <gtest/gtest.h>

#include <string>

#include "mesh/primitives.h"
#include "mesh/validation.h"
#include "proxies/check/containment.h"
#include "proxies/check/pair_check.h"
#include "proxies/pipeline/proxy_pipeline.h"
#include "proxies/shared/parity_solid.h"
#include "tests/proxies/shared/gen_test_util.h"
#include "util/error.h"

namespace proxyvis {
namespace {

using gen_test::genOptions;
using gen_test::mesh;

void append(TriMesh& to, const TriMesh& m) {
  const uint32_t base = uint32_t(to.vertices.size());
  to.vertices.insert(to.vertices.end(), m.vertices.begin(), m.vertices.end());
  for (const Triangle& t : m.triangles)
    to.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

// Unit cubes [0,1]^3 and [1,2]x[1,2]x[0,1]: they share the edge x = y = 1 (four faces on it,
// each cube with its own vertices there). Volume 2.
TriMesh twoBoxesSharingAnEdge() {
  TriMesh m = makeBoxMesh({0, 0, 0}, {1, 1, 1}, "two-boxes");
  append(m, makeBoxMesh({1, 1, 0}, {2, 2, 1}));
  return m;
}

// Three fans over the triangle loop A B C (apexes below, between, above): every loop edge has
// three faces, every other edge two. No boundary edge, yet no inside.
TriMesh theta() {
  TriMesh m;
  m.source = "theta";
  m.vertices = {{0, 0, 0},        {1, 0, 0},          {0, 1, 0},
                {0.3f, 0.3f, -1}, {0.3f, 0.3f, 0.5f}, {0.3f, 0.3f, 1}};
  for (uint32_t apex : {3u, 4u, 5u}) {
    m.triangles.push_back({0, 1, apex});
    m.triangles.push_back({1, 2, apex});
    m.triangles.push_back({2, 0, apex});
  }
  return m;
}

void flipAll(TriMesh& m) {
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
}

TEST(ParitySolid, TwoBoxesSharingAnEdgeBoundAVolume) {
  const TriMesh m = twoBoxesSharingAnEdge();
  const MeshReport r = validateMesh(m);
  EXPECT_EQ(r.boundary_edges, 0u);
  EXPECT_EQ(r.non_manifold_edges, 1u);
  EXPECT_EQ(r.odd_edges, 0u);
  EXPECT_FALSE(r.closed);
  EXPECT_TRUE(r.watertight);
  ASSERT_TRUE(parityVolume(m).has_value());
  EXPECT_NEAR(*parityVolume(m), 2.0, 1e-9);
  // The parity volume does not depend on how the faces are oriented.
  TriMesh inward = m;
  flipAll(inward);
  EXPECT_NEAR(parityVolume(inward).value_or(0), 2.0, 1e-9);
}

TEST(ParitySolid, HollowBoxCountsItsCavityOut) {
  // A 2-cube with a 1-cube cavity, both shells oriented outward: parity volume 8 - 1.
  TriMesh m = makeBoxMesh({0, 0, 0}, {2, 2, 2}, "hollow");
  append(m, makeBoxMesh({0.5f, 0.5f, 0.5f}, {1.5f, 1.5f, 1.5f}));
  EXPECT_NEAR(parityVolume(m).value_or(0), 7.0, 1e-9);
}

TEST(ParitySolid, DuplicatedFacesCountModuloTwo) {
  // A box with one face doubled has an edge with three faces: no inside. Tripled, parity is back.
  TriMesh m = makeBoxMesh({0, 0, 0}, {1, 1, 1}, "doubled");
  m.triangles.push_back(m.triangles[0]);
  EXPECT_FALSE(validateMesh(m).watertight);
  EXPECT_FALSE(parityVolume(m).has_value());
  m.triangles.push_back(m.triangles[0]);
  EXPECT_TRUE(validateMesh(m).watertight);
  EXPECT_NEAR(parityVolume(m).value_or(0), 1.0, 1e-9);
}

TEST(ParitySolid, ThetaSurfaceHasNoInside) {
  const TriMesh m = theta();
  const MeshReport r = validateMesh(m);
  EXPECT_EQ(r.boundary_edges, 0u);
  EXPECT_EQ(r.odd_edges, 3u);
  EXPECT_FALSE(r.watertight);
  EXPECT_FALSE(parityVolume(m).has_value());
}

TEST(ParityContainment, BoxInsideOneOfTwoEdgeSharingBoxesIsContained) {
  const TriMesh boxes = twoBoxesSharingAnEdge();
  const ContainmentResult in =
      checkContainment(boxes, makeBoxMesh({0.2f, 0.2f, 0.2f}, {0.8f, 0.8f, 0.8f}));
  EXPECT_TRUE(in.original_closed);
  EXPECT_EQ(in.verdict, ContainmentVerdict::kContained) << in.detail;
  EXPECT_NEAR(in.original_volume.value_or(0), 2.0, 1e-9);
  // In the empty wedge beside the shared edge (x > 1, y < 1): outside both cubes.
  const ContainmentResult out =
      checkContainment(boxes, makeBoxMesh({1.2f, 0.2f, 0.2f}, {1.8f, 0.8f, 0.8f}));
  EXPECT_EQ(out.verdict, ContainmentVerdict::kDisjoint) << out.detail;
  // A box around both contains them.
  const ContainmentResult around =
      checkContainment(boxes, makeBoxMesh({-0.5f, -0.5f, -0.5f}, {2.5f, 2.5f, 1.5f}));
  EXPECT_EQ(around.verdict, ContainmentVerdict::kContains) << around.detail;
}

TEST(ParityContainment, OddEdgesMakeTheOriginalOpen) {
  const ContainmentResult r =
      checkContainment(theta(), makeBoxMesh({0.1f, 0.1f, -0.1f}, {0.2f, 0.2f, 0.1f}));
  EXPECT_FALSE(r.original_closed);
  EXPECT_NE(r.verdict, ContainmentVerdict::kContained) << r.detail;
}

// An inside proxy of the two boxes: the wrap carves each cube from its own seeds.
TEST(ParityInside, TwoBoxesGetAVerifiedInsideWrap) {
  const TriMesh input = twoBoxesSharingAnEdge();
  const ProxyGenResult r =
      generateProxy(input, genOptions(ProxyClass::kInside, "wrap", 100000, 1000));
  EXPECT_TRUE(r.verified) << nlohmann::json(r.report).dump(2);
  EXPECT_EQ(r.report.written_class, ProxyClass::kInside);
  EXPECT_EQ(checkContainment(input, r.proxy).verdict, ContainmentVerdict::kContained);
  EXPECT_GT(*r.report.volume_ratio, 0.5);
}

TEST(ParityInside, OddEdgesAreRefusedWithAdviceThatWorks) {
  try {
    generateProxy(theta(), genOptions(ProxyClass::kInside, "wrap", 0, 1000));
    FAIL() << "a surface with odd edges has no inside";
  } catch (const CheckFailed&) {
    FAIL() << "expected a bad-input Error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("3 edges with an odd number"), std::string::npos) << what;
    EXPECT_NE(what.find("--kind outside"), std::string::npos) << what;
    // No boundary edge: filling holes cannot help, so it is not advised.
    EXPECT_EQ(what.find("--fill-holes"), std::string::npos) << what;
  }
  // What the advice says does work.
  const ProxyGenResult outside =
      generateProxy(theta(), genOptions(ProxyClass::kOutside, "", 0, 1000));
  EXPECT_EQ(outside.report.written_class, ProxyClass::kOutside);
}

// cow.off: no boundary edge, one edge with four faces (two vertices at one position).
class CowInside : public testing::TestWithParam<const char*> {};

TEST_P(CowInside, IsVerifiedAgainstTheInput) {
  const TriMesh& cow = mesh("hard/cow.off");
  const MeshReport in = validateMesh(cow);
  ASSERT_TRUE(in.watertight);
  ASSERT_FALSE(in.closed);
  const ProxyGenResult r = generateProxy(cow, genOptions(ProxyClass::kInside, GetParam(), 0, 2000));
  EXPECT_TRUE(r.verified) << nlohmann::json(r.report).dump(2);
  EXPECT_EQ(r.report.written_class, ProxyClass::kInside);
  EXPECT_FALSE(r.report.class_reason);
  // Independently of the report: the exact check against cow.off itself, and sampled segments.
  const ContainmentResult c = checkContainment(cow, r.proxy);
  EXPECT_EQ(c.verdict, ContainmentVerdict::kContained) << c.detail;
  EXPECT_TRUE(c.original_closed);
  PairCheckOptions po;
  po.rays = 200000;
  po.distance_samples = 1000;
  po.quiet = true;
  const PairCheckReport pc = checkPair(cow, r.proxy, po);
  EXPECT_EQ(pc.sampled.counts.mh, 0u);
  EXPECT_GT(pc.sampled.counts.hh, 0u);
  ASSERT_TRUE(r.report.volume_ratio);
  EXPECT_GT(*r.report.volume_ratio, 0.3);
  EXPECT_LT(*r.report.volume_ratio, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Methods, CowInside, testing::Values("wrap", "erode"));

TEST(CowOutside, HasAVolumeRatio) {
  const TriMesh& cow = mesh("hard/cow.off");
  // The parity volume of the split, consistently oriented cow equals its signed volume (its
  // faces are oriented outward already; the split moves no triangle).
  EXPECT_NEAR(parityVolume(cow).value_or(0), cow.signedVolume(), 1e-9 * cow.signedVolume());
  const ProxyGenResult r = generateProxy(cow, genOptions(ProxyClass::kOutside, "", 0, 1000));
  EXPECT_EQ(r.report.written_class, ProxyClass::kOutside);
  ASSERT_TRUE(r.report.volume_ratio) << nlohmann::json(r.report).dump(2);
  EXPECT_GT(*r.report.volume_ratio, 1.0);
}

// camelhead.off has one cut (56 boundary edges). Filling it lets a proxy be built inside, but
// rays through the cut hit that proxy and miss the input: not an inside proxy of the input.
TEST(FillHoles, CamelheadIsWrittenAsGeneralWithTheReason) {
  const TriMesh& camel = mesh("hard/camelhead.off");
  ProxyGenOptions o = genOptions(ProxyClass::kInside, "wrap", 0, 1000);
  o.fill_holes = true;
  const ProxyGenResult r = generateProxy(camel, o);
  EXPECT_TRUE(r.verified) << nlohmann::json(r.report).dump(2);
  EXPECT_EQ(r.report.kind, ProxyClass::kInside);
  EXPECT_EQ(r.report.written_class, ProxyClass::kGeneral);
  const std::string reason = r.report.class_reason.value_or("");
  EXPECT_NE(reason.find("56 boundary edges"), std::string::npos) << reason;
  EXPECT_NE(reason.find("hole"), std::string::npos) << reason;
  // The evidence for the downgrade: against the input itself the proxy is not contained, and
  // sampled segments (both ends outside both meshes) hit the proxy and miss the input.
  EXPECT_NE(checkContainment(camel, r.proxy).verdict, ContainmentVerdict::kContained);
  PairCheckOptions po;
  po.rays = 200000;
  po.distance_samples = 1000;
  po.quiet = true;
  po.expect = ProxyClass::kGeneral;
  const PairCheckReport pc = checkPair(camel, r.proxy, po);
  EXPECT_GT(pc.sampled.counts.mh, 0u);
  EXPECT_FALSE(pc.failed());
}

TEST(FillHoles, OpenInputWithoutFillHolesSaysWhatFillHolesGives) {
  try {
    generateProxy(mesh("hard/camelhead.off"), genOptions(ProxyClass::kInside, "wrap", 0, 1000));
    FAIL() << "an open mesh has no inside";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("56 boundary edges"), std::string::npos) << what;
    EXPECT_NE(what.find("--fill-holes"), std::string::npos) << what;
    EXPECT_NE(what.find("class general"), std::string::npos) << what;
    EXPECT_EQ(e.exitCode(), kExitBadInput);
  }
}

}  // namespace
}  // namespace proxyvis
