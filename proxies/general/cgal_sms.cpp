// CGAL edge collapse with Garland-Heckbert plane quadrics (CGAL 5.5
// GarlandHeckbert_plane_policies).
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include "proxies/general/general_proxy.h"
#include "proxies/shared/cgal/budget_stop.h"
#include "proxies/shared/cgal/weld.h"
#include "proxies/shared/input_geometry.h"

namespace proxyvis {

TriMesh simplifyCgalSms(const TriMesh& input, const GeneralOptions& options) {
  namespace SMS = CGAL::Surface_mesh_simplification;
  using cgal::SurfaceMesh;
  requireProxyGeometry(input, GeometryNeed::kSurface, "a cgal-sms proxy");
  SurfaceMesh sm = cgal::toWeldedMesh(input);

  const size_t target = generalTargetFaces(input, options);
  // Edges of a closed triangle mesh: 3F/2; the stop predicate counts edges.
  cgal::CountOrBudgetStop<SurfaceMesh> stop{
      SMS::Count_stop_predicate<SurfaceMesh>(target * 3 / 2 + 1), options.budget};
  using Policies = SMS::GarlandHeckbert_plane_policies<SurfaceMesh, cgal::Kernel>;
  Policies policies(sm);
  SMS::edge_collapse(
      sm, stop,
      CGAL::parameters::get_cost(policies.get_cost()).get_placement(policies.get_placement()));
  checkBudget(options.budget, "the cgal-sms edge collapse");
  sm.collect_garbage();
  return cgal::fromSurfaceMesh(sm, "cgal-sms of " + input.source);
}

}  // namespace proxyvis
