#pragma once
// glTF 2.0 (.gltf JSON, .glb binary) through tinygltf: reading a whole file as one world-space
// triangle mesh (writing: mesh/io/gltf_document.h).
#include <filesystem>
#include <string>
#include <vector>

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

// Every triangle of the default scene in world space (with pick.node, of that node's subtree;
// with pick.mesh or pick.mesh_index, of that mesh in its own space; every mesh once when the file
// has no nodes). Strips and fans become triangle lists, a node with a mirroring transform has its
// triangles' winding turned back, Draco, meshopt and quantized primitives are decoded, and nodes
// hidden by KHR_node_visibility are left out.
void gltfSceneToMesh(const tinygltf::Model& model, const GltfPick& pick, const std::string& file,
                     TriMesh& out);

// parseGltfModel + gltfSceneToMesh: the whole file as one mesh in `out`.
void decodeGltf(const std::string& bytes, bool binary, const std::filesystem::path& folder,
                const GltfPick& pick, const std::string& file, TriMesh& out);

}  // namespace proxyvis::detail
