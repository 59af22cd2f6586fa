#include "brute_force.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace proxyvis::test {

BruteForceMesh::BruteForceMesh(const TriMesh& mesh) {
  tris_.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    Vec3d a(mesh.vertices[t[0]]), b(mesh.vertices[t[1]]), c(mesh.vertices[t[2]]);
    Tri tri;
    tri.v0 = a;
    tri.e1 = b - a;
    tri.e2 = c - a;
    double twice_area = length(cross(tri.e1, tri.e2));
    double la = length(c - b), lb = length(a - c), lc = length(b - a);
    tri.h[0] = la > 0 ? twice_area / la : 0;
    tri.h[1] = lb > 0 ? twice_area / lb : 0;
    tri.h[2] = lc > 0 ? twice_area / lc : 0;
    tris_.push_back(tri);
  }
  for (size_t c = 0; c < tris_.size(); c += kCluster) {
    Bounds3d b;
    for (size_t i = c; i < std::min(tris_.size(), c + kCluster); ++i) {
      const Tri& t = tris_[i];
      b.extend(t.v0);
      b.extend(t.v0 + t.e1);
      b.extend(t.v0 + t.e2);
    }
    Vec3d pad = Vec3d(1, 1, 1) * (1e-9 * (b.diagonal() + 1.0));
    b.lo -= pad;
    b.hi += pad;
    clusters_.push_back(b);
  }
}

// Slab test of the segment's t-range against the cluster's box. Infinite inv_d components (axis
// parallel segments) give infinite or NaN slab ends; NaN compares false, which keeps the cluster.
bool BruteForceMesh::segmentMissesCluster(size_t cluster, const Vec3d& o, const Vec3d& inv_d,
                                          double t0, double t1) const {
  const Bounds3d& b = clusters_[cluster];
  for (int a = 0; a < 3; ++a) {
    double ta = (b.lo[a] - o[a]) * inv_d[a], tb = (b.hi[a] - o[a]) * inv_d[a];
    if (ta > tb) std::swap(ta, tb);
    if (ta > t0) t0 = ta;
    if (tb < t1) t1 = tb;
    if (t0 > t1) return true;
  }
  return false;
}

bool BruteForceMesh::crossing(const Tri& tri, const Vec3d& o, const Vec3d& d, double& t, double& b1,
                              double& b2) {
  Vec3d p = cross(d, tri.e2);
  double det = dot(tri.e1, p);
  if (det == 0.0) return false;
  double inv = 1.0 / det;
  Vec3d s = o - tri.v0;
  b1 = dot(s, p) * inv;
  Vec3d q = cross(s, tri.e1);
  b2 = dot(d, q) * inv;
  t = dot(tri.e2, q) * inv;
  return true;
}

bool BruteForceMesh::occluded(const Segment& s) const {
  Vec3d o(s.org), d(s.dir);
  Vec3d inv_d(1.0 / d.x, 1.0 / d.y, 1.0 / d.z);
  for (size_t c = 0; c < clusters_.size(); ++c) {
    if (segmentMissesCluster(c, o, inv_d, s.tnear, s.tfar)) continue;
    for (size_t i = c * kCluster; i < std::min(tris_.size(), (c + 1) * kCluster); ++i) {
      double t, b1, b2;
      if (!crossing(tris_[i], o, d, t, b1, b2)) continue;
      if (b1 >= 0 && b2 >= 0 && b1 + b2 <= 1 && t >= s.tnear && t <= s.tfar) return true;
    }
  }
  return false;
}

BruteHit BruteForceMesh::intersect(const Segment& s) const {
  Vec3d o(s.org), d(s.dir);
  BruteHit best;
  best.t = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < tris_.size(); ++i) {
    double t, b1, b2;
    if (!crossing(tris_[i], o, d, t, b1, b2)) continue;
    if (b1 >= 0 && b2 >= 0 && b1 + b2 <= 1 && t >= s.tnear && t <= s.tfar && t < best.t) {
      best = {true, t, uint32_t(i)};
    }
  }
  return best;
}

bool BruteForceMesh::nearBoundary(const Segment& s, double eps) const {
  Vec3d o(s.org), d(s.dir);
  const double len = length(d);
  const double dt = eps / len;  // eps in units of t
  for (const Tri& tri : tris_) {
    double t, b1, b2;
    Vec3d n = cross(tri.e1, tri.e2);
    double sin_angle = std::abs(dot(n, d)) / (length(n) * len);
    if (sin_angle < 1e-6) {
      // Nearly parallel: ambiguous if the segment comes within eps of the plane at all.
      double dist0 = std::abs(dot(n, o - tri.v0)) / length(n);
      if (dist0 < eps) return true;
      continue;
    }
    if (!crossing(tri, o, d, t, b1, b2)) continue;
    if (t < s.tnear - dt || t > s.tfar + dt) continue;
    // Signed in-plane distance to each edge line: barycentric times the matching height.
    double dist = std::min({(1 - b1 - b2) * tri.h[0], b1 * tri.h[1], b2 * tri.h[2]});
    if (std::abs(dist) <= eps) return true;  // crosses the plane next to an edge or vertex
    if (dist > 0 && (std::abs(t - s.tnear) <= dt || std::abs(t - s.tfar) <= dt))
      return true;  // crosses the triangle next to an endpoint of the segment
  }
  return false;
}

bool BruteForceMesh::ambiguousClosest(const Segment& s, double eps) const {
  if (nearBoundary(s, eps)) return true;
  Vec3d o(s.org), d(s.dir);
  const double dt = eps / length(d);
  BruteHit best = intersect(s);
  if (!best.hit) return false;
  for (size_t i = 0; i < tris_.size(); ++i) {
    double t, b1, b2;
    if (i == best.prim || !crossing(tris_[i], o, d, t, b1, b2)) continue;
    if (b1 >= 0 && b2 >= 0 && b1 + b2 <= 1 && std::abs(t - best.t) <= dt) return true;
  }
  return false;
}

}  // namespace proxyvis::test
