#pragma once
// Draco .drc decoding and encoding through the Draco library.
#include <cstdint>
#include <string>

#include "mesh/tri_mesh.h"

namespace proxyvis::detail {

// Decodes a Draco triangle mesh: one vertex per decoded point (decoder order), POSITION only.
// Throws Error naming `file` for point clouds, corrupt data or a missing POSITION attribute.
void decodeDraco(const std::string& bytes, const std::string& file, TriMesh& out);

// The face count a Draco file's connectivity header declares, read for the bitstream Draco 1.5
// writes (2.2) and for 1.x, without metadata; -1 for anything else (2.0, 2.1, metadata first).
// decodeDraco refuses a declared count that the file's size cannot hold, and a mesh that
// decodes to another count.
int64_t declaredDracoFaceCount(const std::string& bytes);

// Encodes positions and triangles; quantization_bits 0 keeps float positions losslessly.
// Throws WriteError naming `file` if Draco refuses the mesh.
std::string encodeDraco(const TriMesh& mesh, int quantization_bits, int speed,
                        const std::string& file);

}  // namespace proxyvis::detail
