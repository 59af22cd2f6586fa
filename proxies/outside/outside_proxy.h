#pragma once
// Outside proxies: closed meshes that contain the input (no HM' rays, docs/design.md). Sizes are
// fractions of the input's bounding-box diagonal. These functions only build; the caller
// (proxies/general/proxy_pipeline.h) verifies the guarantee exactly before anything is written.
#include <cstddef>

#include "mesh/tri_mesh.h"
#include "proxies/limits/time_budget.h"

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

// The most faces a wrap may be estimated to have (estimateWrapFaces): beyond it the wrap needs
// more memory and time than a proxy is worth. The estimate is about 6 times what is built: on
// the bunny, alpha 1/100 is estimated at 89 k faces and builds 13.9 k; alpha 1/250 at 555 k and
// builds 78 k (39 s, 130 MB for the whole run). The wrap itself stops after a quarter of this
// many Steiner points (about half as many faces), in case the estimate is ever too low.
inline constexpr double kMaxEstimatedWrapFaces = 4e6;

// An upper estimate of the faces of an alpha wrap (outer or inner) of `input` with alpha and
// offset as fractions of the diagonal: the surface the wrap can have (the input's area plus the
// box grown by the offset) covered by triangles of edge ~alpha. Cheap; used to refuse a wrap
// that would not finish before it starts.
double estimateWrapFaces(const TriMesh& input, double alpha, double offset);

// Throws Error naming the input when estimateWrapFaces exceeds kMaxEstimatedWrapFaces.
void requireWrapSize(const TriMesh& input, double alpha, double offset, const char* what);

// Convex hull (CGAL convex_hull_3) pushed outward by options.epsilon · diagonal. Works on any
// input, open or not. Throws Error when the input is flat (no 3-D hull), has no triangles or
// fails requireProxyGeometry (proxies/limits/input_geometry.h).
TriMesh makeHullProxy(const TriMesh& input, const HullOptions& options = {});

// Outer alpha-wrap (CGAL alpha_wrap_3) of the triangles taken as a soup: needs no closed or
// manifold input (leaf cards, polygon soups). The result is closed, 2-manifold and outward
// oriented. Throws Error on non-positive alpha/offset, an input requireProxyGeometry refuses, an
// estimate beyond kMaxEstimatedWrapFaces, or an exhausted options.budget.
TriMesh makeWrapProxy(const TriMesh& input, const WrapOptions& options = {});

}  // namespace proxyvis
