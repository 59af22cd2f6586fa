#pragma once
// General proxies: simplified meshes with no containment guarantee (both HM' and MH' rays are
// possible). Three simplifiers, compared by bench/proxy_gen: OpenMesh's Decimater (quadric error
// metric), CGAL's edge collapse with Garland-Heckbert policies, and meshoptimizer.
#include <cstddef>

#include "mesh/tri_mesh.h"
#include "proxies/shared/time_budget.h"

namespace proxyvis {

struct GeneralOptions {
  size_t max_faces = 0;  // face budget; 0 = use ratio
  double ratio = 0.02;   // target faces as a fraction of the input's (when max_faces == 0)
  // qem only: also bound the one-sided Hausdorff distance (OpenMesh ModHausdorff), as a
  // fraction of the diagonal; 0 = off.
  double hausdorff = 0;
  const TimeBudget* budget = nullptr;  // polled while decimating (qem, cgal-sms); null = no limit
};

// The face budget the options ask for on `input` (at least 4).
size_t generalTargetFaces(const TriMesh& input, const GeneralOptions& options);

// Equal positions welded into one vertex (the simplifiers need shared vertices); unreferenced
// vertices dropped.
TriMesh weldVertices(const TriMesh& input);

// The three simplifiers throw Error when requireProxyGeometry (proxies/shared) refuses the input
// (it needs a surface) or when options.budget is spent.

// Work done by simplifyQem (for tests and benchmarks: counts, not times).
struct QemStats {
  size_t collapses = 0;
  size_t legality_tests = 0;  // OpenMesh collapse legality tests (the costly part of a choice)
};

// OpenMesh Decimater: ModQuadric + ModNormalFlipping (+ ModHausdorff when requested), mixed
// multiple choice and priority queue (proxies/general/qem_decimater.h). Faces that OpenMesh
// cannot add (non-manifold, or degenerate after welding) are skipped.
TriMesh simplifyQem(const TriMesh& input, const GeneralOptions& options, QemStats* stats = nullptr);

// CGAL Surface_mesh_simplification::edge_collapse with GarlandHeckbert_plane_policies.
TriMesh simplifyCgalSms(const TriMesh& input, const GeneralOptions& options);

// meshoptimizer meshopt_simplify (topology preserving), then meshopt_simplifySloppy when that
// stalls above the budget.
TriMesh simplifyMeshopt(const TriMesh& input, const GeneralOptions& options);

}  // namespace proxyvis
