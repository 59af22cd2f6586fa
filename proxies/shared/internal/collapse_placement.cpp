// Where one bounded edge collapse places its vertex (collapse_placement.h): the progressive-hull
// LP, the candidates toward the input, the orientation test and the tests against the mesh.
#include "proxies/shared/internal/collapse_placement.h"

#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <vector>

#include "proxies/shared/internal/face_crossing.h"
#include "proxies/shared/plane_lp.h"

namespace proxyvis::cgal {
namespace {

using Profile = CollapseProfile;

Vec3d toVec(const Point3& p) {
  return {p.x(), p.y(), p.z()};
}

using Tri = std::array<Vec3d, 3>;

// CGAL lists the faces of the collapsing edge first (those that exist), then the faces
// (a, moving vertex, c) that survive it: the index of the first of those.
size_t firstKept(const Profile& profile) {
  return (profile.left_face_exists() ? 1 : 0) + (profile.right_face_exists() ? 1 : 0);
}

// The faces around a collapsing edge: `old_star` all of them, `kept` the (a, c) corners of the
// faces that survive as (a, x, c) once the edge becomes vertex x.
struct Star {
  std::vector<Tri> old_star;
  std::vector<std::array<Vec3d, 2>> kept;
  Vec3d p0, p1;
  explicit Star(const Profile& profile) : p0(toVec(profile.p0())), p1(toVec(profile.p1())) {
    const auto& vpm = profile.vertex_point_map();
    const auto& triangles = profile.triangles();
    const size_t first_kept = firstKept(profile);
    old_star.reserve(triangles.size());
    kept.reserve(triangles.size());
    for (size_t i = 0; i < triangles.size(); ++i) {
      const auto& t = triangles[i];
      const Tri tri{toVec(get(vpm, t.v0)), toVec(get(vpm, t.v1)), toVec(get(vpm, t.v2))};
      old_star.push_back(tri);
      // Triangles after the two edge faces are (a, moving vertex, c) in face order.
      if (i >= first_kept) kept.push_back({tri[0], tri[2]});
    }
  }
  std::vector<Tri> newStar(const Vec3d& x) const {
    std::vector<Tri> out;
    out.reserve(kept.size());
    for (const auto& k : kept) out.push_back({k[0], x, k[1]});
    return out;
  }
  // No surviving face may flip (normal within ~78° of its old one) or vanish.
  bool keepsOrientation(const Vec3d& x) const {
    for (size_t i = old_star.size() - kept.size(), j = 0; j < kept.size(); ++i, ++j) {
      const Tri& t = old_star[i];
      const Vec3d n_old = cross(t[1] - t[0], t[2] - t[0]), n_new = cross(x - t[0], t[2] - t[0]);
      const double len_new = length(n_new), len_old = length(n_old);
      if (!(len_new > 1e-12 * len_old) || dot(n_old, n_new) <= 0.2 * len_old * len_new)
        return false;
    }
    return true;
  }
};

// The nested placement: the LP of one collapse, constraints from every face of the star,
// objective = the volume of the new faces (a, x, c), i.e. x · Σ (c × a) / 6 up to a constant.
std::optional<Vec3d> nestedPlacement(const Star& star, double max_move_edges) {
  lp::PlaneLpProblem problem;
  problem.center = (star.p0 + star.p1) * 0.5;
  problem.half_size = std::max(max_move_edges * length(star.p1 - star.p0), 1e-30);
  problem.candidates = {star.p0, star.p1, problem.center};
  problem.objective = Vec3d(0, 0, 0);
  problem.constraints.reserve(star.old_star.size());
  for (const Tri& t : star.old_star) {
    const Vec3d n = cross(t[1] - t[0], t[2] - t[0]);
    problem.constraints.push_back({n, dot(n, t[0])});
  }
  for (const auto& k : star.kept) problem.objective += cross(k[1], k[0]);
  return lp::solvePlaneLp(problem);
}

constexpr uint32_t kPlacedId = ~0u;  // the id of the vertex being placed

uint32_t idOf(SurfaceMesh::Vertex_index v) {
  return uint32_t(v.idx());
}

IdFace meshFace(const SurfaceMesh& sm, SurfaceMesh::Face_index f) {
  IdFace out;
  int k = 0;
  for (auto w : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
    if (k == 3) break;
    out.p[k] = sm.point(w), out.id[k] = idOf(w), ++k;
  }
  return out;
}

// The faces (a, x, c) that replace the star of the collapsing edge.
std::vector<IdFace> newStar(const Profile& profile, const Point3& x) {
  const SurfaceMesh& sm = profile.surface_mesh();
  const auto& triangles = profile.triangles();
  const size_t first_kept = firstKept(profile);
  std::vector<IdFace> out;
  for (size_t i = first_kept; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    out.push_back({{sm.point(t.v0), x, sm.point(t.v2)}, {idOf(t.v0), kPlacedId, idOf(t.v2)}});
  }
  return out;
}

bool inStar(const IdFace& f, const Profile& profile) {
  const uint32_t v0 = idOf(profile.v0()), v1 = idOf(profile.v1());
  for (uint32_t id : f.id)
    if (id == v0 || id == v1) return true;
  return false;
}

// True when no new face (a, x, c) crosses a face of the surrounding 2-ring (the faces around the
// edge's link). The plane constraints (or the input test) keep the new surface on the right
// side of the old one (or of the input), but they cannot see a nearby, non-adjacent sheet of
// the mesh itself (a staircase of voxel faces, a fold); intersections farther away are left to
// the caller's exact check.
bool locallyFree(const Profile& profile, const Vec3d& xv) {
  const SurfaceMesh& sm = profile.surface_mesh();
  const std::vector<IdFace> star = newStar(profile, Point3(xv[0], xv[1], xv[2]));
  if (anyTwoCross(star)) return false;
  std::vector<SurfaceMesh::Face_index> ring;
  for (auto u : profile.link())
    for (auto f : CGAL::faces_around_target(sm.halfedge(u), sm))
      if (f != SurfaceMesh::null_face()) ring.push_back(f);
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  for (auto f : ring) {
    const IdFace other = meshFace(sm, f);
    if (!inStar(other, profile) && anyCrosses(star, other)) return false;
  }
  return true;
}

}  // namespace

// Volume added by moving the star to x (six times the signed tetrahedra, up to a constant), read
// from the profile without building a Star: CGAL asks for it for every edge whose placement it
// (re)computes.
double addedVolume(const Profile& profile, const Point3& xp) {
  const Vec3d x = toVec(xp);
  const auto& vpm = profile.vertex_point_map();
  const auto& triangles = profile.triangles();
  const size_t first_kept = firstKept(profile);
  double before = 0, after = 0;
  for (size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    const Vec3d a = toVec(get(vpm, t.v0)), b = toVec(get(vpm, t.v1)), c = toVec(get(vpm, t.v2));
    before += dot(a, cross(b, c));
    if (i >= first_kept) after += dot(a, cross(x, c));
  }
  return (after - before) / 6.0;
}

GlobalFreeCheck::GlobalFreeCheck(SurfaceMesh& sm) : sm_(sm) {
  boxes_ = sm.add_property_map<SurfaceMesh::Face_index, CGAL::Bbox_3>("f:pv_box").first;
  for (auto f : sm.faces()) boxes_[f] = faceBox(f);
}
GlobalFreeCheck::~GlobalFreeCheck() {
  sm_.remove_property_map(boxes_);
}

void GlobalFreeCheck::onCollapsed(SurfaceMesh::Vertex_index kept) {
  for (auto f : CGAL::faces_around_target(sm_.halfedge(kept), sm_))
    if (f != SurfaceMesh::null_face()) boxes_[f] = faceBox(f);
}

bool GlobalFreeCheck::allows(const Profile& profile, const Vec3d& xv) const {
  const std::vector<IdFace> star = newStar(profile, Point3(xv[0], xv[1], xv[2]));
  if (anyTwoCross(star)) return false;
  CGAL::Bbox_3 box;
  for (const IdFace& t : star)
    for (const Point3& p : t.p) box += p.bbox();
  for (auto f : sm_.faces()) {
    if (!CGAL::do_overlap(box, boxes_[f])) continue;
    const IdFace other = meshFace(sm_, f);
    if (!inStar(other, profile) && anyCrosses(star, other)) return false;
  }
  return true;
}

CGAL::Bbox_3 GlobalFreeCheck::faceBox(SurfaceMesh::Face_index f) const {
  CGAL::Bbox_3 b;
  for (auto w : CGAL::vertices_around_face(sm_.halfedge(f), sm_)) b += sm_.point(w).bbox();
  return b;
}

std::optional<Vec3d> Placer::choose(const Profile& profile, bool check_mesh) const {
  if (budget_ && budget_->expired()) return std::nullopt;
  const Star star(profile);
  std::vector<Vec3d> candidates;
  const std::optional<Vec3d> nested = nestedPlacement(star, max_move_edges_);
  if (nested) candidates.push_back(*nested);
  if (bound_) {
    const Vec3d mid = (star.p0 + star.p1) * 0.5;
    const Vec3d near = bound_->closestPoint(mid);
    candidates.insert(candidates.end(),
                      {star.p0, star.p1, mid, mid + (near - mid) * 0.5, mid + (near - mid) * 0.8});
    if (nested) candidates.push_back((*nested + mid) * 0.5);
  }
  struct Ranked {
    double added;
    Vec3d x;
  };
  std::vector<Ranked> ranked;
  for (size_t i = 0; i < candidates.size(); ++i) {
    // Only tested points are rounded: the nested phase keeps its exact LP point, as it
    // always has (its outputs are unchanged by the input bound's arrival).
    const Vec3d x = bound_ ? roundToFloat(candidates[i]) : candidates[i];
    if (star.keepsOrientation(x))
      ranked.push_back({addedVolume(profile, Point3(x[0], x[1], x[2])), x});
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const Ranked& a, const Ranked& b) { return a.added < b.added; });
  // The nested point is tested too: rounded to float, it may leave the old faces' planes by a
  // rounding error, and on a mesh already relaxed against the input that can reach it.
  size_t first_touch = 0;  // the new face that refused the last candidate
  auto valid = [&](const Vec3d& x) {
    if (bound_ && !bound_->allows(star.old_star, star.newStar(x), &first_touch)) return false;
    if (check_mesh && !(global_ ? global_->allows(profile, x) : locallyFree(profile, x)))
      return false;
    return true;
  };
  for (size_t i = 0; i < ranked.size(); ++i) {
    if (!valid(ranked[i].x)) continue;
    Vec3d lo = ranked[0].x, hi = ranked[i].x;  // lo refused (when i > 0), hi admissible
    for (int k = 0; i > 0 && k < kBisectionSteps; ++k) {
      const Vec3d m = roundToFloat((lo + hi) * 0.5);
      (star.keepsOrientation(m) && valid(m) ? hi : lo) = m;
    }
    return hi;
  }
  return std::nullopt;
}

}  // namespace proxyvis::cgal
