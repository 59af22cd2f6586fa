#include "mesh/io/gltf_scene_content.h"

#include "mesh/io/mesh_io.h"

#include <fmt/format.h>
#include <cmath>

#include "mesh/io/internal/gltf_accessors.h"
#include "mesh/io/internal/gltf_io.h"
#include "mesh/io/internal/gltf_nodes.h"
#include "mesh/io/internal/gltf_primitives.h"
#include "mesh/io/internal/mesh_file.h"
#include "mesh/io/internal/tiny_gltf.h"
#include "util/error.h"
#include "util/lower_case.h"

namespace proxyvis {
namespace {

using detail::Mat4;

Affine3f toAffine(const Mat4& m) {
  Affine3f a;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 4; ++col) a.m[row][col] = float(m[size_t(col * 4 + row)]);
  return a;
}

Vec3f column(const Mat4& m, int c) {
  return Vec3f(float(m[size_t(c * 4)]), float(m[size_t(c * 4 + 1)]), float(m[size_t(c * 4 + 2)]));
}

std::optional<GltfSceneContent::Camera> firstPerspectiveCamera(
    const tinygltf::Model& model, const std::vector<detail::Placement>& cameras) {
  for (const detail::Placement& p : cameras) {
    const tinygltf::Camera& c = model.cameras[size_t(p.mesh)];  // placements() checks
    if (c.type != "perspective") continue;
    GltfSceneContent::Camera cam;
    cam.eye = column(p.world, 3);
    // A glTF camera looks down its -Z axis with +Y up.
    cam.look_at = cam.eye - normalize(column(p.world, 2));
    cam.up = normalize(column(p.world, 1));
    cam.yfov_deg = c.perspective.yfov * 180.0 / M_PI;
    cam.aspect = c.perspective.aspectRatio;
    // The image size proxyvis wrote (glTF has none): [width, height] in the node's extras.
    const tinygltf::Value& extras = model.nodes[size_t(p.node)].extras;
    if (extras.IsObject() && extras.Has("proxyvis") && extras.Get("proxyvis").IsObject()) {
      const tinygltf::Value& r = extras.Get("proxyvis").Get("resolution");
      if (r.IsArray() && r.ArrayLen() == 2 && r.Get(0).IsNumber() && r.Get(1).IsNumber()) {
        cam.width = r.Get(0).GetNumberAsInt();
        cam.height = r.Get(1).GetNumberAsInt();
      }
    }
    return cam;
  }
  return std::nullopt;
}

// An emissive primitive of a mesh, decoded in the mesh's space.
struct Emitter {
  TriMesh triangles;
  Vec3f radiance;
};

std::vector<Emitter> emittersOf(const tinygltf::Model& model, detail::GltfAccessors& data,
                                size_t mesh, const std::string& file) {
  std::vector<Emitter> out;
  const std::vector<tinygltf::Primitive>& prims = model.meshes[mesh].primitives;
  for (size_t k = 0; k < prims.size(); ++k)
    if (const std::optional<Vec3f> radiance = detail::emittedRadiance(model, prims[k])) {
      Emitter& e = out.emplace_back();
      e.radiance = *radiance;
      detail::appendPrimitive(model, data, mesh, k, file, e.triangles);
    }
  return out;
}

void noteIgnored(const tinygltf::Model& model, GltfSceneContent& out) {
  auto note = [&](size_t n, const char* one, const char* many) {
    if (n > 0) out.ignored.push_back(fmt::format("{} {}", n, n == 1 ? one : many));
  };
  note(model.textures.size(), "texture", "textures");
  note(model.animations.size(), "animation", "animations");
  note(model.skins.size(), "skin", "skins");
  note(model.lights.size(), "punctual light", "punctual lights");
  size_t morphs = 0;
  for (const tinygltf::Mesh& m : model.meshes)
    for (const tinygltf::Primitive& p : m.primitives) morphs += !p.targets.empty();
  note(morphs, "primitive with morph targets", "primitives with morph targets");
}

}  // namespace

GltfSceneContent readGltfScene(const std::filesystem::path& path) {
  const std::string file = path.string();
  const tinygltf::Model model = detail::parseGltfModel(
      detail::readMeshFile(path), lowerExtension(path) == ".glb", detail::folderOf(path), file);
  detail::GltfAccessors data(model, file);
  std::vector<detail::Placement> cameras;
  const std::vector<detail::Placement> placed = detail::placements(model, data, {}, file, &cameras);
  GltfSceneContent out;
  std::vector<int> prototype(model.meshes.size(), -2);  // -2: not looked at; -1: no surface
  std::vector<std::optional<std::vector<Emitter>>> emitters(model.meshes.size());
  for (const detail::Placement& p : placed) {
    const size_t m = size_t(p.mesh);
    const tinygltf::Mesh& mesh = model.meshes[m];  // in range: placements() checks
    if (prototype[m] == -2) {
      prototype[m] = -1;
      for (const tinygltf::Primitive& prim : mesh.primitives)
        if (!detail::isEmissive(model, prim)) {
          out.meshes.push_back(
              {mesh.name, int(m), detail::baseColor(model, prim, {0.7f, 0.7f, 0.7f})});
          prototype[m] = int(out.meshes.size() - 1);
          break;
        }
    }
    if (prototype[m] >= 0) out.instances.push_back({uint32_t(prototype[m]), toAffine(p.world)});
    if (!emitters[m]) emitters[m] = emittersOf(model, data, m, file);  // once per mesh
    for (const Emitter& e : *emitters[m]) {
      const TriMesh& local = e.triangles;
      GltfSceneContent::Light light;
      light.radiance = e.radiance;
      for (const Triangle& t : local.triangles)
        light.triangles.push_back({detail::transformPoint(p.world, local.vertices[t[0]]),
                                   detail::transformPoint(p.world, local.vertices[t[1]]),
                                   detail::transformPoint(p.world, local.vertices[t[2]])});
      if (!light.triangles.empty()) out.lights.push_back(std::move(light));
    }
  }
  out.camera = firstPerspectiveCamera(model, cameras);
  noteIgnored(model, out);
  return out;
}

}  // namespace proxyvis
