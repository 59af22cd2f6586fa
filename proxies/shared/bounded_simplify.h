#pragma once
// Edge-collapse simplification of a closed, outward-oriented mesh that keeps it on one side of
// itself: every accepted collapse produces a mesh that contains the previous one (kOutside, the
// progressive hulls of Sander et al., "Silhouette clipping", SIGGRAPH 2000) or is contained in it
// (kInside, the mirror image). Budget proxies thus keep their outside/inside guarantee, up to
// float rounding and far-away self-intersections, which the caller's exact check catches. With
// the input as options.bound, the last collapses are tested against the input instead and may
// cut volume (docs/proxy_tightness.md).
#include <cstddef>

#include "mesh/tri_mesh.h"
#include "proxies/shared/time_budget.h"

namespace proxyvis {

enum class BoundSide { kOutside, kInside };

struct BoundedSimplifyOptions {
  size_t max_faces = 0;  // target face count; 0 = no simplification
  BoundSide side = BoundSide::kOutside;
  // A collapsed vertex may move at most this many edge lengths from the edge midpoint; keeps
  // new faces local so they do not cut through distant parts of the surface.
  double max_move_edges = 1.0;
  const TimeBudget* budget = nullptr;  // polled between collapses; null = no limit
  // The input the result must keep containing (kOutside) or stay inside of (kInside). With it,
  // a collapse may also move the surface toward the input, tested against the input itself
  // (proxies/shared/internal/input_bound.h): much tighter at small budgets. Null = every
  // collapse keeps the mesh nested in the previous one (progressive hulls).
  const TriMesh* bound = nullptr;
  // With `bound`: how close a moved face may come to it (a face within this distance touches;
  // the proxy's clearance, proxies/pipeline/clearance.h). 0 = up to any distance but contact.
  double clearance = 0;
};

struct BoundedSimplifyStats {
  size_t faces_before = 0, faces_after = 0;
  size_t collapses = 0;
  size_t relaxed = 0;     // vertex moves and edge flips of the relaxation (with options.bound)
  int refine_cycles = 0;  // refinement cycles that lowered the volume (with options.bound)
  bool budget_reached = false;  // false when no admissible collapse was left before the budget
};

// `mesh` must be closed, 2-manifold and outward oriented (positive volume); otherwise throws
// Error, as when options.budget is spent. Returns the simplified mesh; stats (optional) says how
// far it got.
TriMesh simplifyBounded(const TriMesh& mesh, const BoundedSimplifyOptions& options,
                        BoundedSimplifyStats* stats = nullptr);

}  // namespace proxyvis
