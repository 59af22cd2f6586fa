// Sampled one-sided surface distance on nested boxes, where both directions are known exactly:
// from the inner box [0,1]^3 to the outer [-0.5,1.5]^3 every surface point is within 0.5 of the
// outer surface (reached on faces and corners); from the outer box the farthest points are its
// corners, sqrt(3)/2 from the inner corners. Vertices are always sampled, so both are exact.
#include <gtest/gtest.h>

#include <cmath>

#include "proxies/check/mesh_distance.h"
#include "tests/proxies/check/check_shapes.h"
#include "util/error.h"

namespace proxyvis {
namespace {

TEST(MeshDistance, NestedBoxesBothWays) {
  const TriMesh inner = test::makeBox({0, 0, 0}, {1, 1, 1}, "inner");
  const TriMesh outer = test::makeBox({-0.5f, -0.5f, -0.5f}, {1.5f, 1.5f, 1.5f}, "outer");
  EXPECT_NEAR(sampledOneSidedDistance(inner, outer, 5000, 1), 0.5, 1e-6);
  EXPECT_NEAR(sampledOneSidedDistance(outer, inner, 5000, 1), std::sqrt(3.0) / 2, 1e-6);
}

TEST(MeshDistance, SameMeshIsZeroAndDeterministic) {
  const TriMesh s = test::makeSphere({0, 0, 0}, 1, 16, 8);
  EXPECT_NEAR(sampledOneSidedDistance(s, s, 2000, 7), 0.0, 1e-6);
  const TriMesh t = test::makeSphere({0.1f, 0, 0}, 1, 16, 8);
  EXPECT_EQ(sampledOneSidedDistance(s, t, 2000, 7), sampledOneSidedDistance(s, t, 2000, 7));
}

TEST(MeshDistance, EmptyIsAnError) {
  TriMesh empty;
  empty.source = "empty.off";
  EXPECT_THROW(sampledOneSidedDistance(test::makeBox({0, 0, 0}, {1, 1, 1}), empty), Error);
}

}  // namespace
}  // namespace proxyvis
