#pragma once
// The JSON scene format (documented in README.md, "Scene format"). DRAFT CONTRACT: lib/scene
// owns this file and may extend it. Paths in the JSON are relative to the scene file; here they
// are resolved to absolute paths.
//
// {
//   "camera": {"eye": [x,y,z], "look_at": [x,y,z], "up": [0,1,0], "fov_deg": 40,
//              "resolution": [w, h]},
//   "lights": [{"type": "quad", "corner": [..], "edge_u": [..], "edge_v": [..],
//               "radiance": [r,g,b]},
//              {"type": "triangle", "vertices": [[..],[..],[..]], "radiance": [r,g,b]}],
//   "meshes": [{"name": "dragon", "file": "../data/dragon.drc", "albedo": [r,g,b],
//               "transform": {"translate": [..], "scale": s} | [16 numbers, row-major 4x4],
//               "place": true,     // false: only placed through "instances"
//               "proxies": [{"kind": "outside", "method": "wrap", "file": "dragon-plane/dragon.outside.ply",
//                            "class": "outside"}]}],   // class: verified by proxy-gen/proxy-check
//   "instances": {"file": "foliage.instances.txt"}  // lines: "NAME tx ty tz" or "NAME m00..m23"
// }
// Unknown keys are errors naming the key's JSON path (e.g. "meshes[2].albedoo").
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "trace/trace_scene.h"
#include "util/proxy_class.h"

namespace proxyvis {

struct CameraDesc {
  Vec3f eye{0, 0, 5}, look_at{0, 0, 0}, up{0, 1, 0};
  float fov_deg = 40;  // vertical field of view
  int width = 256, height = 256;
};

struct AreaLightDesc {
  std::vector<std::array<Vec3f, 3>> triangles;  // a quad is two triangles
  Vec3f radiance{1, 1, 1};
};

struct ProxyRef {
  std::string kind;                         // "outside", "inside", "general" (what was asked for)
  std::string method;                       // generator method, e.g. "wrap", "hull", "qem"
  std::filesystem::path file;               // absolute after loading
  std::optional<ProxyClass> verified_class; // absent = not verified: treated as general
};

struct SceneMeshDesc {
  std::string name;
  std::filesystem::path file;  // absolute after loading
  Vec3f albedo{0.7f, 0.7f, 0.7f};
  Affine3f transform;          // used when place == true
  bool place = true;
  std::vector<ProxyRef> proxies;
};

struct SceneInstanceDesc {
  uint32_t mesh = 0;  // index into SceneDesc::meshes
  Affine3f transform;
};

struct SceneDesc {
  std::filesystem::path path;  // the scene file (absolute)
  CameraDesc camera;
  std::vector<AreaLightDesc> lights;
  std::vector<SceneMeshDesc> meshes;
  std::filesystem::path instances_file;  // empty if none
  std::vector<SceneInstanceDesc> instances;
};

// Parses and validates a scene file; throws Error naming the file and the JSON path of the
// problem. Does not load the meshes.
SceneDesc loadSceneDesc(const std::filesystem::path& path);

// Writes a scene (paths made relative to the new file's directory), atomically.
void saveSceneDesc(const SceneDesc& scene, const std::filesystem::path& path);

// Content hash (hex) of the scene file and every file it references: the reference cache key.
std::string sceneHash(const SceneDesc& scene);

}  // namespace proxyvis
