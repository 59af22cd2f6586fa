#pragma once
// A glTF document to write: meshes with materials, nodes (transforms, children, extras, hidden,
// LODs) and cameras. saveMesh writes one mesh this way; lib/scene writes whole scenes.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesh/io/mesh_io.h"
#include "mesh/tri_mesh.h"
#include "util/affine3.h"

namespace proxyvis {

struct GltfMaterialOut {
  Vec3f base_color{0.7f, 0.7f, 0.7f};
  Vec3f emissive{0, 0, 0};      // emissiveFactor (each component in [0, 1])
  float emissive_strength = 1;  // KHR_materials_emissive_strength when not 1
};

struct GltfMeshOut {
  const TriMesh* mesh = nullptr;
  std::string name;
  int material = -1;
  nlohmann::json extras;  // null: none
};

struct GltfNodeOut {
  std::string name;
  int mesh = -1, camera = -1;
  std::optional<Affine3f> transform;  // written as a matrix; none: identity
  nlohmann::json extras;              // null: none
  bool hidden = false;                // KHR_node_visibility: present, not drawn
  std::vector<int> children;
  std::vector<int> lod_nodes;  // MSFT_lod: coarser versions of this node, finest first
  bool root = true;            // in the scene's root list (children and LOD nodes are not)
};

struct GltfCameraOut {
  double yfov = 0.7;  // radians
  double aspect = 0;  // 0: left to the viewer
  double znear = 0.01;
};

struct GltfDocumentOut {
  std::vector<GltfMaterialOut> materials;
  std::vector<GltfMeshOut> meshes;
  std::vector<GltfNodeOut> nodes;
  std::vector<GltfCameraOut> cameras;
  nlohmann::json asset_extras;
};

// The document's bytes: a GLB (binary) or a .gltf with its buffer as a data: URI; positions as
// floats with their min/max, indices as the smallest unsigned type that holds them; compressed
// with KHR_draco_mesh_compression or EXT_meshopt_compression when asked. Throws WriteError naming
// `file` when an encoder refuses a mesh.
std::string encodeGltfDocument(const GltfDocumentOut& document, bool binary,
                               GltfCompression compression, int draco_bits, int draco_speed,
                               const std::string& file);

}  // namespace proxyvis
