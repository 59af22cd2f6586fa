// sampledOneSidedDistance skips the closest-point query of points that cannot raise the maximum.
// Checked against a brute force written here (every point against every triangle, Ericson's
// closest point on a triangle) and by counting the queries, not by timing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "proxies/check/mesh_distance.h"
#include "tests/proxies/check/check_shapes.h"

namespace proxyvis {
namespace {

// C. Ericson, "Real-Time Collision Detection", 5.1.5.
Vec3d closestOnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3d bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Vec3d cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = 1 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// The largest distance from the first vertex of every triangle of `from` (the points measured
// with samples = 0) to the surface of `to`.
double bruteForce(const TriMesh& from, const TriMesh& to) {
  double worst = 0;
  for (const Triangle& f : from.triangles) {
    const Vec3d p(from.vertices[f[0]]);
    double best = INFINITY;
    for (const Triangle& t : to.triangles) {
      const Vec3d q = closestOnTriangle(p, Vec3d(to.vertices[t[0]]), Vec3d(to.vertices[t[1]]),
                                        Vec3d(to.vertices[t[2]]));
      best = std::min(best, length(p - q));
    }
    worst = std::max(worst, best);
  }
  return worst;
}

TEST(DistancePruning, SameMaximumAsBruteForceWithFewQueries) {
  // A fine sphere against a coarser, shifted, larger one: distances vary over the surface and
  // the maximum is at one place.
  const TriMesh fine = test::makeSphere({0, 0, 0}, 1, 64, 32, "fine");
  const TriMesh coarse = test::makeSphere({0.05f, 0.02f, -0.03f}, 1.04f, 20, 10, "coarse");
  for (const auto& [from, to] : {std::pair{&fine, &coarse}, std::pair{&coarse, &fine}}) {
    MeshDistanceStats stats;
    const double d = sampledOneSidedDistance(*from, *to, 0, 1, &stats);
    EXPECT_NEAR(d, bruteForce(*from, *to), 1e-9) << from->source << " -> " << to->source;
    EXPECT_EQ(stats.points, from->numTriangles());
    // Without the sphere test every point is a closest-point query.
    EXPECT_LT(stats.tree_queries * 5, stats.points) << stats.tree_queries << " queries";
  }
}

TEST(DistancePruning, SamplesAreMeasuredToo) {
  const TriMesh fine = test::makeSphere({0, 0, 0}, 1, 64, 32, "fine");
  const TriMesh coarse = test::makeSphere({0, 0, 0}, 1.1f, 20, 10, "coarse");
  MeshDistanceStats stats;
  const double d = sampledOneSidedDistance(fine, coarse, 5000, 3, &stats);
  EXPECT_EQ(stats.points, 5000 + fine.numTriangles());
  // Every point of the unit sphere is at least 0.1 - (sagitta of the coarse one) away.
  EXPECT_GT(d, 0.05);
  EXPECT_LT(d, 0.1 + 1e-6);
}

}  // namespace
}  // namespace proxyvis
