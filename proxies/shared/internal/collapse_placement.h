#pragma once
// Private to pv_proxy_shared: where one edge collapse of simplifyBounded (bounded_simplify.cpp)
// puts the merged vertex, and whether it may go there. Without an input bound the point is the
// solution of the progressive-hull LP (Sander et al., "Silhouette clipping", SIGGRAPH 2000, §3):
// on or above the plane of every face around the edge, adding the least volume. With one, the
// candidate of least added volume that the input test (input_bound.h) allows. Either way no
// surviving face may flip and, at collapse time, no new face may cross the mesh itself.
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_profile.h>

#include <optional>

#include "mesh/cgal_bridge.h"
#include "proxies/shared/internal/input_bound.h"
#include "proxies/shared/time_budget.h"
#include "util/vec3.h"

namespace proxyvis::cgal {

using CollapseProfile = CGAL::Surface_mesh_simplification::Edge_profile<SurfaceMesh>;

// Volume added by collapsing the profile's edge to x (negative when it cuts a corner).
double addedVolume(const CollapseProfile& profile, const Point3& x);

// The test of the tight phase against the mesh itself: each new face (a, x, c) against every
// face of the mesh that shares no corner with it, culled by cached face boxes (a linear scan:
// the tight phase runs on a few times the budget). Inward moves can reach a sheet of the mesh
// beyond the 2-ring (the dragon's folds), which the local test of the nested phase misses.
class GlobalFreeCheck {
 public:
  explicit GlobalFreeCheck(SurfaceMesh& sm);
  ~GlobalFreeCheck();
  GlobalFreeCheck(const GlobalFreeCheck&) = delete;
  GlobalFreeCheck& operator=(const GlobalFreeCheck&) = delete;

  // Updates the boxes of the faces around the vertex an edge was collapsed into.
  void onCollapsed(SurfaceMesh::Vertex_index kept);
  bool allows(const CollapseProfile& profile, const Vec3d& xv) const;

 private:
  CGAL::Bbox_3 faceBox(SurfaceMesh::Face_index f) const;
  SurfaceMesh& sm_;
  SurfaceMesh::Property_map<SurfaceMesh::Face_index, CGAL::Bbox_3> boxes_;
};

// Chooses where an edge collapses to. Without an input bound: the nested LP point. With one:
// the candidate of least added volume (often negative: corners are cut) that the input test
// allows, among the LP point, the edge's ends and midpoint and two points pulled toward the
// input; then a short bisection from the best refused candidate toward the chosen one.
class Placer {
 public:
  // budget, bound, global: may be null (no limit; nested collapses; the local mesh test).
  Placer(double max_move_edges, const TimeBudget* budget, const InputBound* bound,
         const GlobalFreeCheck* global)
      : max_move_edges_(max_move_edges), budget_(budget), bound_(bound), global_(global) {}

  // check_mesh: also test the new faces against the mesh itself (at collapse time only).
  // Nothing once the time budget is spent.
  std::optional<Vec3d> choose(const CollapseProfile& profile, bool check_mesh) const;

 private:
  // Measured on bunny/3holes/spot at 2 %: 0 -> 2 -> 3 steps lower the outside ratio by about
  // 0.02 each; more steps gain nothing measurable and cost input tests.
  static constexpr int kBisectionSteps = 3;
  double max_move_edges_;
  const TimeBudget* budget_;
  const InputBound* bound_;
  const GlobalFreeCheck* global_;
};

}  // namespace proxyvis::cgal
