#pragma once
// A lighter copy of a mesh for display only (the 3D view of docs/report_3d.md): vertex clustering
// on a uniform grid. Never used for a check: the checks run on the mesh itself.
#include <cstddef>
#include <cstdint>

#include "mesh/tri_mesh.h"

namespace proxyvis {

struct ViewMesh {
  TriMesh mesh;
  uint32_t grid = 0;  // cells along the longest side of the box; 0: not decimated (a copy)
};

// `mesh` itself when it has at most max_triangles triangles (max_triangles >= 1). Otherwise the
// vertices that fall into one cell of a grid over its box are merged into their mean, triangles
// that collapse are dropped and triangles on the same three cells are kept once; the grid is the
// finest of those tried that gives at most max_triangles triangles.
ViewMesh decimateForView(const TriMesh& mesh, size_t max_triangles);

// One clustering step, exposed for tests: `mesh` clustered on a grid of `grid` cells along the
// longest side of its box (1 <= grid <= 2^20).
TriMesh clusterVertices(const TriMesh& mesh, uint32_t grid);

}  // namespace proxyvis
