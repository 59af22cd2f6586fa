#pragma once
// The geometry a proxy generator can handle, checked before any CGAL / OpenMesh code sees the
// mesh. CGAL's alpha wrap, convex hull and hole filling and OpenMesh's decimater crash, abort or
// loop on inputs that load fine: all vertices on one line or at one point, coordinates so large
// that an offset or a squared distance overflows float or double (an infinity reaching GMP), or
// a mesh so far from the origin that float coordinates cannot resolve it. Such an input is an
// Error naming the file, what is wrong, why and what to do.
#include <cstddef>
#include <string>

#include "mesh/tri_mesh.h"

namespace proxyvis {

// The bounds (see docs/proxy_input_limits.md for the reasoning).
// |coordinate| at most this: squared extents stay far below the float maximum (3.4e38) even
// after the largest offset, and the exact predicates never see an infinity.
inline constexpr double kMaxProxyCoordinate = 1e12;
// The bounding-box diagonal at least this (absolute): smaller meshes underflow squared float
// distances.
inline constexpr double kMinProxyDiagonal = 1e-9;
// The diagonal at least this fraction of the largest |coordinate|: float keeps 24 bits, so this
// leaves about 8000 distinct coordinate steps across the mesh for the proxy's offset.
inline constexpr double kMinProxyRelativeExtent = 1e-3;

// What a generator needs besides a finite, resolvable extent.
enum class GeometryNeed {
  kSurface,  // some triangle of non-zero area (wrap, qem, cgal-sms, meshopt)
  kSolid,    // vertices not all in one plane (hull, inside wrap, erode)
};

// Measures of the vertices that triangles reference, in double.
struct GeometryMeasure {
  size_t triangles = 0;
  bool finite = true;
  double max_abs = 0;   // largest |coordinate|
  double diagonal = 0;  // bounding-box diagonal
  // Largest distance of a vertex from the line through two far-apart vertices (0: collinear),
  // and from the plane through those and the widest vertex (0: coplanar).
  double width = 0;
  double thickness = 0;
  size_t non_degenerate_triangles = 0;  // exactly: the three corners are not collinear
  // Below this, width or thickness count as none: float rounding at max_abs, or 1e-6 diagonal.
  double flat_tolerance() const;
};

GeometryMeasure measureGeometry(const TriMesh& mesh);

// Throws Error (exit code 2) naming mesh.source when `generator` (e.g. "the outside wrap") cannot
// handle the mesh: no triangles, a non-finite coordinate, |coordinate| > kMaxProxyCoordinate, a
// diagonal below kMinProxyDiagonal or below kMinProxyRelativeExtent of the largest coordinate,
// and for `need` no triangle of non-zero area (kSurface) or all vertices in one plane (kSolid).
void requireProxyGeometry(const TriMesh& mesh, GeometryNeed need, const std::string& generator);

}  // namespace proxyvis
