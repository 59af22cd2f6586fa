#pragma once
// A scene and its proxies as one glTF file: what engines load (docs/gltf.md, "Scenes").
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesh/io/mesh_io.h"
#include "mesh/tri_mesh.h"
#include "scene/scene_desc.h"

namespace proxyvis {

struct GltfSceneProxy {
  const TriMesh* mesh = nullptr;
  std::string cls;        // "outside", "inside" or "general" (the class written for it)
  nlohmann::json extras;  // the mesh's extras (the proof), null: none
};

// Every mesh of `scene` (originals[i] for scene.meshes[i]) with its albedo as the base colour,
// placed by one node for "place": true and one per instance; the area lights as emissive meshes;
// the camera (its resolution in the camera's extras). Each mesh's proxies[i] are meshes of their
// own, linked to every node of the original: an outside or inside proxy as a hidden child node
// (KHR_node_visibility) named after the original with "-occludee" / "-occonly", a general proxy as
// the node's MSFT_lod level. Throws WriteError naming `file` when an encoder refuses a mesh.
std::string encodeSceneGltf(const SceneDesc& scene, const std::vector<TriMesh>& originals,
                            const std::vector<std::vector<GltfSceneProxy>>& proxies, bool binary,
                            GltfCompression compression, const std::string& file);

}  // namespace proxyvis
