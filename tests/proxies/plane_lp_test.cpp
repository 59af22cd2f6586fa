// The placement LP of the bounded edge collapse, on programs whose optimum is known by hand.
#include <gtest/gtest.h>

#include "proxies/shared/plane_lp.h"

namespace proxyvis::lp {
namespace {

TEST(PlaneLp, OctantCornerIsTheOptimum) {
  PlaneLpProblem p;
  p.constraints = {{{1, 0, 0}, 0}, {{0, 1, 0}, 0}, {{0, 0, 1}, 0}};  // x, y, z >= 0
  p.objective = {1, 2, 3};
  p.center = {1, 1, 1};
  p.half_size = 5;
  auto x = solvePlaneLp(p);
  ASSERT_TRUE(x);
  EXPECT_NEAR(x->x, 0, 1e-12);
  EXPECT_NEAR(x->y, 0, 1e-12);
  EXPECT_NEAR(x->z, 0, 1e-12);
}

TEST(PlaneLp, BoxBoundsAnUnboundedDirection) {
  PlaneLpProblem p;
  p.constraints = {{{0, 0, 1}, 2}};  // z >= 2
  p.objective = {-1, 0, 1};          // push x up, z down
  p.center = {0, 0, 3};
  p.half_size = 4;
  auto x = solvePlaneLp(p);
  ASSERT_TRUE(x);
  EXPECT_NEAR(x->x, 4, 1e-12);
  EXPECT_NEAR(x->z, 2, 1e-12);
}

TEST(PlaneLp, InfeasibleSlabGivesNothing) {
  PlaneLpProblem p;
  p.constraints = {{{0, 0, 1}, 1}, {{0, 0, -1}, 0}};  // z >= 1 and z <= 0
  p.objective = {0, 0, 1};
  p.center = {0, 0, 0.5};
  p.half_size = 10;
  EXPECT_FALSE(solvePlaneLp(p));
}

TEST(PlaneLp, FlatNeighbourhoodPrefersTheCentre) {
  // All constraints are the same plane and the objective is its normal: every point of the
  // plane is optimal; the tie-breaker must pick the centre, not a box corner.
  PlaneLpProblem p;
  p.constraints = {{{0, 0, 1}, 0}, {{0, 0, 2}, 0}};
  p.objective = {0, 0, 1};
  p.center = {0.25, -0.5, 0};
  p.half_size = 1;
  p.candidates = {p.center, {0, 0, 0}};
  auto x = solvePlaneLp(p);
  ASSERT_TRUE(x);
  EXPECT_NEAR(x->x, 0.25, 1e-12);
  EXPECT_NEAR(x->y, -0.5, 1e-12);
  EXPECT_NEAR(x->z, 0, 1e-12);
}

}  // namespace
}  // namespace proxyvis::lp
