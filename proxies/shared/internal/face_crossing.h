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
#include <cstdint>
#include <vector>

#include "mesh/cgal_bridge.h"

namespace proxyvis::cgal {

// A face's corners and their vertex ids; a vertex being placed gets an id no other vertex has.
struct IdFace {
  std::array<Point3, 3> p;
  std::array<uint32_t, 3> id;
};

inline bool facesCross(const IdFace& a, const IdFace& b) {
  int shared = 0;
  std::array<int, 3> in_b{-1, -1, -1};  // in_b[i]: the corner of b that is a's corner i
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (a.id[i] == b.id[j]) in_b[i] = j, ++shared;
  const Kernel::Triangle_3 ta(a.p[0], a.p[1], a.p[2]), tb(b.p[0], b.p[1], b.p[2]);
  if (ta.is_degenerate()) return true;  // a new face must be a real triangle
  if (tb.is_degenerate()) return false;
  if (shared == 0) return CGAL::do_intersect(ta, tb);
  if (shared == 1) {
    const int i = in_b[0] >= 0 ? 0 : (in_b[1] >= 0 ? 1 : 2), j = in_b[i];
    const Kernel::Segment_3 opposite_a(a.p[(i + 1) % 3], a.p[(i + 2) % 3]);
    const Kernel::Segment_3 opposite_b(b.p[(j + 1) % 3], b.p[(j + 2) % 3]);
    return CGAL::do_intersect(opposite_a, tb) || CGAL::do_intersect(opposite_b, ta);
  }
  if (shared == 2) {
    const int i = in_b[0] < 0 ? 0 : (in_b[1] < 0 ? 1 : 2);  // a's corner off the shared edge
    int j = 0;
    while (j < 3 && (b.id[j] == a.id[(i + 1) % 3] || b.id[j] == a.id[(i + 2) % 3])) ++j;
    const Point3 &u = a.p[(i + 1) % 3], &w = a.p[(i + 2) % 3];
    return CGAL::coplanar(u, w, a.p[i], b.p[j]) &&
           CGAL::coplanar_orientation(u, w, a.p[i], b.p[j]) == CGAL::POSITIVE;
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
