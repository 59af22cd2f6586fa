#include "scene/gltf_scene_export.h"

#include <algorithm>
#include <cmath>
#include <deque>

#include "mesh/io/gltf_document.h"
#include "util/error.h"

namespace proxyvis {
namespace {

using json = nlohmann::json;

// The camera's node transform: columns right, up, backward (a glTF camera looks down -Z), eye.
Affine3f cameraTransform(const CameraDesc& c) {
  const Vec3f back = normalize(c.eye - c.look_at);
  const Vec3f right = normalize(cross(c.up, back));
  const Vec3f up = cross(back, right);
  Affine3f t;
  for (int row = 0; row < 3; ++row) {
    t.m[row][0] = right[row];
    t.m[row][1] = up[row];
    t.m[row][2] = back[row];
    t.m[row][3] = c.eye[row];
  }
  return t;
}

const char* proxySuffix(const std::string& cls) {
  return cls == "inside" ? "-occonly" : cls == "outside" ? "-occludee" : "-lod";
}

class SceneDocument {
 public:
  SceneDocument(const SceneDesc& scene, const std::vector<TriMesh>& originals,
                const std::vector<std::vector<GltfSceneProxy>>& proxies)
      : scene_(scene), originals_(originals), proxies_(proxies) {}

  GltfDocumentOut build() {
    for (size_t m = 0; m < scene_.meshes.size(); ++m) addMesh(m);
    for (size_t m = 0; m < scene_.meshes.size(); ++m)
      if (scene_.meshes[m].place) placeMesh(m, scene_.meshes[m].transform, scene_.meshes[m].name);
    for (size_t i = 0; i < scene_.instances.size(); ++i) {
      const SceneInstanceDesc& inst = scene_.instances[i];
      placeMesh(inst.mesh, inst.transform, scene_.meshes[inst.mesh].name + "." + std::to_string(i));
    }
    for (size_t l = 0; l < scene_.lights.size(); ++l) addLight(l);
    addCamera();
    return std::move(doc_);
  }

 private:
  void addMesh(size_t m) {
    doc_.materials.push_back({scene_.meshes[m].albedo, {0, 0, 0}, 1});
    const int material = int(doc_.materials.size() - 1);
    first_mesh_.push_back(int(doc_.meshes.size()));
    doc_.meshes.push_back({&originals_[m], scene_.meshes[m].name, material, nullptr});
    for (const GltfSceneProxy& p : proxies_[m])
      doc_.meshes.push_back(
          {p.mesh, scene_.meshes[m].name + proxySuffix(p.cls), material, p.extras});
  }

  // One node of the original; its outside/inside proxies hidden below it, its general proxies
  // as its LOD levels (nodes of their own, outside the scene's root list).
  void placeMesh(size_t m, const Affine3f& transform, const std::string& name) {
    GltfNodeOut node;
    node.name = name;
    node.mesh = first_mesh_[m];
    node.transform = transform;
    std::vector<GltfNodeOut> extra;
    for (size_t k = 0; k < proxies_[m].size(); ++k) {
      const GltfSceneProxy& p = proxies_[m][k];
      GltfNodeOut proxy;
      proxy.name = name + proxySuffix(p.cls);
      proxy.mesh = first_mesh_[m] + 1 + int(k);
      proxy.extras = {{"proxyvis", {{"class", p.cls}, {"proxy_of", scene_.meshes[m].name}}}};
      proxy.root = false;
      if (p.cls == "general") {
        proxy.transform = transform;  // an LOD node stands in for the whole node
        node.lod_nodes.push_back(int(doc_.nodes.size() + 1 + extra.size()));
      } else {
        proxy.hidden = true;
        node.children.push_back(int(doc_.nodes.size() + 1 + extra.size()));
      }
      extra.push_back(std::move(proxy));
    }
    doc_.nodes.push_back(std::move(node));
    for (GltfNodeOut& e : extra) doc_.nodes.push_back(std::move(e));
  }

  void addLight(size_t l) {
    const AreaLightDesc& light = scene_.lights[l];
    TriMesh& mesh = light_meshes_.emplace_back();
    for (const auto& t : light.triangles) {
      const uint32_t base = uint32_t(mesh.vertices.size());
      for (const Vec3f& v : t) mesh.vertices.push_back(v);
      mesh.triangles.push_back({base, base + 1, base + 2});
    }
    const float peak = std::max({light.radiance.x, light.radiance.y, light.radiance.z, 1e-30f});
    doc_.materials.push_back({{0, 0, 0}, light.radiance / peak, peak});
    doc_.meshes.push_back(
        {&mesh, "light" + std::to_string(l), int(doc_.materials.size() - 1), nullptr});
    GltfNodeOut node;
    node.name = "light" + std::to_string(l);
    node.mesh = int(doc_.meshes.size() - 1);
    doc_.nodes.push_back(std::move(node));
  }

  void addCamera() {
    const CameraDesc& c = scene_.camera;
    doc_.cameras.push_back({double(c.fov_deg) * M_PI / 180.0, double(c.width) / c.height, 0.01});
    GltfNodeOut node;
    node.name = "camera";
    node.camera = 0;
    node.transform = cameraTransform(c);
    node.extras = {{"proxyvis", {{"resolution", {c.width, c.height}}}}};
    doc_.nodes.push_back(std::move(node));
  }

  const SceneDesc& scene_;
  const std::vector<TriMesh>& originals_;
  const std::vector<std::vector<GltfSceneProxy>>& proxies_;
  GltfDocumentOut doc_;
  std::vector<int> first_mesh_;       // document mesh of each scene mesh (its proxies follow)
  std::deque<TriMesh> light_meshes_;  // stable addresses for the document's pointers
};

}  // namespace

std::string encodeSceneGltf(const SceneDesc& scene, const std::vector<TriMesh>& originals,
                            const std::vector<std::vector<GltfSceneProxy>>& proxies, bool binary,
                            GltfCompression compression, const std::string& file) {
  PV_CHECK(originals.size() == scene.meshes.size() && proxies.size() == scene.meshes.size());
  SceneDocument builder(scene, originals, proxies);
  GltfDocumentOut doc = builder.build();
  doc.asset_extras = {{"proxyvis", {{"scene", scene.displayName()}}}};
  return encodeGltfDocument(doc, binary, compression, 0, 5, file);
}

}  // namespace proxyvis
