#pragma once
// OBJ, PLY and OFF files: OpenMesh's file readers and writers driven through its
// BaseImporter/BaseExporter interfaces, without building a half-edge mesh. Why: OpenMesh's own mesh
// kernels refuse faces that would make an edge or vertex non-manifold (the ecosys foliage has
// non-manifold edges, the teapot a pinched vertex), and ImporterT then drops such faces or
// duplicates their vertices. Reading into a polygon soup keeps every face and the file's vertex
// order; the parsing stays OpenMesh's.
#include <ostream>
#include <string>

#include "mesh/tri_mesh.h"

namespace proxyvis::detail {

// Parses `bytes` (the whole file) as format `ext` ("obj", "ply", "off") with OpenMesh and
// fan-triangulates every polygon into `out` (positions and triangles only). Throws Error naming
// `file` on parse failure or when a face references a vertex that does not exist.
void readWithOpenMesh(const std::string& bytes, const std::string& ext, const std::string& file,
                      TriMesh& out);

// Writes `mesh` as `ext` with OpenMesh to `out` (binary: PLY only; open `out` in binary mode).
// Returns false on failure.
bool writeWithOpenMesh(const TriMesh& mesh, const std::string& ext, std::ostream& out, bool binary);

}  // namespace proxyvis::detail
