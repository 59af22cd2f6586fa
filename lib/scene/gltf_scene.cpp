// A glTF file as a scene: its content (mesh/io/gltf_scene_content.h) turned into a SceneDesc
// with the limits the JSON format has.
#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <set>

#include "mesh/io/gltf_scene_content.h"
#include "mesh/io/mesh_io.h"
#include "scene/internal/value_ranges.h"
#include "scene/scene_desc.h"
#include "util/error.h"

namespace proxyvis {
namespace fs = std::filesystem;

namespace {

constexpr int kDefaultImageWidth = 512;

// A mesh name the instance list and reports can use: no whitespace or '#', unique, never empty.
std::string sceneMeshName(const GltfSceneContent::Mesh& m, std::set<std::string>& taken) {
  std::string name = m.name.empty() ? fmt::format("mesh{}", m.index) : m.name;
  for (char& c : name)
    if (static_cast<unsigned char>(c) <= ' ' || c == '#' || static_cast<unsigned char>(c) >= 127)
      c = '_';
  if (taken.count(name)) name += fmt::format("_{}", m.index);
  taken.insert(name);
  return name;
}

void fail(const fs::path& path, const std::string& where, const detail::RangeProblem& p) {
  throw Error(path.string(), where + ": " + p.what, p.why, p.todo);
}

CameraDesc cameraOf(const GltfSceneContent& content, const fs::path& path) {
  CameraDesc camera;
  if (!content.camera) return camera;  // the JSON format's default view
  const GltfSceneContent::Camera& c = *content.camera;
  camera.eye = c.eye;
  camera.look_at = c.look_at;
  camera.up = c.up;
  camera.fov_deg = float(c.yfov_deg);
  if (!(camera.fov_deg >= kMinFovDeg && camera.fov_deg <= kMaxFovDeg))
    throw Error(path.string(), fmt::format("camera yfov of {:g} degrees", c.yfov_deg),
                fmt::format("it must be in [{:g}, {:g}]", kMinFovDeg, kMaxFovDeg),
                "fix the camera in the file");
  for (const Vec3f& p : {camera.eye, camera.look_at})
    if (auto problem = detail::positionProblem(p, "camera position"))
      fail(path, "camera", *problem);
  camera.width = kDefaultImageWidth;
  camera.height = c.aspect > 0 ? std::max(1, int(std::lround(kDefaultImageWidth / c.aspect)))
                               : kDefaultImageWidth;
  if (c.width > 0 && c.height > 0) {
    camera.width = c.width;
    camera.height = c.height;
  }
  camera.width = std::min(camera.width, kMaxImageSide);
  camera.height = std::min(camera.height, kMaxImageSide);
  return camera;
}

void addLights(const GltfSceneContent& content, const fs::path& path, SceneDesc& scene) {
  for (size_t i = 0; i < content.lights.size(); ++i) {
    const GltfSceneContent::Light& l = content.lights[i];
    const std::string where = fmt::format("emissive primitive {}", i);
    for (int c = 0; c < 3; ++c)
      if (!(l.radiance[c] >= 0 && l.radiance[c] <= kMaxRadiance))
        throw Error(path.string(), fmt::format("{}: radiance {:g}", where, l.radiance[c]),
                    fmt::format("each component must be in [0, {:g}]", kMaxRadiance),
                    "lower emissiveFactor or the emissive strength");
    AreaLightDesc light;
    light.radiance = l.radiance;
    for (const auto& t : l.triangles) {
      for (const Vec3f& p : t)
        if (auto problem = detail::positionProblem(p, "light vertex")) fail(path, where, *problem);
      const float area = 0.5f * length(cross(t[1] - t[0], t[2] - t[0]));
      if (area >= kMinLightArea) light.triangles.push_back(t);  // slivers emit nothing usable
    }
    if (!light.triangles.empty()) scene.lights.push_back(std::move(light));
  }
  if (scene.lights.empty())
    throw Error(path.string(), "no lights",
                "direct illumination needs emissive triangles (a material with emissiveFactor)",
                "give a light's mesh an emissive material, or describe the scene in JSON");
}

}  // namespace

SceneDesc sceneFromGltf(const fs::path& path) {
  const GltfSceneContent content = readGltfScene(path);
  SceneDesc scene;
  std::error_code ec;
  scene.path = fs::absolute(path, ec).lexically_normal();
  scene.camera = cameraOf(content, scene.path);
  addLights(content, scene.path, scene);
  std::set<std::string> taken;
  for (const GltfSceneContent::Mesh& m : content.meshes) {
    SceneMeshDesc mesh;
    mesh.name = sceneMeshName(m, taken);
    mesh.file = scene.path;
    mesh.gltf_mesh = m.index;
    mesh.albedo = m.albedo;
    mesh.place = false;  // every placement is an instance, as in an instanced JSON scene
    scene.meshes.push_back(std::move(mesh));
  }
  for (size_t i = 0; i < content.instances.size(); ++i) {
    const GltfSceneContent::Instance& inst = content.instances[i];
    if (auto problem = detail::transformProblem(inst.transform))
      fail(scene.path, fmt::format("instance {} of mesh '{}'", i, scene.meshes[inst.mesh].name),
           *problem);
    scene.instances.push_back({inst.mesh, inst.transform});
  }
  std::string ignored;
  for (const std::string& item : content.ignored) ignored += (ignored.empty() ? "" : ", ") + item;
  if (!content.camera)
    ignored += std::string(ignored.empty() ? "" : "; ") + "no perspective camera: the default view";
  if (!ignored.empty())
    std::fprintf(stderr, "note: %s: ignored: %s\n", scene.path.filename().string().c_str(),
                 ignored.c_str());
  return scene;
}

namespace {

GltfPick scenePick(const SceneMeshDesc& mesh) {
  GltfPick pick;
  if (mesh.gltf_mesh >= 0) {
    pick.mesh_index = mesh.gltf_mesh;
    pick.surfaces_only = true;
  }
  return pick;
}

}  // namespace

TriMesh loadSceneMesh(const SceneMeshDesc& mesh) {
  return loadMesh(mesh.file, scenePick(mesh));
}

TriMesh parseSceneMeshBytes(std::string bytes, const SceneMeshDesc& mesh) {
  return parseMeshBytesIn(std::move(bytes), mesh.file, mesh.file.parent_path(), scenePick(mesh));
}

std::string sceneMeshContentKey(const std::string& file_sha256, const SceneMeshDesc& mesh) {
  return mesh.gltf_mesh < 0 ? file_sha256
                            : fmt::format("{}:gltf_mesh={}", file_sha256, mesh.gltf_mesh);
}

}  // namespace proxyvis
