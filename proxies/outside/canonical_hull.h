#pragma once
// CGAL-only: the convex hull in an order that does not depend on the heap layout (defined in
// hull_wrap.cpp, used by the hull and by each convex part).
#include "mesh/cgal_bridge.h"

namespace proxyvis::cgal {

// convex_hull_3 (CGAL 5.5's quickhull) orders its output by vertex addresses; this rebuilds it
// with vertices sorted by coordinates and faces sorted, the same whatever the allocator did.
// Any triangle mesh can be put in this order (the convex parts' union is).
SurfaceMesh canonicalHull(const SurfaceMesh& hull);

}  // namespace proxyvis::cgal
