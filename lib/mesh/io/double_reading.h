#pragma once
// A second reading of a mesh file, in double: what a CAD tool or any program that parses the
// file's decimals as double sees. proxyvis itself reads every vertex as float (TriMesh); a
// proxy's class is proved in both readings (docs/clearance.md).
#include <filesystem>
#include <vector>

#include "mesh/tri_mesh.h"
#include "util/vec3.h"

namespace proxyvis {

// The positions of `mesh`'s vertices (as loadMesh read them from `file`) read in double: for the
// text formats (OFF, OBJ, ASCII PLY) each decimal parsed as the nearest double, by CGAL's readers
// (another parser than the one loadMesh uses); for formats that store binary floats (binary
// PLY, Draco, glTF) the stored values, which are the float vertices themselves. Matched vertex
// by vertex: each double must round to the float loadMesh read. Throws Error naming the file when
// the two readings cannot be matched.
std::vector<Vec3d> readDoublePositions(const std::filesystem::path& file, const TriMesh& mesh);

// Whether `file`'s format stores decimals (so the two readings can differ).
bool storesDecimals(const std::filesystem::path& file);

// Whether `positions` (another reading of `mesh`'s file) are exactly its float vertices, as for a
// binary format or decimals that floats represent: a check on them then repeats the same check
// on the float vertices, and its answer can be reused.
bool readsAsFloat(const TriMesh& mesh, const std::vector<Vec3d>& positions);

}  // namespace proxyvis
