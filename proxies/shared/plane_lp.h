#pragma once
// A tiny 3-variable linear program for edge-collapse placement (no CGAL): minimise c·x subject
// to n_i·x >= d_i for the supporting planes of the faces around an edge and a box around the
// edge. Seidel's randomised incremental algorithm solves it in time linear in the planes: the
// stars of a convex hull's vertices have 50 and more faces, where enumerating every triple of
// planes took most of a hull's budget reduction (63 % of proxy-gen's time on the beetle's hull).
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

// The same program by enumerating every vertex of the arrangement (triples of planes): the
// constraint planes alone first, then with the box planes only if none of those vertices is
// feasible. O(planes^4) at worst. The reference the tests compare solvePlaneLp() with, and its
// fallback should rounding ever leave its answer outside a constraint.
std::optional<Vec3d> solvePlaneLpByEnumeration(const PlaneLpProblem& problem);

}  // namespace proxyvis::lp
