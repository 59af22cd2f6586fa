#pragma once
// The last rungs of the face-budget ladder (docs/budgets.md): closed shapes of 12 or 4 faces
// that contain a mesh, or that a closed mesh contains. They are built to hold their side by
// construction, with a margin; the pipeline still verifies each one exactly before use.
#include <optional>

#include "mesh/tri_mesh.h"

namespace proxyvis {

// The fewest faces a closed triangle mesh can have (a tetrahedron).
inline constexpr size_t kMinClosedFaces = 4;
// Faces of a box.
inline constexpr size_t kBoxFaces = 12;

// An oriented bounding box of `input` (CGAL's optimal bounding box), pushed outward by
// `margin` (a fraction of the diagonal): 8 vertices, 12 faces, outward oriented.
TriMesh enclosingBox(const TriMesh& input, double margin = 1e-5);

// The smallest of a few tetrahedra (4 faces) whose face planes are pushed out to touch the
// input's vertices plus `margin` (a fraction of the diagonal), oriented along the input's
// bounding box; outward oriented.
TriMesh enclosingTetrahedron(const TriMesh& input, double margin = 1e-5);

// A point of the interior of the closed mesh `input` and its distance to the surface, found on
// a grid and refined locally; nullopt when no grid point is inside (an open or flat mesh).
struct InteriorBall {
  Vec3d center;
  double radius = 0;
};
std::optional<InteriorBall> deepestInteriorPoint(const TriMesh& input);

// A cube (12 faces) and a regular tetrahedron (4 faces) inscribed in the ball, shrunk by 2 %:
// inside the mesh by construction.
TriMesh inscribedBox(const InteriorBall& ball, const std::string& source);
TriMesh inscribedTetrahedron(const InteriorBall& ball, const std::string& source);

}  // namespace proxyvis
