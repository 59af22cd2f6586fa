// General proxies: the three simplifiers meet the face budget, stay near the surface, and the
// pipeline's report has every documented key and survives a JSON round trip.
#include <gtest/gtest.h>

#include <string>

#include "proxies/general/general_proxy.h"
#include "proxies/pipeline/proxy_pipeline.h"
#include "tests/proxies/shared/gen_test_util.h"
#include "util/error.h"

namespace proxyvis {
namespace {

using gen_test::genOptions;
using gen_test::mesh;

class GeneralMethod : public testing::TestWithParam<const char*> {};

TEST_P(GeneralMethod, MeetsBudgetAndStaysClose) {
  const TriMesh& input = mesh("bunny.off");
  const ProxyGenResult r =
      generateProxy(input, genOptions(ProxyClass::kGeneral, GetParam(), 700, 4000));
  EXPECT_LE(r.proxy.numTriangles(), 700u);
  EXPECT_GT(r.proxy.numTriangles(), 350u);
  // 10 % of the input faces: a decent simplifier stays within 2 % of the diagonal.
  EXPECT_LT(r.report.hausdorff_proxy_to_original, 0.02);
  EXPECT_LT(r.report.hausdorff_original_to_proxy, 0.02);
  EXPECT_NE(r.report.written_class, ProxyClass::kOutside);
  EXPECT_NE(r.report.written_class, ProxyClass::kInside);
}

INSTANTIATE_TEST_SUITE_P(AllMethods, GeneralMethod, testing::Values("qem", "cgal-sms", "meshopt"));

TEST(GeneralRatio, RatioSetsTheBudget) {
  const TriMesh& input = mesh("spot_triangulated.obj");
  GeneralOptions g;
  g.ratio = 0.1;
  const size_t target = generalTargetFaces(input, g);
  EXPECT_EQ(target, size_t(std::llround(0.1 * double(input.numTriangles()))));
  EXPECT_LE(simplifyQem(input, g).numTriangles(), target);
  g.ratio = 0;
  EXPECT_THROW(generalTargetFaces(input, g), Error);
}

TEST(GeneralWeld, SharedPositionsBecomeOneVertex) {
  // Two triangles of a quad stored with six unshared vertices (as leaf cards are).
  TriMesh quad;
  quad.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quad.triangles = {{0, 1, 2}, {3, 4, 5}};
  const TriMesh welded = weldVertices(quad);
  EXPECT_EQ(welded.numVertices(), 4u);
  EXPECT_EQ(welded.numTriangles(), 2u);
}

TEST(GeneralReport, HasEveryKeyAndRoundTrips) {
  const TriMesh& input = mesh("bunny.off");
  ProxyGenOptions o = genOptions(ProxyClass::kGeneral, "", 0, 1000);
  o.ratio = 0.05;
  const ProxyGenResult r = generateProxy(input, o);
  const nlohmann::json parsed = nlohmann::json::parse(nlohmann::json(r.report).dump());
  for (const char* key :
       {"input", "kind", "method", "parameters", "faces", "volume_ratio",
        "hausdorff_proxy_to_original", "hausdorff_original_to_proxy", "verified", "seconds"})
    EXPECT_TRUE(parsed.contains(key)) << key;
  for (const char* key : {"path", "faces", "closed"})
    EXPECT_TRUE(parsed["input"].contains(key)) << key;
  EXPECT_EQ(parsed["kind"], "general");
  EXPECT_EQ(parsed["method"], "qem");
  EXPECT_EQ(parsed["input"]["faces"].get<size_t>(), input.numTriangles());
  EXPECT_TRUE(parsed["seconds"].contains("total"));
  // The distances in scene units beside the fractions of the diagonal, which they must match.
  const nlohmann::json& h = parsed["hausdorff"];
  EXPECT_EQ(h["unit"], "scene units");
  EXPECT_NEAR(h["diagonal"].get<double>(), input.diagonal(), 1e-6);
  EXPECT_NEAR(h["proxy_to_original"].get<double>() / input.diagonal(),
              parsed["hausdorff_proxy_to_original"].get<double>(), 1e-9);
  EXPECT_NEAR(h["original_to_proxy_fraction_of_diagonal"].get<double>(),
              parsed["hausdorff_original_to_proxy"].get<double>(), 1e-9);
}

}  // namespace
}  // namespace proxyvis
