#pragma once
// Private to proxies/: after a bounded collapse has reached its face budget, moves each vertex
// toward the input as far as the input test (input_bound.h) and a self-intersection test allow.
// The face count stays; the volume between proxy and input shrinks. Including this header pulls
// in CGAL; only proxies/**/*.cpp may include it.
#include "mesh/tri_mesh.h"
#include "proxies/limits/time_budget.h"
#include "proxies/outside/internal/input_bound.h"

namespace proxyvis::cgal {

// `mesh` is closed and outward oriented, and its outside holds no input (for an inside proxy:
// the reversed mesh). Every move keeps that, shrinks the enclosed volume, flips no face and
// crosses no other face of the mesh. `sweeps` passes over all vertices; stops early when a pass
// gains almost nothing or the budget is spent. Returns the number of vertices moved.
size_t relaxTowardInput(TriMesh& mesh, const InputBound& bound, int sweeps,
                        const TimeBudget* budget);

}  // namespace proxyvis::cgal
