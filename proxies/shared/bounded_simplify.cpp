// Containment-preserving edge collapse.
//
// P. V. Sander, X. Gu, S. J. Gortler, H. Hoppe, J. Snyder, "Silhouette clipping", SIGGRAPH 2000,
// §3 (progressive hulls): collapsing edge (v0, v1) into x yields a mesh that contains the old
// one if x lies on or above the supporting plane of every face around v0 and v1. Among such x
// the one adding the least volume is the solution of a 3-variable LP (the added volume is
// linear in x). The inside variant is the same construction on the reversed mesh.
//
// CGAL Surface_mesh_simplification drives the collapses (priority queue, link condition); our
// placement (internal/collapse_placement.h) solves the LP and refuses the collapse when it is
// infeasible or flips a face. This file runs the phases.
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

#include <algorithm>
#include <optional>
#include <string>

#include "mesh/cgal_bridge.h"
#include "proxies/shared/cgal/budget_stop.h"
#include "proxies/shared/internal/collapse_placement.h"
#include "proxies/shared/internal/input_bound.h"
#include "proxies/shared/internal/refine_cycles.h"
#include "proxies/shared/internal/relax_toward_input.h"
#include "util/error.h"

namespace proxyvis {
namespace {

namespace SMS = CGAL::Surface_mesh_simplification;
namespace PMP = CGAL::Polygon_mesh_processing;
using cgal::Point3;
using cgal::SurfaceMesh;
using Profile = cgal::CollapseProfile;

// Once the time budget is spent, no edge gets a placement: CGAL's initial pass over every edge
// then ends quickly, and the stop predicate ends the collapses.
struct PlacementPolicy {
  const cgal::Placer* placer;
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
  const cgal::Placer* placer;
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
    const double added = cgal::addedVolume(profile, *placement);
    return signed_volume ? added : std::max(0.0, added);
  }
};

struct CollapseVisitor : SMS::Edge_collapse_visitor_base<SurfaceMesh> {
  size_t* count;
  cgal::GlobalFreeCheck* global = nullptr;
  CollapseVisitor(size_t* c, cgal::GlobalFreeCheck* g) : count(c), global(g) {}
  void OnCollapsed(const Profile&, SurfaceMesh::Vertex_index kept) {
    ++*count;
    if (global) global->onCollapsed(kept);
  }
};

// One run of CGAL's edge collapse down to max_faces; with `bound`, the tight phase.
void collapse(SurfaceMesh& sm, size_t max_faces, const BoundedSimplifyOptions& options,
              const cgal::InputBound* bound, size_t* collapses) {
  // A closed triangle mesh has E = 3F/2 edges; CGAL's stop predicate counts edges.
  cgal::CountOrBudgetStop<SurfaceMesh> stop{
      SMS::Count_stop_predicate<SurfaceMesh>(max_faces * 3 / 2 + 1), options.budget};
  std::optional<cgal::GlobalFreeCheck> global;
  if (bound) global.emplace(sm);
  CollapseVisitor visitor(collapses, global ? &*global : nullptr);
  const cgal::Placer placer(options.max_move_edges, options.budget, bound,
                            global ? &*global : nullptr);
  SMS::edge_collapse(sm, stop,
                     CGAL::parameters::get_cost(AddedVolumeCost{bound != nullptr})
                         .get_placement(PlacementPolicy{&placer})
                         .filter(MeshFilter{&placer})
                         .visitor(visitor));
  checkBudget(options.budget, "the face budget's edge collapse");
}

// With an input bound, nested collapses run down to this many times the budget, the tight
// ones from there (see simplifyBounded).
constexpr size_t kBoundPhaseFactor = 4;
// The tight phase tests every new face against every face of the mesh (box-culled): quadratic,
// so it starts at no more than this many faces for budgets below it. Where nesting stalls
// above it (an erosion's staircase), the tight phase starts there.
constexpr size_t kMaxTightFaces = 1500;
// Where nesting stalls far above that (a wrap of thousands of loose scan fragments stalled at
// 10 k faces and the tight phase then ran for minutes), the tight phase is skipped: the
// caller's budget ladder tries a coarser proxy instead.
constexpr size_t kMaxTightStartFaces = 4000;

// Where the tight phase starts: kBoundPhaseFactor times a small budget, at most kMaxTightFaces;
// for an inside proxy, twice a budget of at least kMaxTightFaces, at most kMaxTightStartFaces.
// Such budgets used to be met by nesting alone: with its last 2,000 collapses tight, the
// dragon's inside proxy at 2 % (2,000 faces) went from 0.841 to 0.856 of the volume, in 5.3 s
// instead of 3.2 s. Outside, the same took it from 1.131 to 1.104 but from 3.2 to 6.2 s, past
// the 5 s an outside wrap at 2 % may take (docs/proxy_speed.md), so outside keeps nesting alone
// there. Budgets just below kMaxTightFaces keep their short tight phase: bun_zipper's (1,388
// faces) from twice would cost 1.4 s more on a run that is already the slowest.
size_t tightStartFaces(size_t budget, BoundSide side) {
  if (budget >= kMaxTightFaces)
    return side == BoundSide::kInside ? std::max(budget, std::min(2 * budget, kMaxTightStartFaces))
                                      : budget;
  return std::min(kBoundPhaseFactor * budget, kMaxTightFaces);
}

// Relaxation passes after the budget is reached; the last ones gain little. Its test against
// the mesh itself scans every face: quadratic, so it runs up to kMaxRelaxFaces (the dragon's
// 2 % budget, ~0.2 s there).
constexpr int kRelaxSweeps = 4;
constexpr size_t kMaxRelaxFaces = 3000;

// The nested phase with an input bound: collapses down to a few times the budget
// (tightStartFaces), measured as tight as the input test all the way (its gain comes in the last
// collapses) and several times faster. False when its result is final: a large budget it met
// (neither the tight phase nor the relaxation pays there), or too many faces left for the tight
// phase.
bool nestedPhase(SurfaceMesh& sm, const BoundedSimplifyOptions& options, size_t* collapses) {
  const size_t phase1 = tightStartFaces(options.max_faces, options.side);
  if (sm.number_of_faces() > phase1) collapse(sm, phase1, options, nullptr, collapses);
  sm.collect_garbage();
  if (sm.number_of_faces() <= options.max_faces && sm.number_of_faces() > kMaxRelaxFaces)
    return false;
  return sm.number_of_faces() <= std::max(kMaxTightStartFaces, options.max_faces);
}

// The tight phase: collapses to the budget tested against the input. Its tests see only the
// neighbourhood and cannot rule out every crossing of the mesh with itself: a result that has
// one falls back to nested collapses from the previous stage.
void tightPhase(SurfaceMesh& sm, const BoundedSimplifyOptions& options,
                const cgal::InputBound& bound, size_t* collapses) {
  const SurfaceMesh nested = sm;
  if (sm.number_of_faces() > options.max_faces) {
    collapse(sm, options.max_faces, options, &bound, collapses);
    sm.collect_garbage();
  }
  if (sm.number_of_faces() < nested.number_of_faces() && PMP::does_self_intersect(sm)) {
    sm = nested;
    collapse(sm, options.max_faces, options, nullptr, collapses);
    sm.collect_garbage();
  }
}

// The relaxation (internal/relax_toward_input.h), kept when it moved something and the result
// does not cross itself.
void relaxPhase(TriMesh& out, const cgal::InputBound& bound, const TimeBudget* budget,
                BoundedSimplifyStats& st) {
  TriMesh relaxed = out;
  st.relaxed = cgal::relaxTowardInput(relaxed, bound, kRelaxSweeps, budget);
  checkBudget(budget, "the face budget's relaxation");
  if (st.relaxed > 0 && !cgal::crossesItself(relaxed))
    out = std::move(relaxed);
  else
    st.relaxed = 0;
}

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

// The refinement cycles: the tight phase again, from a split and relaxed copy of the result
// instead of from the nested mesh; on small enough results only.
void refinePhase(TriMesh& out, const BoundedSimplifyOptions& options, const cgal::InputBound& bound,
                 const std::string& source, BoundedSimplifyStats& st) {
  if (out.numTriangles() > kMaxRefineFaces ||
      double(out.numTriangles()) * double(options.bound->numTriangles()) > kMaxRefineWork)
    return;
  auto collapse_to_budget = [&](const TriMesh& fine) -> std::optional<TriMesh> {
    SurfaceMesh fsm;
    if (!cgal::toSurfaceMesh(fine, fsm)) return std::nullopt;
    collapse(fsm, options.max_faces, options, &bound, &st.collapses);
    fsm.collect_garbage();
    if (fsm.number_of_faces() > options.max_faces) return std::nullopt;
    return cgal::fromSurfaceMesh(fsm, source);
  };
  st.refine_cycles = cgal::refineCycles(out, bound, kRefineCycles, kRelaxSweeps, collapse_to_budget,
                                        options.budget);
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
  if (!options.bound) {
    collapse(sm, options.max_faces, options, nullptr, &st.collapses);
    sm.collect_garbage();
    return finish(cgal::fromSurfaceMesh(sm, mesh.source));
  }
  if (!nestedPhase(sm, options, &st.collapses))
    return finish(cgal::fromSurfaceMesh(sm, mesh.source));
  const cgal::InputBound bound(*options.bound, options.clearance);
  tightPhase(sm, options, bound, &st.collapses);
  TriMesh out = cgal::fromSurfaceMesh(sm, mesh.source);
  if (out.numTriangles() <= kMaxRelaxFaces) {
    relaxPhase(out, bound, options.budget, st);
    refinePhase(out, options, bound, mesh.source, st);
  }
  return finish(std::move(out));
}

}  // namespace proxyvis
