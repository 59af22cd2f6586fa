#pragma once
// Private to pv_proxy_shared: refinement cycles for a proxy that already meets its face budget.
// Greedy collapses leave the triangulation as it fell, and the relaxation only moves vertices
// and flips edges, so it stops in a local minimum. A cycle splits every edge at its midpoint
// (same surface, four times the faces), relaxes that finer mesh toward the input, collapses it
// back to the budget under the input test and relaxes again: the tight phase then starts from
// a tight mesh instead of a nested one. The volume is the one that counts (outside: less is
// tighter; inside the mesh is reversed, so again less).
#include <functional>
#include <optional>

#include "mesh/tri_mesh.h"
#include "proxies/shared/internal/input_bound.h"
#include "proxies/shared/time_budget.h"

namespace proxyvis::cgal {

// True when CGAL cannot load the mesh as a 2-manifold or a pair of its faces crosses
// (CGAL's does_self_intersect): a relaxed or refined result that does is dropped.
bool crossesItself(const TriMesh& mesh);

// Collapses a closed mesh to the face budget under the input test; nothing when it cannot.
using CollapseToBudget = std::function<std::optional<TriMesh>(const TriMesh&)>;

// Runs up to `cycles` cycles from `mesh` (each from the previous cycle's result, so a cycle
// that loses a little may lead to one that gains), keeps the smallest volume in `mesh` and
// returns how many cycles lowered it. A split that touches the input (float midpoints), a
// collapse that misses the budget or a result that crosses itself ends the cycles.
int refineCycles(TriMesh& mesh, const InputBound& bound, int cycles, int relax_sweeps,
                 const CollapseToBudget& collapse_to_budget, const TimeBudget* budget);

}  // namespace proxyvis::cgal
