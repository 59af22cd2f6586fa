// Writing scene files (the inverse of scene_load.cpp) and the content hash used as the
// reference-image cache key.
#include <fmt/core.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "scene/internal/json_text.h"
#include "scene/scene_desc.h"
#include "util/atomic_write.h"
#include "util/error.h"
#include "util/fnv1a.h"
#include "util/input_file.h"

namespace proxyvis {

namespace fs = std::filesystem;
// Ordered: keys are written in the order of scenes/FORMAT.md and the hand-written scenes.
using OrderedJson = nlohmann::ordered_json;  // keys in the order written

namespace {

OrderedJson toJson(const Vec3f& v) {
  return OrderedJson::array({v.x, v.y, v.z});
}

OrderedJson toJson(const Affine3f& a) {
  OrderedJson m = OrderedJson::array();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) m.push_back(a.m[i][j]);
  for (float v : {0.f, 0.f, 0.f, 1.f}) m.push_back(v);
  return m;
}

// Relative to `dir` when the file is below or beside it, so scenes stay relocatable.
std::string relativePath(const fs::path& file, const fs::path& dir) {
  if (dir.empty()) return file.generic_string();
  const fs::path rel = file.lexically_relative(dir);
  return rel.empty() ? file.generic_string() : rel.generic_string();
}

// Every light is written as a triangle list, which keeps the vertices bit-exact (a quad's
// corner and edges cannot be recovered exactly from its float triangles).
OrderedJson lightToJson(const AreaLightDesc& l) {
  OrderedJson tris = OrderedJson::array();
  for (const auto& t : l.triangles)
    tris.push_back(OrderedJson::array({toJson(t[0]), toJson(t[1]), toJson(t[2])}));
  return {{"type", "triangles"}, {"triangles", tris}, {"radiance", toJson(l.radiance)}};
}

std::string instanceLines(const SceneDesc& scene) {
  std::string out = "# NAME m00 m01 ... m23 (row-major 3x4, world = M * [x y z 1])\n";
  for (const SceneInstanceDesc& inst : scene.instances) {
    out += scene.meshes.at(inst.mesh).name;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) out += fmt::format(" {}", inst.transform.m[i][j]);
    out += '\n';
  }
  return out;
}

OrderedJson sceneToJson(const SceneDesc& scene, const fs::path& dir,
                        const fs::path& instances_file) {
  OrderedJson root;
  if (!scene.name.empty()) root["name"] = scene.name;
  if (!scene.description.empty()) root["description"] = scene.description;
  const CameraDesc& c = scene.camera;
  root["camera"] = {{"eye", toJson(c.eye)},
                    {"look_at", toJson(c.look_at)},
                    {"up", toJson(c.up)},
                    {"fov_deg", c.fov_deg},
                    {"resolution", {c.width, c.height}}};
  OrderedJson lights = OrderedJson::array();
  for (const AreaLightDesc& l : scene.lights) lights.push_back(lightToJson(l));
  root["lights"] = lights;
  OrderedJson meshes = OrderedJson::array();
  for (const SceneMeshDesc& m : scene.meshes) {
    OrderedJson jm = {{"name", m.name}, {"file", relativePath(m.file, dir)}};
    if (m.gltf_mesh >= 0) jm["gltf_mesh"] = m.gltf_mesh;
    jm.update(OrderedJson{
        {"albedo", toJson(m.albedo)}, {"transform", toJson(m.transform)}, {"place", m.place}});
    if (!m.make_proxy) jm["make_proxy"] = false;
    if (m.proxy_max_faces) jm["proxy_max_faces"] = *m.proxy_max_faces;
    OrderedJson proxies = OrderedJson::array();
    for (const ProxyRef& p : m.proxies) {
      OrderedJson jp = {{"kind", p.kind}};
      if (!p.method.empty()) jp["method"] = p.method;
      jp["file"] = relativePath(p.file, dir);
      if (p.verified_class) jp["class"] = proxyClassName(*p.verified_class);
      if (!p.sha256.empty()) jp["sha256"] = p.sha256;
      proxies.push_back(jp);
    }
    jm["proxies"] = proxies;
    meshes.push_back(jm);
  }
  root["meshes"] = meshes;
  if (!instances_file.empty()) root["instances"] = {{"file", relativePath(instances_file, dir)}};
  return root;
}

}  // namespace

void saveSceneDesc(const SceneDesc& scene, const fs::path& path) {
  std::error_code ec;
  const fs::path target = fs::absolute(path, ec).lexically_normal();
  const fs::path dir = target.parent_path();
  fs::path instances_file = scene.instances_file;
  if (instances_file.empty() && !scene.instances.empty()) {
    instances_file = dir / (target.stem().string() + ".instances.txt");
    writeTextAtomically(instances_file, instanceLines(scene));
  }
  // A derived scene (proxy-gen's DIR/scene.json) keeps the title of the scene it came from.
  OrderedJson root = sceneToJson(scene, dir, instances_file);
  if (scene.name.empty() && !scene.path.empty()) {
    OrderedJson named = {{"name", scene.displayName()}};
    named.update(root);
    root = std::move(named);
  }
  writeTextAtomically(target, detail::sceneJsonText(root) + "\n");
}

std::string sceneHash(const SceneDesc& scene) {
  Fnv1a fnv;
  // Paths relative to the scene's directory, so moving a whole scene folder keeps its hash.
  // Hashed with sorted keys and full doubles, as before the file kept its key order, so that
  // cached references stay valid.
  // The name is only a title: renaming a scene keeps its cached references.
  OrderedJson canonical = sceneToJson(scene, scene.path.parent_path(), scene.instances_file);
  canonical.erase("name");
  fnv.add(nlohmann::json::parse(canonical.dump()).dump());
  std::vector<fs::path> files;
  for (const SceneMeshDesc& m : scene.meshes) {
    files.push_back(m.file);
    for (const ProxyRef& p : m.proxies) files.push_back(p.file);
  }
  if (!scene.instances_file.empty()) {
    files.push_back(scene.instances_file);
  } else {
    fnv.add(instanceLines(scene));
  }
  for (const fs::path& f : files) {
    fnv.add(f.filename().string());
    fnv.add(readTextFile(f));
  }
  return fmt::format("{:016x}", fnv.h);
}

}  // namespace proxyvis
