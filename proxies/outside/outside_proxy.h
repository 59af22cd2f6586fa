#pragma once
// Outside proxies: closed meshes that contain the input (no HM' rays, docs/design.md). Sizes are
// fractions of the input's bounding-box diagonal. These functions only build; the caller
// (proxies/pipeline/proxy_pipeline.h) verifies the guarantee exactly before anything is written.
#include <cstddef>

#include "mesh/tri_mesh.h"
#include "proxies/shared/time_budget.h"

namespace proxyvis {

struct HullOptions {
  // CGAL's hull faces lie ON input faces, and touching surfaces count as intersecting in the
  // exact containment test. The hull is therefore scaled about its vertex centroid so that
  // every face plane moves outward by at least this fraction of the diagonal.
  double epsilon = 1e-5;
};

struct WrapOptions {
  // alpha_wrap_3 parameters as fractions of the diagonal. alpha = 1/50: on the 100 k-face
  // dragon ~5.8 k faces with volume ratio ~1.13 in ~1.7 s; offset = 1/600 keeps the
  // wrap close while leaving room for the budgeted simplification.
  double alpha = 1.0 / 50;
  double offset = 1.0 / 600;
  const TimeBudget* budget = nullptr;  // polled while wrapping; null = no limit
};

// Union of convex pieces (proxies/outside/convex_parts.cpp): space cut by planes into up to
// max_parts convex cells, each cut chosen to remove the most hull volume; each cell's part of the
// input wrapped in its convex hull grown by epsilon · diagonal / parts; the pieces united exactly.
inline constexpr size_t kMaxConvexParts = 256;
struct ConvexPartsOptions {
  size_t max_parts = 16;
  // Stop cutting when the best cut removes less than this fraction of the whole hull's volume.
  double min_gain = 0.004;
  // Growth of the pieces, a fraction of the diagonal shared among the parts: strictly outside
  // the input, and far above the rounding of the double clipping and of the float output.
  double epsilon = 1e-3;
  // The face budget the union will be reduced to (0 = none): each piece is first reduced to a
  // share of it (3 × budget / parts, at least 16), which keeps the exact union small.
  size_t face_budget = 0;
  const TimeBudget* budget = nullptr;
};
struct ConvexPartsStats {
  size_t parts = 0;
  size_t piece_faces = 0;  // the pieces' faces before the union
};
// Throws Error on max_parts outside [1, kMaxConvexParts], an input requireProxyGeometry refuses
// as a solid (all vertices in one plane), a union that is not manifold, or a spent budget.
TriMesh makeConvexPartsProxy(const TriMesh& input, const ConvexPartsOptions& options = {},
                             ConvexPartsStats* stats = nullptr);

// Convex hull (CGAL convex_hull_3) pushed outward by options.epsilon · diagonal. Works on any
// input, open or not. Throws Error when the input is flat (no 3-D hull), has no triangles or
// fails requireProxyGeometry (proxies/shared/input_geometry.h).
TriMesh makeHullProxy(const TriMesh& input, const HullOptions& options = {});

// Outer alpha-wrap (CGAL alpha_wrap_3) of the triangles taken as a soup: needs no closed or
// manifold input (leaf cards, polygon soups). The result is closed, 2-manifold and outward
// oriented. Throws Error on non-positive alpha/offset, an input requireProxyGeometry refuses, an
// estimate beyond kMaxEstimatedWrapFaces (proxies/shared/wrap_size.h), or an exhausted
// options.budget.
TriMesh makeWrapProxy(const TriMesh& input, const WrapOptions& options = {});

}  // namespace proxyvis
