// Containment-preserving edge collapse.
//
// P. V. Sander, X. Gu, S. J. Gortler, H. Hoppe, J. Snyder, "Silhouette clipping", SIGGRAPH 2000,
// §3 (progressive hulls): collapsing edge (v0, v1) into x yields a mesh that contains the old
// one if x lies on or above the supporting plane of every face around v0 and v1. Among such x
// the one adding the least volume is the solution of a 3-variable LP (the added volume is
// linear in x). The inside variant is the same construction on the reversed mesh.
//
// CGAL Surface_mesh_simplification drives the collapses (priority queue, link condition); our
// placement solves the LP and refuses the collapse when it is infeasible or flips a face.
#include "proxies/outside/bounded_simplify.h"

#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <boost/optional.hpp>

#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "proxies/outside/internal/budget_stop.h"
#include "proxies/outside/internal/cgal_mesh.h"
#include "proxies/outside/internal/plane_lp.h"
#include "util/error.h"

namespace proxyvis {
namespace {

namespace SMS = CGAL::Surface_mesh_simplification;
using cgal::Point3;
using cgal::SurfaceMesh;
using Profile = SMS::Edge_profile<SurfaceMesh>;

Vec3d toVec(const Point3& p) {
  return {p.x(), p.y(), p.z()};
}

// The LP of one collapse: constraints from every face of the star, objective = the volume of
// the new faces (a, x, b), i.e. x · Σ (b × a) / 6 up to a constant.
boost::optional<Point3> placeOutside(const Profile& profile, double max_move_edges) {
  const auto& vpm = profile.vertex_point_map();
  const Vec3d p0 = toVec(profile.p0()), p1 = toVec(profile.p1());
  lp::PlaneLpProblem problem;
  problem.center = (p0 + p1) * 0.5;
  problem.half_size = std::max(max_move_edges * length(p1 - p0), 1e-30);
  problem.candidates = {p0, p1, problem.center};
  problem.objective = Vec3d(0, 0, 0);

  const auto& triangles = profile.triangles();
  size_t first_kept = (profile.left_face_exists() ? 1 : 0) + (profile.right_face_exists() ? 1 : 0);
  for (size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    const Vec3d a = toVec(get(vpm, t.v0)), b = toVec(get(vpm, t.v1)), c = toVec(get(vpm, t.v2));
    const Vec3d n = cross(b - a, c - a);
    problem.constraints.push_back({n, dot(n, a)});
    // Triangles after the two edge faces are (a, moving vertex, c) in face order.
    if (i >= first_kept) problem.objective += cross(c, a);
  }
  std::optional<Vec3d> x = lp::solvePlaneLp(problem);
  if (!x) return boost::none;

  // Reject fold-overs: every surviving face must keep a normal within 90° of its old one and a
  // non-vanishing area.
  for (size_t i = first_kept; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    const Vec3d a = toVec(get(vpm, t.v0)), b = toVec(get(vpm, t.v1)), c = toVec(get(vpm, t.v2));
    const Vec3d n_old = cross(b - a, c - a), n_new = cross(*x - a, c - a);
    const double len_new = length(n_new), len_old = length(n_old);
    if (!(len_new > 1e-12 * len_old) || dot(n_old, n_new) <= 0.2 * len_old * len_new)
      return boost::none;
  }
  return Point3((*x)[0], (*x)[1], (*x)[2]);
}

// Once the time budget is spent, no edge gets a placement: CGAL's initial pass over every edge
// (an LP each) then ends quickly, and the stop predicate ends the collapses.
struct OutsidePlacement {
  double max_move_edges;
  const TimeBudget* budget;
  boost::optional<Point3> operator()(const Profile& profile) const {
    if (budget && budget->expired()) return boost::none;
    return placeOutside(profile, max_move_edges);
  }
};

// Cost = volume added by the collapse (>= 0 up to rounding): cheap collapses first, the
// progressive-hull order.
struct AddedVolumeCost {
  boost::optional<double> operator()(const Profile& profile,
                                     const boost::optional<Point3>& placement) const {
    if (!placement) return boost::none;
    const auto& vpm = profile.vertex_point_map();
    const Vec3d x = toVec(*placement);
    double before = 0, after = 0;
    const auto& triangles = profile.triangles();
    size_t first_kept =
        (profile.left_face_exists() ? 1 : 0) + (profile.right_face_exists() ? 1 : 0);
    for (size_t i = 0; i < triangles.size(); ++i) {
      const auto& t = triangles[i];
      const Vec3d a = toVec(get(vpm, t.v0)), b = toVec(get(vpm, t.v1)), c = toVec(get(vpm, t.v2));
      before += dot(a, cross(b, c));
      if (i >= first_kept) after += dot(a, cross(x, c));
    }
    return std::max(0.0, (after - before) / 6.0);
  }
};

// Called by CGAL just before a collapse is carried out (not for every queued edge): rejects it
// when a new face would cross a face of the surrounding 2-ring that shares no vertex with it.
// The plane constraints keep the new surface on the right side of the old one, but they cannot
// see a nearby, non-adjacent sheet (a staircase of voxel faces, a fold); intersections farther
// away are left to the caller's exact check.
struct LocalIntersectionFilter {
  boost::optional<Point3> operator()(const Profile& profile,
                                     boost::optional<Point3> placement) const {
    if (!placement) return placement;
    const SurfaceMesh& sm = profile.surface_mesh();
    const auto v0 = profile.v0(), v1 = profile.v1();
    std::vector<SurfaceMesh::Face_index> ring;
    auto collect = [&](SurfaceMesh::Vertex_index u) {
      for (auto f : CGAL::faces_around_target(sm.halfedge(u), sm)) {
        if (f == SurfaceMesh::null_face()) continue;
        bool in_star = false;
        for (auto w : CGAL::vertices_around_face(sm.halfedge(f), sm))
          in_star |= (w == v0 || w == v1);
        if (!in_star) ring.push_back(f);
      }
    };
    for (auto u : profile.link()) collect(u);
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());

    const auto& triangles = profile.triangles();
    const size_t first_kept =
        (profile.left_face_exists() ? 1 : 0) + (profile.right_face_exists() ? 1 : 0);
    for (size_t i = first_kept; i < triangles.size(); ++i) {
      const auto& t = triangles[i];
      const cgal::Kernel::Triangle_3 moved(sm.point(t.v0), *placement, sm.point(t.v2));
      if (moved.is_degenerate()) return boost::none;
      for (auto f : ring) {
        std::array<SurfaceMesh::Vertex_index, 3> fv;
        int k = 0;
        bool shares = false;
        for (auto w : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
          shares |= (w == t.v0 || w == t.v2);
          fv[k++ % 3] = w;
        }
        if (shares) continue;
        if (CGAL::do_intersect(
                moved, cgal::Kernel::Triangle_3(sm.point(fv[0]), sm.point(fv[1]), sm.point(fv[2]))))
          return boost::none;
      }
    }
    return placement;
  }
};

struct CountCollapses : SMS::Edge_collapse_visitor_base<SurfaceMesh> {
  size_t* count;
  explicit CountCollapses(size_t* c) : count(c) {}
  void OnCollapsed(const Profile&, SurfaceMesh::Vertex_index) { ++*count; }
};

TriMesh reversed(const TriMesh& mesh) {
  TriMesh out = mesh;
  for (Triangle& t : out.triangles) std::swap(t[1], t[2]);
  return out;
}

}  // namespace

TriMesh simplifyBounded(const TriMesh& mesh, const BoundedSimplifyOptions& options,
                        BoundedSimplifyStats* stats) {
  BoundedSimplifyStats local;
  BoundedSimplifyStats& st = stats ? *stats : local;
  st = {};
  st.faces_before = st.faces_after = mesh.numTriangles();
  if (options.max_faces == 0 || mesh.numTriangles() <= options.max_faces) {
    st.budget_reached = true;
    return mesh;
  }
  if (mesh.signedVolume() <= 0)
    throw Error(mesh.source, "cannot simplify with a containment bound",
                "the mesh has no positive volume (open or inward oriented)");
  const bool inside = options.side == BoundSide::kInside;
  SurfaceMesh sm;
  if (!cgal::toSurfaceMesh(inside ? reversed(mesh) : mesh, sm) || !CGAL::is_closed(sm))
    throw Error(mesh.source, "cannot simplify with a containment bound",
                "the mesh is not a closed 2-manifold");

  // A closed triangle mesh has E = 3F/2 edges; CGAL's stop predicate counts edges.
  cgal::CountOrBudgetStop<SurfaceMesh> stop{
      SMS::Count_stop_predicate<SurfaceMesh>(options.max_faces * 3 / 2 + 1), options.budget};
  CountCollapses visitor(&st.collapses);
  SMS::edge_collapse(sm, stop,
                     CGAL::parameters::get_cost(AddedVolumeCost())
                         .get_placement(OutsidePlacement{options.max_move_edges, options.budget})
                         .filter(LocalIntersectionFilter())
                         .visitor(visitor));
  checkBudget(options.budget, "the face budget's edge collapse");
  sm.collect_garbage();
  TriMesh out = cgal::fromSurfaceMesh(sm, mesh.source);
  if (inside) out = reversed(out);
  st.faces_after = out.numTriangles();
  st.budget_reached = st.faces_after <= options.max_faces;
  return out;
}

}  // namespace proxyvis
