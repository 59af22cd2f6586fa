#pragma once
// Reference answers for the trace tests, independent of Embree: Möller–Trumbore ray–triangle
// intersection (Möller, Trumbore, "Fast, Minimum Storage Ray/Triangle Intersection", JGT 1997)
// in double precision, tried against every triangle.
#include <vector>

#include "mesh/tri_mesh.h"
#include "trace/trace_scene.h"

namespace proxyvis::test {

struct BruteHit {
  bool hit = false;
  double t = 0;
  uint32_t prim = 0;
};

// Triangles in double, with what the tests need per triangle.
class BruteForceMesh {
 public:
  explicit BruteForceMesh(const TriMesh& mesh);

  // Any triangle crossed at t in [tnear, tfar] (boundaries inclusive).
  bool occluded(const Segment& s) const;
  // Closest crossing at t in [tnear, tfar].
  BruteHit intersect(const Segment& s) const;
  // True if the segment passes within `eps` (world units) of a triangle's boundary where it
  // crosses the triangle's plane, or crosses a triangle within `eps` of its own endpoints, or
  // runs nearly parallel to a triangle it comes close to: the cases where a float and a double
  // test may legitimately disagree.
  bool nearBoundary(const Segment& s, double eps) const;
  // Same for the closest hit: a second triangle crossed within `eps` of the first one's distance.
  bool ambiguousClosest(const Segment& s, double eps) const;

  size_t size() const { return tris_.size(); }

 private:
  struct Tri {
    Vec3d v0, e1, e2;
    double h[3];  // heights: distance from vertex i to the opposite edge's line
  };
  // Plane crossing: t and barycentrics (b0, b1, b2) of org + t*dir; false if parallel.
  static bool crossing(const Tri& tri, const Vec3d& o, const Vec3d& d, double& t, double& b1,
                       double& b2);
  // Runs of kCluster consecutive triangles with a padded box; a run whose box the segment misses
  // is skipped (only a speed-up: it never changes an answer, the padding keeps it conservative).
  static constexpr size_t kCluster = 16;
  bool segmentMissesCluster(size_t cluster, const Vec3d& o, const Vec3d& inv_d, double t0,
                            double t1) const;
  std::vector<Tri> tris_;
  std::vector<Bounds3d> clusters_;
};

}  // namespace proxyvis::test
