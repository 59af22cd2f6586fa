#pragma once
// A glTF file as a scene (lib/scene turns it into a SceneDesc): its meshes as prototypes, each
// node that draws one an instance, area lights from emissive primitives, the first perspective
// camera, and a list of what a renderer of direct lighting ignores.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "util/affine3.h"
#include "util/vec3.h"

namespace proxyvis {

struct GltfSceneContent {
  struct Mesh {
    std::string name;                // the glTF mesh's name (may be empty or repeated)
    int index = -1;                  // meshes[index] of the file
    Vec3f albedo{0.7f, 0.7f, 0.7f};  // baseColorFactor of its first surface primitive
  };
  struct Instance {
    uint32_t mesh = 0;  // into meshes
    Affine3f transform;
  };
  struct Light {
    std::vector<std::array<Vec3f, 3>> triangles;  // world space
    Vec3f radiance;
  };
  struct Camera {
    Vec3f eye, look_at, up;
    double yfov_deg = 40;
    double aspect = 0;          // width / height; 0 when the file leaves it open
    int width = 0, height = 0;  // the camera node's extras.proxyvis.resolution, 0: none
  };
  std::vector<Mesh> meshes;  // those with surface (non-emissive) triangles that a node places
  std::vector<Instance> instances;
  std::vector<Light> lights;
  std::optional<Camera> camera;
  std::vector<std::string> ignored;  // e.g. "3 textures", "1 animation"
};

// Reads `path` (.gltf or .glb; buffers from its folder only, as loadMesh) as a scene. Throws Error
// as loadMesh does for a corrupt file. Meshes are not decoded here except emissive primitives
// (the lights); loadMesh(path, {.mesh_index = m.index, .surfaces_only = true}) loads a prototype.
GltfSceneContent readGltfScene(const std::filesystem::path& path);

}  // namespace proxyvis
