#pragma once
// glTF 2.0 (.gltf JSON, .glb binary) through tinygltf: reading a whole file as one world-space
// triangle mesh, and writing meshes with their proof in `extras` (docs/gltf.md).
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesh/tri_mesh.h"

namespace tinygltf {
class Model;
}

namespace proxyvis::detail {

// The parsed document. External buffers are read only from inside `folder` (never through `..`,
// absolute paths, symbolic links that leave it or URI schemes); an empty `folder` allows none
// (callers that hold only the bytes). Images are never read. Throws Error naming `file` and the
// JSON path or GLB chunk at fault.
tinygltf::Model parseGltfModel(const std::string& bytes, bool binary,
                               const std::filesystem::path& folder, const std::string& file);

// Every triangle of the default scene (or of every mesh, when the file has no nodes) in world
// space; strips and fans become triangle lists, a node with a mirroring transform has its
// triangles' winding turned back. Draco, meshopt and quantized primitives are decoded.
void gltfSceneToMesh(const tinygltf::Model& model, const std::string& file, TriMesh& out);

// parseGltfModel + gltfSceneToMesh: the whole file as one mesh in `out`.
void decodeGltf(const std::string& bytes, bool binary, const std::filesystem::path& folder,
                const std::string& file, TriMesh& out);

// One mesh of a file to write, placed by its own node with `name` and `extras`.
struct GltfMeshOut {
  const TriMesh* mesh = nullptr;
  std::string name;
  nlohmann::json extras;  // null: none
  bool hidden = false;    // KHR_node_visibility: present in the file, not drawn
};

// Encodes the meshes as a GLB (binary) or a .gltf with its buffer as a data: URI, positions as
// floats with their min/max, indices as the smallest unsigned type that holds them.
std::string encodeGltf(const std::vector<GltfMeshOut>& meshes, bool binary,
                       const nlohmann::json& asset_extras, const std::string& file);

}  // namespace proxyvis::detail
