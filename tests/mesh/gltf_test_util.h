#pragma once
// What the glTF loader tests share: component types, a tetrahedron document and error capture.
#include <functional>
#include <string>
#include <vector>

#include "gltf_builder.h"
#include "mesh/io/mesh_io.h"
#include "util/error.h"

namespace proxyvis::test {

inline constexpr int kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kUInt = 5125,
                     kFloat = 5126;

// A unit right tetrahedron, outward-oriented (volume 1/6).
inline const std::vector<float> kTetraPositions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
inline const std::vector<uint32_t> kTetraIndices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

inline TriMesh parseGlb(const GltfBuilder& b) {
  return parseMeshBytes(b.glb(), "t.glb");
}

inline std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

// A tetrahedron document with indices of component type `index_type`.
inline GltfBuilder tetra(int index_type = kUInt) {
  GltfBuilder b;
  const int p = b.accessor(b.view(kTetraPositions), kFloat, 4, "VEC3");
  int i = -1;
  if (index_type == kUByte)
    i = b.accessor(b.view(std::vector<uint8_t>(kTetraIndices.begin(), kTetraIndices.end())), kUByte,
                   12, "SCALAR");
  else if (index_type == kUShort)
    i = b.accessor(b.view(std::vector<uint16_t>(kTetraIndices.begin(), kTetraIndices.end())),
                   kUShort, 12, "SCALAR");
  else
    i = b.accessor(b.view(kTetraIndices), kUInt, 12, "SCALAR");
  b.root(b.node({{"mesh", b.mesh(p, i)}}));
  return b;
}

}  // namespace proxyvis::test
