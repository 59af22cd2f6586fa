#pragma once
// Private to pv_proxy_shared: after a bounded collapse has reached its face budget, moves each
// vertex toward the input as far as the input test (input_bound.h) and a self-intersection test
// allow, and flips edges where that removes volume under the same tests. The face count stays;
// the volume between proxy and input shrinks.
#include "mesh/tri_mesh.h"
#include "proxies/shared/internal/input_bound.h"
#include "proxies/shared/time_budget.h"

namespace proxyvis::cgal {

// `mesh` is closed and outward oriented, and its outside holds no input (for an inside proxy:
// the reversed mesh). Every move keeps that, shrinks the enclosed volume, flips no face and
// crosses no other face of the mesh; so does every flip. `sweeps` passes over all vertices and
// edges; stops early when a pass gains almost nothing or the budget is spent. Returns the number
// of vertex moves and edge flips.
size_t relaxTowardInput(TriMesh& mesh, const InputBound& bound, int sweeps,
                        const TimeBudget* budget);

}  // namespace proxyvis::cgal
