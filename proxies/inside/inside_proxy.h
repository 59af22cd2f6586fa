#pragma once
// Inside proxies: closed meshes contained in a closed input (no MH' rays, docs/design.md). Sizes
// are fractions of the input's bounding-box diagonal. These functions only build; the caller
// (proxies/pipeline/proxy_pipeline.h) verifies containment exactly before anything is written.
#include <cstddef>

#include "mesh/tri_mesh.h"
#include "proxies/shared/time_budget.h"

namespace proxyvis {

struct InsideWrapOptions {
  // alpha_wrap_3 carved from interior seeds: the result is the interior offset surface.
  double alpha = 1.0 / 50;
  double offset = 1.0 / 600;
  // Seeds: local maxima of the distance to the surface on a grid of seed_grid cells along the
  // longest box side, deeper than 2·offset, at most max_seeds of them (deepest first). Several
  // seeds reach thin parts that alpha-sized passages do not connect.
  int seed_grid = 40;
  size_t max_seeds = 400;
  const TimeBudget* budget = nullptr;  // polled by the seed search and the wrap; null = no limit
};

struct ErodeOptions {
  double voxel = 1.0 / 150;            // voxel edge length
  double erosion = 1.0 / 150;          // erosion distance (rounded up to whole voxels, at least 1)
  const TimeBudget* budget = nullptr;  // polled between voxel passes; null = no limit
};

struct InsideStats {
  size_t seeds = 0;   // wrap: seeds used
  size_t voxels = 0;  // erode: voxels left after erosion
};

// Fills every hole of `input` (CGAL triangulate_refine_and_fair_hole; plain triangulation when
// fairing fails) after welding equal positions and dropping unreferenced vertices. Throws
// Error when the result is still not closed (e.g. non-manifold edges). `holes` (optional)
// receives the number of holes filled.
TriMesh fillHoles(const TriMesh& input, size_t* holes = nullptr);

// Inner alpha-wrap from interior seeds (CGAL alpha_wrap_3 with seed_points). `input` must bound
// a volume by ray parity (every welded edge has an even number of faces, non-manifold edges
// allowed; proxies/shared/parity_solid.h): otherwise throws Error naming the boundary and odd
// edges with advice that works for them. Throws Error when no interior point is deeper than the
// offset, when requireProxyGeometry (proxies/shared) refuses the input, when the wrap's estimate
// exceeds kMaxEstimatedWrapFaces (proxies/shared/wrap_size.h), or when options.budget is spent.
TriMesh makeInsideWrapProxy(const TriMesh& input, const InsideWrapOptions& options = {},
                            InsideStats* stats = nullptr);

// The voxel edge (fraction of the diagonal) for an erosion that will be reduced to `max_faces`:
// `voxel`, or coarser so that the voxel surface (about twice the input's area over the voxel
// face) has at most kErodeFacesPerBudgetFace x max_faces faces, then fine enough to divide
// `erosion` (which is rounded up to whole voxels); never coarser than 1/30.
inline constexpr double kErodeFacesPerBudgetFace = 100;
double erodeVoxelForBudget(const TriMesh& input, size_t max_faces, double voxel, double erosion);

// Solid voxelisation (ray parity along x), erosion by a cube of ceil(erosion/voxel) voxels,
// removal of voxels that would make the surface non-manifold, and the boundary of the voxel
// set as a closed, outward oriented triangle mesh (not simplified: use simplifyBounded with
// BoundSide::kInside). Throws Error when nothing is left after erosion, when
// requireProxyGeometry refuses the input, or when options.budget is spent.
TriMesh makeErodeProxy(const TriMesh& input, const ErodeOptions& options = {},
                       InsideStats* stats = nullptr);

}  // namespace proxyvis
