#pragma once
// Which surfaces bound a volume, and the volume they bound, read by ray parity: a point is inside
// when a ray from it crosses the surface an odd number of times. That is well defined exactly
// when every edge (after welding equal positions) has an even number of faces: a closed manifold
// (two faces per edge) or a watertight surface with non-manifold edges where four or six faces
// meet (two solids touching along an edge, a scan pinched at one edge). Such a surface needs no
// repair to have an inside; one with a boundary edge or an odd edge has none
// (docs/proxy_classes.md). lib/mesh's validateMesh counts the edges (MeshReport::watertight).
#include <cstdint>
#include <optional>
#include <string>

#include "mesh/tri_mesh.h"
#include "util/error.h"

namespace proxyvis {

// The volume inside `mesh` by ray parity (each face's contribution signed by the side the
// interior lies on), or nullopt when some welded edge has an odd number of faces. For a closed,
// outward oriented manifold it equals mesh.signedVolume().
std::optional<double> parityVolume(const TriMesh& mesh);

// The Error for a mesh that has no inside, when `what` (e.g. "an inside proxy") needs one: names
// the boundary edges (one face) and odd edges (3, 5, ... faces) and advises what works.
Error noInteriorError(const std::string& source, uint64_t boundary_edges, uint64_t odd_edges,
                      const std::string& what);

}  // namespace proxyvis
