// Vertex enumeration for a 3-D linear program: the optimum of a bounded feasible LP is attained
// at a vertex of the feasible polytope, i.e. at the intersection of three constraint planes.
#include "proxies/outside/internal/plane_lp.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace proxyvis::lp {
namespace {

struct Plane {
  Vec3d n;  // unit
  double d;
};

// Unit normals make the feasibility tolerance a distance; near-duplicate planes (flat regions)
// are merged, keeping the most restrictive one, which shrinks the triple count a lot.
std::vector<Plane> normalizePlanes(const PlaneLpProblem& problem) {
  std::vector<Plane> planes;
  auto add = [&](Vec3d n, double d) {
    const double len = length(n);
    if (!(len > 0) || !std::isfinite(len)) return;
    n = n / len;
    d /= len;
    for (Plane& p : planes) {
      if (dot(p.n, n) > 1 - 1e-12) {
        p.d = std::max(p.d, d);
        return;
      }
    }
    planes.push_back({n, d});
  };
  for (const HalfSpace& h : problem.constraints) add(h.n, h.d);
  for (int axis = 0; axis < 3; ++axis) {
    Vec3d e(0, 0, 0);
    e[axis] = 1;
    add(e, problem.center[axis] - problem.half_size);
    add(-e, -(problem.center[axis] + problem.half_size));
  }
  return planes;
}

bool isFeasible(const std::vector<Plane>& planes, const Vec3d& x, double tol) {
  for (const Plane& p : planes)
    if (dot(p.n, x) < p.d - tol) return false;
  return true;
}

}  // namespace

std::optional<Vec3d> solvePlaneLp(const PlaneLpProblem& problem) {
  const std::vector<Plane> planes = normalizePlanes(problem);
  const double tol = 1e-9 * problem.half_size;
  const size_t m = planes.size();

  struct Vertex {
    double value;
    Vec3d x;
  };
  std::vector<Vertex> vertices;
  vertices.reserve(m * m * m / 6 + problem.candidates.size());
  for (const Vec3d& x : problem.candidates) vertices.push_back({dot(problem.objective, x), x});

  std::vector<Vec3d> cross_nm(m * m);
  for (size_t i = 0; i < m; ++i)
    for (size_t j = i + 1; j < m; ++j) cross_nm[i * m + j] = cross(planes[i].n, planes[j].n);
  for (size_t i = 0; i < m; ++i) {
    for (size_t j = i + 1; j < m; ++j) {
      for (size_t k = j + 1; k < m; ++k) {
        const Vec3d& jk = cross_nm[j * m + k];
        const double det = dot(planes[i].n, jk);
        if (std::abs(det) < 1e-9) continue;  // (nearly) parallel planes: no single vertex
        // Cramer's rule in the form x = (d_i (n_j×n_k) + d_j (n_k×n_i) + d_k (n_i×n_j)) / det.
        const Vec3d x = (jk * planes[i].d - cross_nm[i * m + k] * planes[j].d +
                         cross_nm[i * m + j] * planes[k].d) /
                        det;
        vertices.push_back({dot(problem.objective, x), x});
      }
    }
  }
  std::sort(vertices.begin(), vertices.end(),
            [](const Vertex& a, const Vertex& b) { return a.value < b.value; });

  std::optional<Vec3d> best;
  double best_value = 0, best_dist2 = std::numeric_limits<double>::infinity();
  const double tie = 1e-9 * length(problem.objective) * problem.half_size + 1e-300;
  for (const Vertex& v : vertices) {
    if (best && v.value > best_value + tie) break;
    if (!isFeasible(planes, v.x, tol)) continue;
    const Vec3d off = v.x - problem.center;
    const double dist2 = dot(off, off);
    if (!best) best_value = v.value;
    if (dist2 < best_dist2) {
      best = v.x;
      best_dist2 = dist2;
    }
  }
  return best;
}

}  // namespace proxyvis::lp
