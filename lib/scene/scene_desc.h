#pragma once
// The JSON scene format (full reference with examples: scenes/FORMAT.md). Paths in the JSON are
// relative to the scene file; loadSceneDesc resolves them to absolute paths.
//
// {
//   "description": "optional free text",
//   "camera": {"eye": [x,y,z], "look_at": [x,y,z], "up": [0,1,0], "fov_deg": 40,
//              "resolution": [w, h]},
//   "lights": [{"type": "quad", "corner": [..], "edge_u": [..], "edge_v": [..],
//               "radiance": [r,g,b]},
//              {"type": "triangle", "vertices": [[..],[..],[..]], "radiance": [r,g,b]},
//              {"type": "triangles", "triangles": [[[..],[..],[..]], ...], "radiance": [..]}],
//   "meshes": [{"name": "dragon", "file": "../data/dragon.drc", "albedo": [r,g,b],
//               "transform": {"translate": [..], "rotate": [ax, ay, az, degrees],
//                             "scale": s | [sx, sy, sz]}
//                            | [12 or 16 numbers, row-major 3x4 / 4x4],
//               "place": true,     // false: only placed through "instances"
//               "make_proxy": true, // false: proxy-gen's scene mode skips this mesh
//               "proxy_max_faces": 96, // proxy-gen's face budget for this mesh (0 = none),
//                                      // instead of --max-faces / --ratio
//               "proxies": [{"kind": "outside", "method": "wrap",
//                            "file": "dragon-plane/dragon.outside.ply",
//                            "class": "outside",     // verified by proxy-gen/proxy-check
//                            "sha256": "..."}]}],    // of the file the class was verified for
//   "instances": {"file": "foliage.instances.txt"}
// }
// Instance list lines: "NAME tx ty tz" or "NAME" followed by 12 or 16 numbers (row-major 3x4 or
// 4x4, world = M * [x y z 1]); '#' starts a comment. Unknown keys are errors naming the key's
// JSON path (e.g. "meshes[2].albedoo").
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mesh/tri_mesh.h"
#include "util/affine3.h"
#include "util/proxy_class.h"
#include "util/vec3.h"

namespace proxyvis {

// The largest image width and height, in pixels, a scene or a command-line override may ask for.
inline constexpr int kMaxImageSide = 16384;
// The scene's "name": a title, one line of printable text.
inline constexpr size_t kMaxSceneNameLength = 200;

// Value ranges loadSceneDesc enforces. Within them the renderer's float arithmetic (squared
// distances, radiance * area / pdf, squared pixel errors summed over an image) stays finite;
// outside them a scene could render inf/NaN tables and still exit 0.
inline constexpr float kMaxSceneCoordinate = 1e6f;  // |x|, |y|, |z| of every position
inline constexpr float kMaxRadiance = 1e6f;         // each radiance component, in [0, this]
inline constexpr float kMinLightArea = 1e-12f;      // per light triangle (the pdf is 1/area)
inline constexpr float kMaxTransformScale = 1e6f;   // |entry| of a linear part and its inverse
inline constexpr float kMinUpLength = 1e-6f;        // camera up: length in [this, 1/this]
inline constexpr float kMinFovDeg = 0.01f, kMaxFovDeg = 179.0f;  // camera fov_deg

struct CameraDesc {
  Vec3f eye{0, 0, 5}, look_at{0, 0, 0}, up{0, 1, 0};
  float fov_deg = 40;  // vertical field of view, in [kMinFovDeg, kMaxFovDeg]
  int width = 256, height = 256;
};

// Emits radiance on both sides of every triangle (so the winding in the file does not matter).
struct AreaLightDesc {
  std::vector<std::array<Vec3f, 3>> triangles;  // a quad is two triangles
  Vec3f radiance{1, 1, 1};
  Bounds3f bounds() const {
    Bounds3f b;
    for (const auto& t : triangles)
      for (const Vec3f& v : t) b.extend(v);
    return b;
  }
};

struct ProxyRef {
  std::string kind;                          // "outside", "inside", "general" (what was asked for)
  std::string method;                        // generator method, e.g. "wrap", "hull", "qem"
  std::filesystem::path file;                // absolute after loading
  std::optional<ProxyClass> verified_class;  // absent = not verified: treated as general
  // SHA-256 (64 lowercase hex digits) of the proxy file whose verified_class was proven; empty =
  // none recorded. A class without a matching hash is re-verified before estimators rely on it
  // (proxies/check/class_trust.h).
  std::string sha256;
};

struct SceneMeshDesc {
  std::string name;            // unique, no whitespace (the instance list refers to it)
  std::filesystem::path file;  // absolute after loading
  // A .gltf/.glb file's meshes[gltf_mesh], its surface (non-emissive) primitives in the mesh's
  // own coordinates; -1: the whole file, as loadMesh reads it.
  int gltf_mesh = -1;
  Vec3f albedo{0.7f, 0.7f, 0.7f};
  Affine3f transform;  // used when place == true
  bool place = true;
  // false: proxy-gen's scene mode builds no proxy for this mesh (e.g. a terrain that only
  // receives shadows); proxies listed here are still used.
  bool make_proxy = true;
  // proxy-gen's face budget for this mesh's proxy (0: none), instead of the run's --max-faces or
  // --ratio: a scene's budget shared out over its meshes
  // (scripts/proxy_budgets/allocate_proxy_budgets.py).
  std::optional<uint32_t> proxy_max_faces;
  std::vector<ProxyRef> proxies;
};

struct SceneInstanceDesc {
  uint32_t mesh = 0;  // index into SceneDesc::meshes
  Affine3f transform;
};

struct SceneDesc {
  std::filesystem::path path;  // the scene file (absolute)
  std::string name;            // the "name" key (titles of reports); empty if the file has none
  std::string description;
  CameraDesc camera;
  std::vector<AreaLightDesc> lights;
  std::vector<SceneMeshDesc> meshes;
  std::filesystem::path instances_file;  // absolute; empty if none
  std::vector<SceneInstanceDesc> instances;

  // Index of the mesh called `name`, or -1.
  int findMesh(const std::string& name) const;
  // What to call the scene in titles: its name, else the scene file's stem.
  std::string displayName() const;
};

// A glTF file as a scene (docs/gltf.md): every mesh a node draws is a mesh of the scene placed only
// through instances (one per node, and per GPU instance), emissive primitives are area lights,
// the first perspective camera is the camera. Throws Error as loadSceneDesc does (no lights, ...).
// Prints one line on stderr naming what it ignores (textures, animations, ...).
SceneDesc sceneFromGltf(const std::filesystem::path& path);

// The triangles of a scene mesh (its file, or the glTF mesh it picks), in its own coordinates.
TriMesh loadSceneMesh(const SceneMeshDesc& mesh);
// The same from the file's bytes, read already (and checked against its sidecar).
TriMesh parseSceneMeshBytes(std::string bytes, const SceneMeshDesc& mesh);
// What identifies a scene mesh's content for caches: the file's SHA-256, and the glTF mesh it
// picks (every mesh of one glTF file has the same file hash).
std::string sceneMeshContentKey(const std::string& file_sha256, const SceneMeshDesc& mesh);

// Parses and validates a scene file (JSON; a .gltf/.glb goes to sceneFromGltf) and its instance
// list; throws Error naming the file and the
// JSON path (or list line) of the problem: unknown keys, wrong types, non-finite numbers, missing
// referenced files, duplicate mesh names, singular transforms, no lights. Does not load meshes.
SceneDesc loadSceneDesc(const std::filesystem::path& path);

// The parse-and-validate stage of loadSceneDesc on text already read: `path` is the scene file
// the text came from (relative paths resolve against its folder; errors name it). Referenced
// files must exist but are not read: instances_file is set and `instances` stays empty.
SceneDesc parseSceneDesc(const std::string& text, const std::filesystem::path& path);

// Parses an instance list for `meshes` (names looked up there). Throws Error naming
// "file:line" for an unknown name, a wrong count of numbers, a non-finite or singular transform,
// or a 4x4 whose last row is not 0 0 0 1.
std::vector<SceneInstanceDesc> loadInstanceList(const std::filesystem::path& path,
                                                const std::vector<SceneMeshDesc>& meshes);

// loadInstanceList on text already read; `path` names the list in errors.
std::vector<SceneInstanceDesc> parseInstanceList(const std::string& text,
                                                 const std::filesystem::path& path,
                                                 const std::vector<SceneMeshDesc>& meshes);

// Writes a scene (paths made relative to the new file's directory), atomically. Transforms are
// written as 16 numbers. Instances: the scene refers to scene.instances_file if set; otherwise,
// if there are instances, they are written to "<stem>.instances.txt" beside the scene (also
// atomically) and referenced from it.
void saveSceneDesc(const SceneDesc& scene, const std::filesystem::path& path);

// Content hash (16 hex digits, FNV-1a 64) of the scene's canonical JSON and the bytes of every
// file it references (meshes, proxies, instance list): the reference cache key. Throws Error if a
// referenced file cannot be read.
std::string sceneHash(const SceneDesc& scene);

}  // namespace proxyvis
