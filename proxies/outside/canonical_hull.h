#pragma once
// CGAL-only: convex hulls that depend on the points alone, not on where the allocator put them
// (defined in hull_wrap.cpp; used by the hull and by each convex part).
#include "mesh/cgal_bridge.h"

namespace proxyvis::cgal {

// convex_hull_3 (CGAL 5.5's quickhull) orders its output by vertex addresses; this rebuilds it
// with vertices sorted by coordinates and faces sorted, the same whatever the allocator did.
// Any triangle mesh can be put in this order (the convex parts' union is).
SurfaceMesh canonicalHull(const SurfaceMesh& hull);

// The hull's surface from the Delaunay triangulation of the points: every point on the hull's
// boundary is a vertex, and coplanar facets are triangulated by symbolic perturbation, i.e. by
// the points alone (quickhull picks those triangulations, and whether a point inside a facet is
// kept, by address). In canonicalHull's order; empty when the points span no volume.
SurfaceMesh uniqueHull(const std::vector<Point3>& points);

// The strict corners of a hull (convex_hull_3's output): a vertex inside a facet (every
// neighbour in one plane with it) or inside an edge (between two neighbours on one line) is
// dropped, so the set depends on the points alone. Sorted.
std::vector<Point3> extremeCorners(const SurfaceMesh& hull);

}  // namespace proxyvis::cgal
