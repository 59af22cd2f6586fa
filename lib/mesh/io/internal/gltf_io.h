#pragma once
// glTF 2.0 (.gltf JSON, .glb binary) through tinygltf: reading a whole file as one world-space
// triangle mesh, and writing meshes with their proof in `extras` (docs/gltf.md).
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesh/io/mesh_io.h"
#include "mesh/tri_mesh.h"

namespace tinygltf {
class Model;
}

namespace proxyvis::detail {

using proxyvis::GltfCompression;

// The parsed document. External buffers are read only from inside `folder` (never through `..`,
// absolute paths, symbolic links that leave it or URI schemes); an empty `folder` allows none
// (callers that hold only the bytes). Images are never read. Throws Error naming `file` and the
// JSON path or GLB chunk at fault.
tinygltf::Model parseGltfModel(const std::string& bytes, bool binary,
                               const std::filesystem::path& folder, const std::string& file);

// Every triangle of the default scene (or, with pick.node, of that node's subtree in world space;
// with pick.mesh, of that mesh in its own space) (or of every mesh, when the file has no nodes) in world
// space; strips and fans become triangle lists, a node with a mirroring transform has its
// triangles' winding turned back. Draco, meshopt and quantized primitives are decoded.
void gltfSceneToMesh(const tinygltf::Model& model, const GltfPick& pick, const std::string& file,
                     TriMesh& out);

// parseGltfModel + gltfSceneToMesh: the whole file as one mesh in `out`.
void decodeGltf(const std::string& bytes, bool binary, const std::filesystem::path& folder,
                const GltfPick& pick, const std::string& file, TriMesh& out);

// One mesh of a file to write, placed by its own node with `name` and `extras`.
struct GltfMeshOut {
  const TriMesh* mesh = nullptr;
  std::string name;
  nlohmann::json extras;  // null: none
  bool hidden = false;    // KHR_node_visibility: present in the file, not drawn
};

struct GltfEncoding {
  bool binary = true;  // GLB; else .gltf with the buffer as a data: URI
  GltfCompression compression = GltfCompression::kNone;
  int draco_bits = 0;  // Draco position quantization (0: lossless floats)
  int draco_speed = 5;
};

// Encodes the meshes, positions as floats with their min/max, indices as the smallest unsigned
// type that holds them; compressed with KHR_draco_mesh_compression or EXT_meshopt_compression
// (vertex and index codecs, no filters: exact) when asked.
std::string encodeGltf(const std::vector<GltfMeshOut>& meshes, const GltfEncoding& encoding,
                       const nlohmann::json& asset_extras, const std::string& file);

}  // namespace proxyvis::detail
