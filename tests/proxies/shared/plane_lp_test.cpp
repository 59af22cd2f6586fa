// The placement LP of the bounded edge collapse, on programs whose optimum is known by hand.
#include <gtest/gtest.h>

#include "proxies/shared/plane_lp.h"

namespace proxyvis::lp {
namespace {

TEST(PlaneLp, OctantCornerIsTheOptimum) {
  // x, y, z >= 0
  const auto x = solvePlaneLp({.constraints = {{{1, 0, 0}, 0}, {{0, 1, 0}, 0}, {{0, 0, 1}, 0}},
                               .objective = {1, 2, 3},
                               .center = {1, 1, 1},
                               .half_size = 5,
                               .candidates = {}});
  ASSERT_TRUE(x);
  EXPECT_NEAR(x->x, 0, 1e-12);
  EXPECT_NEAR(x->y, 0, 1e-12);
  EXPECT_NEAR(x->z, 0, 1e-12);
}

TEST(PlaneLp, BoxBoundsAnUnboundedDirection) {
  // z >= 2; the objective pushes x up and z down.
  const auto x = solvePlaneLp({.constraints = {{{0, 0, 1}, 2}},
                               .objective = {-1, 0, 1},
                               .center = {0, 0, 3},
                               .half_size = 4,
                               .candidates = {}});
  ASSERT_TRUE(x);
  EXPECT_NEAR(x->x, 4, 1e-12);
  EXPECT_NEAR(x->z, 2, 1e-12);
}

TEST(PlaneLp, InfeasibleSlabGivesNothing) {
  // z >= 1 and z <= 0
  EXPECT_FALSE(solvePlaneLp({.constraints = {{{0, 0, 1}, 1}, {{0, 0, -1}, 0}},
                             .objective = {0, 0, 1},
                             .center = {0, 0, 0.5},
                             .half_size = 10,
                             .candidates = {}}));
}

TEST(PlaneLp, FlatNeighbourhoodPrefersTheCentre) {
  // All constraints are the same plane and the objective is its normal: every point of the
  // plane is optimal; the tie-breaker must pick the centre, not a box corner.
  const Vec3d center{0.25, -0.5, 0};
  const auto x = solvePlaneLp({.constraints = {{{0, 0, 1}, 0}, {{0, 0, 2}, 0}},
                               .objective = {0, 0, 1},
                               .center = center,
                               .half_size = 1,
                               .candidates = {center, {0, 0, 0}}});
  ASSERT_TRUE(x);
  EXPECT_NEAR(x->x, 0.25, 1e-12);
  EXPECT_NEAR(x->y, -0.5, 1e-12);
  EXPECT_NEAR(x->z, 0, 1e-12);
}

}  // namespace
}  // namespace proxyvis::lp
