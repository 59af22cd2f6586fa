#pragma once
// The mesh loader targets (fuzz_ply, fuzz_obj, fuzz_off, fuzz_draco): the fuzzer's bytes are
// parsed in memory as the contents of a file with the given extension, exactly as loadMesh
// parses a file once it has read it.
#include "fuzz_support.h"
#include "mesh/io/mesh_io.h"

namespace proxyvis::fuzz {

// A loaded mesh must keep loadMesh's promises: finite positions, indices in range, a triangle.
inline void checkLoadedMesh(const TriMesh& mesh) {
  if (mesh.triangles.empty()) finding("loaded a mesh without triangles");
  for (const Vec3f& v : mesh.vertices)
    if (!isFinite(v)) finding("loaded a mesh with a non-finite vertex");
  for (const Triangle& t : mesh.triangles)
    for (uint32_t i : t)
      if (i >= mesh.vertices.size()) finding("loaded a mesh with an index out of range");
}

inline int fuzzMeshBytes(const uint8_t* data, size_t size, const char* file_name) {
  parsedOrRefused([&] { checkLoadedMesh(parseMeshBytes(bytesOf(data, size), file_name)); });
  return 0;
}

}  // namespace proxyvis::fuzz
