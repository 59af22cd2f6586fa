// The placement LP of the bounded edge collapse, on programs whose optimum is known by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

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

// Stars like those of a collapse: planes through points near the origin, normals spread over a
// cone (a cone of half-angle > 90 degrees makes some programs infeasible). solvePlaneLp() takes
// Seidel's optimum only where no other point ties with it, else it asks the enumeration: both
// must give the same point, bit for bit, and be infeasible together.
struct RandomStars {
  std::mt19937 rng{12345};
  PlaneLpProblem next(int planes, double cone) {
    std::uniform_real_distribution<double> u(-1, 1), ang(0, 1);
    PlaneLpProblem p;
    for (int i = 0; i < planes; ++i) {
      const double z = std::cos(cone * std::sqrt(ang(rng))), phi = 6.283185307179586 * ang(rng);
      const double r = std::sqrt(std::max(0.0, 1 - z * z));
      const Vec3d n{r * std::cos(phi), r * std::sin(phi), z};
      const Vec3d at{0.3 * u(rng), 0.3 * u(rng), 0.3 * u(rng)};
      p.constraints.push_back({n * (0.5 + ang(rng)), dot(n * (0.5 + ang(rng)), at)});
      p.constraints.back().d = dot(p.constraints.back().n, at);
    }
    p.objective = Vec3d{u(rng), u(rng), u(rng)};
    p.center = Vec3d{0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng)};
    p.half_size = 0.5 + ang(rng);
    p.candidates = {p.center, p.center + Vec3d{0.05, 0, 0}};
    return p;
  }
};

bool feasible(const PlaneLpProblem& p, const Vec3d& x, double tol) {
  for (const HalfSpace& h : p.constraints)
    if (dot(h.n, x) < h.d - tol * length(h.n)) return false;
  for (int a = 0; a < 3; ++a)
    if (std::abs(x[a] - p.center[a]) > p.half_size + tol) return false;
  return true;
}

TEST(PlaneLp, SeidelAgreesWithTheEnumerationOnRandomStars) {
  RandomStars stars;
  int feasible_count = 0;
  for (int round = 0; round < 3000; ++round) {
    const int planes = 3 + round % 60;
    const double cone = round % 3 == 0 ? 2.2 : 1.2;
    const PlaneLpProblem p = stars.next(planes, cone);
    const auto seidel = solvePlaneLp(p);
    const auto enumerated = solvePlaneLpByEnumeration(p);
    ASSERT_EQ(bool(seidel), bool(enumerated)) << "round " << round << ", " << planes << " planes";
    if (!seidel) continue;
    ++feasible_count;
    const double tol = 1e-8 * p.half_size;
    ASSERT_TRUE(feasible(p, *seidel, tol)) << "round " << round;
    // The same bits: a unique vertex is computed as the enumeration computes it.
    ASSERT_EQ(seidel->x, enumerated->x) << "round " << round;
    ASSERT_EQ(seidel->y, enumerated->y) << "round " << round;
    ASSERT_EQ(seidel->z, enumerated->z) << "round " << round;
  }
  // Both kinds occur: the test covers feasible and infeasible programs.
  EXPECT_GT(feasible_count, 1000);
  EXPECT_LT(feasible_count, 3000);
}

}  // namespace
}  // namespace proxyvis::lp
