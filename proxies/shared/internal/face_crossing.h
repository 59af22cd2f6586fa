#pragma once
// Private to pv_proxy_shared: does a new face of a proxy cross another face of the same mesh?
// Faces that share corners meet there by construction, so a plain triangle test would always
// say yes; skipping them instead (as the collapse and the relaxation once did) misses the
// crossings that start at a shared corner, which the exact check then found as self-
// intersecting pairs and the whole tight phase was dropped. The rule, as in CGAL's
// self-intersection test: sharing one corner s, the faces cross when the edge opposite s of
// either one meets the other; sharing an edge, when they are coplanar and fold onto each other.
#include <CGAL/intersections.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "mesh/cgal_bridge.h"

namespace proxyvis::cgal {

// A face's corners and their vertex ids; a vertex being placed gets an id no other vertex has.
struct IdFace {
  std::array<Point3, 3> p;
  std::array<uint32_t, 3> id;
};

// CGAL's Triangle_3::is_degenerate (exact), answered first by a floating-point test where the
// corners are clearly not collinear: the cross product's 1-norm beyond 1e-10 of its scale, where
// its rounding error stays below 1e-15 of it. Most faces pass there; the exact predicate runs on
// interval arithmetic for every call.
inline bool isDegenerate(const Point3& a, const Point3& b, const Point3& c) {
  const double u[3] = {b.x() - a.x(), b.y() - a.y(), b.z() - a.z()};
  const double v[3] = {c.x() - a.x(), c.y() - a.y(), c.z() - a.z()};
  const double n1 = std::abs(u[1] * v[2] - u[2] * v[1]) + std::abs(u[2] * v[0] - u[0] * v[2]) +
                    std::abs(u[0] * v[1] - u[1] * v[0]);
  const double scale = (std::abs(u[0]) + std::abs(u[1]) + std::abs(u[2])) *
                       (std::abs(v[0]) + std::abs(v[1]) + std::abs(v[2]));
  if (n1 > 1e-10 * scale) return false;
  return CGAL::collinear(a, b, c);
}

// Voxel surfaces (an erosion) are made of exactly coplanar axis-aligned faces, where CGAL's 3D
// predicates fall back to exact arithmetic. Two faces in one plane x_k = c are tested in the
// other two coordinates instead, with CGAL's 2D predicates (exact as well): sharedAxis gives k,
// or -1 when the six corners do not share a coordinate.
inline int sharedAxis(const IdFace& a, const IdFace& b) {
  for (int k = 0; k < 3; ++k) {
    const double c = a.p[0][k];
    bool same = true;
    for (int i = 0; i < 3; ++i) same = same && a.p[i][k] == c && b.p[i][k] == c;
    if (same) return k;
  }
  return -1;
}
inline Kernel::Point_2 inPlane(const Point3& p, int axis) {
  return {p[(axis + 1) % 3], p[(axis + 2) % 3]};
}
inline Kernel::Triangle_2 inPlane(const IdFace& f, int axis) {
  return {inPlane(f.p[0], axis), inPlane(f.p[1], axis), inPlane(f.p[2], axis)};
}

inline bool facesCross(const IdFace& a, const IdFace& b) {
  int shared = 0;
  std::array<int, 3> in_b{-1, -1, -1};  // in_b[i]: the corner of b that is a's corner i
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (a.id[i] == b.id[j]) in_b[i] = j, ++shared;
  if (isDegenerate(a.p[0], a.p[1], a.p[2])) return true;  // a new face must be a real triangle
  if (isDegenerate(b.p[0], b.p[1], b.p[2])) return false;
  const int axis = sharedAxis(a, b);
  if (shared == 0) {
    if (axis >= 0) return CGAL::do_intersect(inPlane(a, axis), inPlane(b, axis));
    return CGAL::do_intersect(Kernel::Triangle_3(a.p[0], a.p[1], a.p[2]),
                              Kernel::Triangle_3(b.p[0], b.p[1], b.p[2]));
  }
  if (shared == 1) {
    const int i = in_b[0] >= 0 ? 0 : (in_b[1] >= 0 ? 1 : 2), j = in_b[i];
    const Point3 &a1 = a.p[(i + 1) % 3], &a2 = a.p[(i + 2) % 3];
    const Point3 &b1 = b.p[(j + 1) % 3], &b2 = b.p[(j + 2) % 3];
    if (axis >= 0)
      return CGAL::do_intersect(Kernel::Segment_2(inPlane(a1, axis), inPlane(a2, axis)),
                                inPlane(b, axis)) ||
             CGAL::do_intersect(Kernel::Segment_2(inPlane(b1, axis), inPlane(b2, axis)),
                                inPlane(a, axis));
    return CGAL::do_intersect(Kernel::Segment_3(a1, a2),
                              Kernel::Triangle_3(b.p[0], b.p[1], b.p[2])) ||
           CGAL::do_intersect(Kernel::Segment_3(b1, b2),
                              Kernel::Triangle_3(a.p[0], a.p[1], a.p[2]));
  }
  if (shared == 2) {
    const int i = in_b[0] < 0 ? 0 : (in_b[1] < 0 ? 1 : 2);  // a's corner off the shared edge
    int j = 0;
    while (j < 3 && (b.id[j] == a.id[(i + 1) % 3] || b.id[j] == a.id[(i + 2) % 3])) ++j;
    // The faces (u, w, r) and (w, u, s) fold onto each other: coplanar, with r and s on the same
    // side of their edge.
    const Point3 &u = a.p[(i + 1) % 3], &w = a.p[(i + 2) % 3], &r = a.p[i], &s = b.p[j];
    if (axis >= 0) {
      const Kernel::Point_2 u2 = inPlane(u, axis), w2 = inPlane(w, axis);
      const CGAL::Orientation side_s = CGAL::orientation(u2, w2, inPlane(s, axis));
      return side_s != CGAL::COLLINEAR && side_s == CGAL::orientation(u2, w2, inPlane(r, axis));
    }
    return CGAL::coplanar(u, w, r, s) && CGAL::coplanar_orientation(u, w, r, s) == CGAL::POSITIVE;
  }
  return false;  // the same face
}

// Two of the new faces cross: a fan folding over itself.
inline bool anyTwoCross(const std::vector<IdFace>& faces) {
  for (size_t i = 0; i < faces.size(); ++i)
    for (size_t j = i + 1; j < faces.size(); ++j)
      if (facesCross(faces[i], faces[j])) return true;
  return false;
}

// One of the new faces crosses `other`, a face of the mesh.
inline bool anyCrosses(const std::vector<IdFace>& faces, const IdFace& other) {
  for (const IdFace& f : faces)
    if (facesCross(f, other)) return true;
  return false;
}

}  // namespace proxyvis::cgal
