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
//
// Given the input itself (options.bound), the last collapses may also move the surface toward
// it, tested exactly against the input (internal/input_bound.h), and a relaxation moves the
// vertices of the result inward (internal/relax_toward_input.h): docs/proxy_tightness.md.
#include "proxies/shared/bounded_simplify.h"

#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <boost/optional.hpp>

#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "mesh/cgal_bridge.h"
#include "proxies/shared/cgal/budget_stop.h"
#include "proxies/shared/internal/face_crossing.h"
#include "proxies/shared/internal/input_bound.h"
#include "proxies/shared/internal/refine_cycles.h"
#include "proxies/shared/internal/relax_toward_input.h"
#include "proxies/shared/plane_lp.h"
#include "util/error.h"

namespace proxyvis {
namespace {

namespace SMS = CGAL::Surface_mesh_simplification;
namespace PMP = CGAL::Polygon_mesh_processing;
using cgal::Point3;
using cgal::SurfaceMesh;
using Profile = SMS::Edge_profile<SurfaceMesh>;
using cgal::IdFace;

// With an input bound, nested collapses run down to this many times the budget, the tight
// ones from there (see simplifyBounded).
constexpr size_t kBoundPhaseFactor = 4;
// The tight phase tests every new face against every face of the mesh (box-culled): quadratic,
// so it starts at no more than this many faces, or at the budget when that is larger (the
// dragon's 2 % budget of 2,000 faces gets the relaxation only; nesting meets its targets).
// Where nesting stalls above it (an erosion's staircase), the tight phase starts there.
constexpr size_t kMaxTightFaces = 1500;
// Where nesting stalls far above that (a wrap of thousands of loose scan fragments stalled at
// 10 k faces and the tight phase then ran for minutes), the tight phase is skipped: the
// caller's budget ladder tries a coarser proxy instead.
constexpr size_t kMaxTightStartFaces = 4000;
// Relaxation passes after the budget is reached; the last ones gain little. Its test against
// the mesh itself scans every face: quadratic, so it runs up to kMaxRelaxFaces (the dragon's
// 2 % budget, ~0.2 s there).
constexpr int kRelaxSweeps = 4;
constexpr size_t kMaxRelaxFaces = 3000;
// Refinement cycles after the relaxation (internal/refine_cycles.h), on results of at most a
// quarter of kMaxRelaxFaces (the split mesh is relaxed). The first cycle gains most.
constexpr int kRefineCycles = 2;
// On the dragon's 2 % (2,000 faces) two cycles reached 1.081 outside and 0.888 inside instead
// of 1.132 and 0.844, but took 42 s and 19 s: the split mesh's input tests dominate.
constexpr size_t kMaxRefineFaces = kMaxRelaxFaces / 4;
// The cycles' input tests grow with proxy faces times input faces; above this product they
// cost more than the rest of proxy-gen for little: the open camelhead scan (454 x 22,704) took
// 18.8 s instead of 8.7 s, the dragon at 200 faces 16 s instead of 7.7 s for 1.747 instead of
// 1.774. Fandisk (288 x 14,454), the largest product below it, gains 0.005 in 2.7 s.
constexpr double kMaxRefineWork = 5e6;

Vec3d toVec(const Point3& p) {
  return {p.x(), p.y(), p.z()};
}

using Tri = std::array<Vec3d, 3>;

// The faces around a collapsing edge: `old_star` all of them, `kept` the (a, c) corners of the
// faces that survive as (a, x, c) once the edge becomes vertex x.
struct Star {
  std::vector<Tri> old_star;
  std::vector<std::array<Vec3d, 2>> kept;
  Vec3d p0, p1;
  explicit Star(const Profile& profile) : p0(toVec(profile.p0())), p1(toVec(profile.p1())) {
    const auto& vpm = profile.vertex_point_map();
    const auto& triangles = profile.triangles();
    const size_t first_kept =
        (profile.left_face_exists() ? 1 : 0) + (profile.right_face_exists() ? 1 : 0);
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
  // Volume added by moving the star to x (six times the signed tetrahedra, up to a constant).
  double addedVolume(const Vec3d& x) const {
    double before = 0, after = 0;
    for (const Tri& t : old_star) before += dot(t[0], cross(t[1], t[2]));
    for (const auto& k : kept) after += dot(k[0], cross(x, k[1]));
    return (after - before) / 6.0;
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
  const size_t first_kept =
      (profile.left_face_exists() ? 1 : 0) + (profile.right_face_exists() ? 1 : 0);
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
  if (cgal::anyTwoCross(star)) return false;
  std::vector<SurfaceMesh::Face_index> ring;
  for (auto u : profile.link())
    for (auto f : CGAL::faces_around_target(sm.halfedge(u), sm))
      if (f != SurfaceMesh::null_face()) ring.push_back(f);
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  for (auto f : ring) {
    const IdFace other = meshFace(sm, f);
    if (!inStar(other, profile) && cgal::anyCrosses(star, other)) return false;
  }
  return true;
}

// The second-phase replacement of locallyFree: each new face (a, x, c) against every face of
// the mesh that shares no corner with it, culled by cached face boxes (a linear scan: the
// second phase runs on at most kBoundPhaseFactor times the budget). Inward moves can reach a
// sheet of the mesh beyond the 2-ring (the dragon's folds), which the local test misses.
class GlobalFreeCheck {
 public:
  explicit GlobalFreeCheck(SurfaceMesh& sm) : sm_(sm) {
    boxes_ = sm.add_property_map<SurfaceMesh::Face_index, CGAL::Bbox_3>("f:pv_box").first;
    for (auto f : sm.faces()) boxes_[f] = faceBox(f);
  }
  ~GlobalFreeCheck() { sm_.remove_property_map(boxes_); }
  GlobalFreeCheck(const GlobalFreeCheck&) = delete;
  GlobalFreeCheck& operator=(const GlobalFreeCheck&) = delete;

  void onCollapsed(SurfaceMesh::Vertex_index kept) {
    for (auto f : CGAL::faces_around_target(sm_.halfedge(kept), sm_))
      if (f != SurfaceMesh::null_face()) boxes_[f] = faceBox(f);
  }

  bool allows(const Profile& profile, const Vec3d& xv) const {
    const std::vector<IdFace> star = newStar(profile, Point3(xv[0], xv[1], xv[2]));
    if (cgal::anyTwoCross(star)) return false;
    CGAL::Bbox_3 box;
    for (const IdFace& t : star)
      for (const Point3& p : t.p) box += p.bbox();
    for (auto f : sm_.faces()) {
      if (!CGAL::do_overlap(box, boxes_[f])) continue;
      const IdFace other = meshFace(sm_, f);
      if (!inStar(other, profile) && cgal::anyCrosses(star, other)) return false;
    }
    return true;
  }

 private:
  CGAL::Bbox_3 faceBox(SurfaceMesh::Face_index f) const {
    CGAL::Bbox_3 b;
    for (auto w : CGAL::vertices_around_face(sm_.halfedge(f), sm_)) b += sm_.point(w).bbox();
    return b;
  }
  SurfaceMesh& sm_;
  SurfaceMesh::Property_map<SurfaceMesh::Face_index, CGAL::Bbox_3> boxes_;
};

// Chooses where an edge collapses to. Without an input bound: the nested LP point. With one:
// the candidate of least added volume (often negative: corners are cut) that the input test
// allows, among the LP point, the edge's ends and midpoint and two points pulled toward the
// input; then a short bisection from the best refused candidate toward the chosen one.
class Placer {
 public:
  Placer(double max_move_edges, const TimeBudget* budget, const cgal::InputBound* bound,
         const GlobalFreeCheck* global)
      : max_move_edges_(max_move_edges), budget_(budget), bound_(bound), global_(global) {}

  // check_mesh: also test the new faces against the mesh itself (at collapse time only).
  std::optional<Vec3d> choose(const Profile& profile, bool check_mesh) const {
    if (budget_ && budget_->expired()) return std::nullopt;
    const Star star(profile);
    std::vector<Vec3d> candidates;
    const std::optional<Vec3d> nested = nestedPlacement(star, max_move_edges_);
    if (nested) candidates.push_back(*nested);
    if (bound_) {
      const Vec3d mid = (star.p0 + star.p1) * 0.5;
      const Vec3d near = bound_->closestPoint(mid);
      candidates.insert(candidates.end(), {star.p0, star.p1, mid, mid + (near - mid) * 0.5,
                                           mid + (near - mid) * 0.8});
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
      const Vec3d x = bound_ ? cgal::roundToFloat(candidates[i]) : candidates[i];
      if (star.keepsOrientation(x)) ranked.push_back({star.addedVolume(x), x});
    }
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const Ranked& a, const Ranked& b) { return a.added < b.added; });
    // The nested point is tested too: rounded to float, it may leave the old faces' planes by a
    // rounding error, and on a mesh already relaxed against the input that can reach it.
    auto valid = [&](const Vec3d& x) {
      if (bound_ && !bound_->allows(star.old_star, star.newStar(x))) return false;
      if (check_mesh && !(global_ ? global_->allows(profile, x) : locallyFree(profile, x)))
        return false;
      return true;
    };
    for (size_t i = 0; i < ranked.size(); ++i) {
      if (!valid(ranked[i].x)) continue;
      Vec3d lo = ranked[0].x, hi = ranked[i].x;  // lo refused (when i > 0), hi admissible
      for (int k = 0; i > 0 && k < kBisectionSteps; ++k) {
        const Vec3d m = cgal::roundToFloat((lo + hi) * 0.5);
        (star.keepsOrientation(m) && valid(m) ? hi : lo) = m;
      }
      return hi;
    }
    return std::nullopt;
  }

 private:
  // Measured on bunny/3holes/spot at 2 %: 0 -> 2 -> 3 steps lower the outside ratio by about
  // 0.02 each; more steps gain nothing measurable and cost input tests.
  static constexpr int kBisectionSteps = 3;
  double max_move_edges_;
  const TimeBudget* budget_;
  const cgal::InputBound* bound_;
  const GlobalFreeCheck* global_;
};

// Once the time budget is spent, no edge gets a placement: CGAL's initial pass over every edge
// then ends quickly, and the stop predicate ends the collapses.
struct PlacementPolicy {
  const Placer* placer;
  boost::optional<Point3> operator()(const Profile& profile) const {
    const std::optional<Vec3d> x = placer->choose(profile, false);
    if (!x) return boost::none;
    return Point3((*x)[0], (*x)[1], (*x)[2]);
  }
};

// Called by CGAL just before a collapse is carried out (not for every queued edge): the
// placement again, now also tested against the mesh itself. CGAL collapses to the placement it
// got from PlacementPolicy and reads only whether this returns one, so a placement that the
// mesh test moves elsewhere is refused rather than carried out unchecked.
struct MeshFilter {
  const Placer* placer;
  boost::optional<Point3> operator()(const Profile& profile,
                                     boost::optional<Point3> placement) const {
    if (!placement) return placement;
    const std::optional<Vec3d> x = placer->choose(profile, true);
    if (!x || Point3((*x)[0], (*x)[1], (*x)[2]) != *placement) return boost::none;
    return placement;
  }
};

// Cost = volume added by the collapse (negative when it cuts a corner, which only the input
// bound allows): cheap collapses first, the progressive-hull order.
struct AddedVolumeCost {
  bool signed_volume;  // false: clamped at 0 (nested collapses: negative only by rounding)
  boost::optional<double> operator()(const Profile& profile,
                                     const boost::optional<Point3>& placement) const {
    if (!placement) return boost::none;
    const double added = Star(profile).addedVolume(toVec(*placement));
    return signed_volume ? added : std::max(0.0, added);
  }
};

struct CollapseVisitor : SMS::Edge_collapse_visitor_base<SurfaceMesh> {
  size_t* count;
  GlobalFreeCheck* global = nullptr;
  CollapseVisitor(size_t* c, GlobalFreeCheck* g) : count(c), global(g) {}
  void OnCollapsed(const Profile&, SurfaceMesh::Vertex_index kept) {
    ++*count;
    if (global) global->onCollapsed(kept);
  }
};

// One run of CGAL's edge collapse down to max_faces; with `bound`, the tight second phase.
void collapse(SurfaceMesh& sm, size_t max_faces, const BoundedSimplifyOptions& options,
              const cgal::InputBound* bound, size_t* collapses) {
  // A closed triangle mesh has E = 3F/2 edges; CGAL's stop predicate counts edges.
  cgal::CountOrBudgetStop<SurfaceMesh> stop{
      SMS::Count_stop_predicate<SurfaceMesh>(max_faces * 3 / 2 + 1), options.budget};
  std::optional<GlobalFreeCheck> global;
  if (bound) global.emplace(sm);
  CollapseVisitor visitor(collapses, global ? &*global : nullptr);
  const Placer placer(options.max_move_edges, options.budget, bound, global ? &*global : nullptr);
  SMS::edge_collapse(sm, stop,
                     CGAL::parameters::get_cost(AddedVolumeCost{bound != nullptr})
                         .get_placement(PlacementPolicy{&placer})
                         .filter(MeshFilter{&placer})
                         .visitor(visitor));
  checkBudget(options.budget, "the face budget's edge collapse");
}

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
  auto finish = [&](TriMesh out) {
    if (inside) out = reversed(out);
    st.faces_after = out.numTriangles();
    st.budget_reached = st.faces_after <= options.max_faces;
    return out;
  };
  SurfaceMesh sm;
  if (!cgal::toSurfaceMesh(inside ? reversed(mesh) : mesh, sm) || !CGAL::is_closed(sm))
    throw Error(mesh.source, "cannot simplify with a containment bound",
                "the mesh is not a closed 2-manifold");

  if (options.bound) {
    // Nested collapses first, down to a few times the budget (at most kMaxTightFaces): measured
    // as tight as the input test all the way (its gain comes in the last collapses) and several
    // times faster. Tests that see only the neighbourhood cannot rule out every crossing of
    // the mesh with itself: a result that has one falls back to the previous stage.
    const size_t phase1 = std::min(kBoundPhaseFactor * options.max_faces,
                                   std::max(options.max_faces, kMaxTightFaces));
    if (sm.number_of_faces() > phase1) collapse(sm, phase1, options, nullptr, &st.collapses);
    sm.collect_garbage();
    // A large budget the nested phase met: neither phase 2 nor the relaxation pays there.
    if (sm.number_of_faces() <= options.max_faces && sm.number_of_faces() > kMaxRelaxFaces)
      return finish(cgal::fromSurfaceMesh(sm, mesh.source));
    if (sm.number_of_faces() > std::max(kMaxTightStartFaces, options.max_faces))
      return finish(cgal::fromSurfaceMesh(sm, mesh.source));
    const cgal::InputBound bound(*options.bound);
    SurfaceMesh nested = sm;
    if (sm.number_of_faces() > options.max_faces) {
      collapse(sm, options.max_faces, options, &bound, &st.collapses);
      sm.collect_garbage();
    }
    if (sm.number_of_faces() < nested.number_of_faces() && PMP::does_self_intersect(sm)) {
      sm = nested;
      collapse(sm, options.max_faces, options, nullptr, &st.collapses);
      sm.collect_garbage();
    }
    TriMesh out = cgal::fromSurfaceMesh(sm, mesh.source);
    if (out.numTriangles() > kMaxRelaxFaces) return finish(std::move(out));
    TriMesh relaxed = out;
    st.relaxed = cgal::relaxTowardInput(relaxed, bound, kRelaxSweeps, options.budget);
    checkBudget(options.budget, "the face budget's relaxation");
    if (st.relaxed > 0 && !cgal::crossesItself(relaxed))
      out = std::move(relaxed);
    else
      st.relaxed = 0;
    // Refinement cycles (internal/refine_cycles.h): the tight phase again, from a split and
    // relaxed copy of the result instead of from the nested mesh.
    auto collapse_to_budget = [&](const TriMesh& fine) -> std::optional<TriMesh> {
      SurfaceMesh fsm;
      if (!cgal::toSurfaceMesh(fine, fsm)) return std::nullopt;
      collapse(fsm, options.max_faces, options, &bound, &st.collapses);
      fsm.collect_garbage();
      if (fsm.number_of_faces() > options.max_faces) return std::nullopt;
      return cgal::fromSurfaceMesh(fsm, mesh.source);
    };
    if (out.numTriangles() <= kMaxRefineFaces &&
        double(out.numTriangles()) * double(options.bound->numTriangles()) <= kMaxRefineWork)
      st.refine_cycles = cgal::refineCycles(out, bound, kRefineCycles, kRelaxSweeps,
                                            collapse_to_budget, options.budget);
    return finish(std::move(out));
  }
  collapse(sm, options.max_faces, options, nullptr, &st.collapses);
  sm.collect_garbage();
  return finish(cgal::fromSurfaceMesh(sm, mesh.source));
}

}  // namespace proxyvis
