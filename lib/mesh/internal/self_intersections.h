#pragma once
// The only door to CGAL in lib/mesh (CGAL costs 15-37 s per translation unit to compile).
#include <cstdint>

#include "mesh/tri_mesh.h"

namespace proxyvis::detail {

// Number of pairs of non-adjacent triangles that intersect (CGAL Polygon_mesh_processing::
// self_intersections, exact predicates). Exactly equal positions are merged and degenerate
// triangles dropped first; non-manifold vertices are split apart to form a CGAL Surface_mesh, so
// two triangles that touch only at such a pinched vertex count as one intersecting pair.
uint64_t countSelfIntersectingPairs(const TriMesh& mesh);

// True if the three points lie on one line (a zero-area triangle), decided exactly (CGAL's
// filtered predicate), so neither a slightly bent sliver counts nor a rounding error hides one.
// All coordinates must be finite.
bool areCollinear(const Vec3f& a, const Vec3f& b, const Vec3f& c);

}  // namespace proxyvis::detail
