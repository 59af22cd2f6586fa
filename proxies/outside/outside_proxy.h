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
