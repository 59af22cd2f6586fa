#pragma once
// A tiny 3-variable linear program for edge-collapse placement (no CGAL): minimise c·x subject
// to n_i·x >= d_i for a handful of planes (the supporting planes of the faces around an edge)
// and a box around the edge. With ~10-20 planes, enumerating the vertices of the arrangement
// (triples of planes) is simpler and fast enough (~10 µs) compared to a general LP solver.
#include <optional>
#include <vector>

#include "util/vec3.h"

namespace proxyvis::lp {

// Half-space {x : dot(n, x) >= d}; n need not be unit length.
struct HalfSpace {
  Vec3d n;
  double d = 0;
};

struct PlaneLpProblem {
  std::vector<HalfSpace> constraints;
  Vec3d objective;                // minimise dot(objective, x)
  Vec3d center;                   // box centre, and the tie-breaker: prefer points near it
  double half_size = 1;           // box half-size (> 0); keeps the program bounded
  std::vector<Vec3d> candidates;  // extra points to try (e.g. edge endpoints and midpoint)
};

// Returns the feasible point of least objective; among points whose objective is within a
// relative tie tolerance of the best, the one closest to `center` (so a flat neighbourhood
// collapses to the midpoint, not to a box corner). nullopt when the constraints are infeasible
// inside the box.
std::optional<Vec3d> solvePlaneLp(const PlaneLpProblem& problem);

}  // namespace proxyvis::lp
