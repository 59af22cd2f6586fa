// Vertex enumeration for a 3-D linear program: the optimum of a bounded feasible LP is attained
// at a vertex of the feasible polytope, i.e. at the intersection of three constraint planes.
#include "proxies/shared/plane_lp.h"

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
std::vector<Plane> normalizePlanes(const PlaneLpProblem& problem, size_t& num_constraints) {
  std::vector<Plane> planes;
  planes.reserve(problem.constraints.size() + 6);
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
  num_constraints = planes.size();
  for (int axis = 0; axis < 3; ++axis) {
    Vec3d e(0, 0, 0);
    e[axis] = 1;
    add(e, problem.center[axis] - problem.half_size);
    add(-e, -(problem.center[axis] + problem.half_size));
  }
  return planes;
}

// Most tested vertices are infeasible, and the plane that cut the last one usually cuts the
// next: it is tested first (`last_cut`), which makes a rejection about one dot product.
bool isFeasible(const std::vector<Plane>& planes, const Vec3d& x, double tol, size_t& last_cut) {
  if (dot(planes[last_cut].n, x) < planes[last_cut].d - tol) return false;
  for (size_t i = 0; i < planes.size(); ++i) {
    if (dot(planes[i].n, x) < planes[i].d - tol) {
      last_cut = i;
      return false;
    }
  }
  return true;
}

}  // namespace

std::optional<Vec3d> solvePlaneLp(const PlaneLpProblem& problem) {
  size_t s = 0;
  const std::vector<Plane> planes = normalizePlanes(problem, s);
  const double tol = 1e-9 * problem.half_size;
  const size_t m = planes.size();

  // Upper bound from the extra candidates, then only vertices that can beat it are tested for
  // feasibility (most are cut by one dot product), in enumeration order.
  std::optional<Vec3d> best;
  double best_value = std::numeric_limits<double>::infinity();
  double best_dist2 = std::numeric_limits<double>::infinity();
  const double tie = 1e-9 * length(problem.objective) * problem.half_size + 1e-300;
  size_t last_cut = 0;
  auto consider = [&](const Vec3d& x) {
    const double value = dot(problem.objective, x);
    if (value > best_value + tie) return;
    if (!isFeasible(planes, x, tol, last_cut)) return;
    const Vec3d off = x - problem.center;
    const double dist2 = dot(off, off);
    if (value < best_value - tie) {
      best_value = value;
      best = x;
      best_dist2 = dist2;
    } else if (dist2 < best_dist2) {
      best_value = std::min(best_value, value);
      best = x;
      best_dist2 = dist2;
    }
  };
  for (const Vec3d& x : problem.candidates) consider(x);

  // Pairwise cross products and their objective values give each vertex's objective in a few
  // flops (Cramer's rule dotted with the objective), so the vertex itself is computed only
  // when it can beat the best so far; twice the tie tolerance covers the two roundings.
  std::vector<Vec3d> cross_nm(m * m);
  std::vector<double> cross_value(m * m);
  for (size_t i = 0; i < m; ++i)
    for (size_t j = i + 1; j < m; ++j) {
      cross_nm[i * m + j] = cross(planes[i].n, planes[j].n);
      cross_value[i * m + j] = dot(problem.objective, cross_nm[i * m + j]);
    }
  // Pass 1: vertices of the constraint planes alone (C(s,3) instead of C(s+6,3) triples). Any
  // feasible one inside the box will do: optimality only affects quality, feasibility is what
  // keeps containment. Pass 2, with the box planes, only when pass 1 found nothing.
  auto enumerate = [&](bool with_box) {
    const size_t k_begin = with_box ? s : 0, k_end = with_box ? m : s;
    for (size_t i = 0; i < m; ++i) {
      for (size_t j = i + 1; j < m; ++j) {
        for (size_t k = std::max(j + 1, k_begin); k < k_end; ++k) {
          const Vec3d& jk = cross_nm[j * m + k];
          const double det = dot(planes[i].n, jk);
          if (std::abs(det) < 1e-9) continue;  // (nearly) parallel planes: no single vertex
          const double di = planes[i].d, dj = planes[j].d, dk = planes[k].d;
          const double value = (di * cross_value[j * m + k] - dj * cross_value[i * m + k] +
                                dk * cross_value[i * m + j]) /
                               det;
          if (value > best_value + 2 * tie) continue;
          // Cramer's rule: x = (d_i (n_j×n_k) + d_j (n_k×n_i) + d_k (n_i×n_j)) / det.
          consider((jk * di - cross_nm[i * m + k] * dj + cross_nm[i * m + j] * dk) / det);
        }
      }
    }
  };
  enumerate(false);
  if (!best) enumerate(true);
  return best;
}

}  // namespace proxyvis::lp
