// A glTF file as one triangle mesh: primitives decoded (plain, Draco, meshopt, quantized), nodes
// walked from the default scene with their transforms applied.
#include "mesh/io/internal/tiny_gltf.h"

#include <fmt/format.h>
#include <array>
#include <cmath>

#include "mesh/io/internal/draco_io.h"
#include "mesh/io/internal/gltf_accessors.h"
#include "mesh/io/internal/gltf_io.h"
#include "mesh/io/internal/gltf_nodes.h"
#include "mesh/io/internal/gltf_primitives.h"
#include "util/error.h"

namespace proxyvis::detail {
namespace {

// More triangles than this after instancing is refused (about 1.6 GB of mesh): a small file whose
// nodes repeat a large mesh many times would otherwise exhaust memory.
constexpr size_t kMaxExpandedTriangles = size_t(1) << 26;

const char* modeName(int mode) {
  static const char* names[] = {"points", "lines", "a line loop", "a line strip"};
  return mode >= 0 && mode < 4 ? names[mode] : "an unknown mode";
}

}  // namespace

void appendPrimitive(const tinygltf::Model& model, GltfAccessors& data, size_t mesh_index,
                     size_t prim_index, const std::string& file, TriMesh& local) {
  const tinygltf::Mesh& mesh = model.meshes[mesh_index];
  const tinygltf::Primitive& prim = mesh.primitives[prim_index];
  const std::string where = fmt::format("meshes[{}].primitives[{}]", mesh_index, prim_index);
  const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
  if (mode < TINYGLTF_MODE_TRIANGLES || mode > TINYGLTF_MODE_TRIANGLE_FAN)
    throw Error(
        file,
        fmt::format("{} (mesh '{}') draws {}", where, printableText(mesh.name), modeName(mode)),
        "only triangles, strips and fans make a surface",
        "export the mesh's faces, not its points or edges");
  const uint32_t base = uint32_t(local.vertices.size());
  if (auto draco = prim.extensions.find("KHR_draco_mesh_compression");
      draco != prim.extensions.end()) {
    const tinygltf::Value& view = draco->second.Get("bufferView");
    const std::string_view bytes = data.viewBytes(view.IsNumber() ? view.GetNumberAsInt() : -1,
                                                  where + ".extensions.KHR_draco_mesh_compression");
    TriMesh decoded;
    decodeDraco(std::string(bytes), file + " (" + where + ")", decoded);
    for (const Vec3f& v : decoded.vertices) local.vertices.push_back(v);
    for (const Triangle& t : decoded.triangles)
      local.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    return;
  }
  const auto position = prim.attributes.find("POSITION");
  if (position == prim.attributes.end())
    throw Error(file, where + " has no POSITION attribute", "a surface needs vertex positions",
                "the file is corrupt; re-export it");
  const std::vector<double> p =
      data.readValues(position->second, 3, where + ".attributes.POSITION");
  const size_t n = p.size() / 3;
  for (size_t i = 0; i < n; ++i)
    local.vertices.push_back(Vec3f(float(p[3 * i]), float(p[3 * i + 1]), float(p[3 * i + 2])));
  std::vector<uint32_t> idx;
  if (prim.indices >= 0) {
    idx = data.readIndices(prim.indices, where + ".indices");
  } else {
    idx.resize(n);
    for (size_t i = 0; i < n; ++i) idx[i] = uint32_t(i);
  }
  for (size_t k = 0; k < idx.size(); ++k)
    if (idx[k] >= n)
      throw Error(file, fmt::format("{}.indices[{}] is {}", where, k, idx[k]),
                  fmt::format("the primitive has {} vertices", n),
                  "the file is corrupt; re-export it");
  auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
    if (a != b && b != c && a != c) local.triangles.push_back({a + base, b + base, c + base});
  };
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    for (size_t k = 0; k + 2 < idx.size(); k += 3)
      local.triangles.push_back({idx[k] + base, idx[k + 1] + base, idx[k + 2] + base});
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    // Every other triangle of a strip is flipped back to the strip's winding; the repeated
    // indices strips use to restart make no triangle.
    for (size_t k = 0; k + 2 < idx.size(); ++k)
      k % 2 == 0 ? add(idx[k], idx[k + 1], idx[k + 2]) : add(idx[k + 1], idx[k], idx[k + 2]);
  } else {
    for (size_t k = 1; k + 1 < idx.size(); ++k) add(idx[0], idx[k], idx[k + 1]);
  }
}

std::optional<Vec3f> emittedRadiance(const tinygltf::Model& model,
                                     const tinygltf::Primitive& prim) {
  if (prim.material < 0 || size_t(prim.material) >= model.materials.size()) return std::nullopt;
  const tinygltf::Material& m = model.materials[size_t(prim.material)];
  double strength = 1;
  if (auto ext = m.extensions.find("KHR_materials_emissive_strength"); ext != m.extensions.end()) {
    const tinygltf::Value& v = ext->second.Get("emissiveStrength");
    if (v.IsNumber()) strength = v.GetNumberAsDouble();
  }
  if (m.emissiveFactor.size() != 3) return std::nullopt;
  const Vec3f radiance(float(m.emissiveFactor[0] * strength), float(m.emissiveFactor[1] * strength),
                       float(m.emissiveFactor[2] * strength));
  if (!(radiance.x > 0 || radiance.y > 0 || radiance.z > 0)) return std::nullopt;
  return radiance;
}

Vec3f baseColor(const tinygltf::Model& model, const tinygltf::Primitive& prim, Vec3f fallback) {
  if (prim.material < 0 || size_t(prim.material) >= model.materials.size()) return fallback;
  const std::vector<double>& c =
      model.materials[size_t(prim.material)].pbrMetallicRoughness.baseColorFactor;
  return c.size() >= 3 ? Vec3f(float(c[0]), float(c[1]), float(c[2])) : fallback;
}

void gltfSceneToMesh(const tinygltf::Model& model, const GltfPick& pick, const std::string& file,
                     TriMesh& out) {
  GltfAccessors data(model, file);
  const std::vector<Placement> placed = placements(model, data, pick, file);
  std::vector<TriMesh> local(model.meshes.size());
  std::vector<bool> decoded(model.meshes.size(), false);
  size_t expanded = 0;
  for (const Placement& p : placed) {
    const size_t m = size_t(p.mesh);  // in range: placements() checks
    if (!decoded[m]) {
      for (size_t k = 0; k < model.meshes[m].primitives.size(); ++k)
        if (!pick.surfaces_only || !isEmissive(model, model.meshes[m].primitives[k]))
          appendPrimitive(model, data, m, k, file, local[m]);
      decoded[m] = true;
    }
    expanded += local[m].triangles.size();
    if (expanded > kMaxExpandedTriangles)
      throw Error(file, "the scene expands to too many triangles",
                  fmt::format("its nodes place more than {} triangles", kMaxExpandedTriangles),
                  "load one mesh of it, or use it as a scene");
  }
  for (const Placement& p : placed) {
    const TriMesh& mesh = local[size_t(p.mesh)];
    const Mat4& w = p.world;
    const uint32_t base = uint32_t(out.vertices.size());
    for (const Vec3f& v : mesh.vertices) out.vertices.push_back(transformPoint(w, v));
    const bool mirrored = determinant3(w) < 0;
    for (const Triangle& t : mesh.triangles)
      out.triangles.push_back(mirrored ? Triangle{t[0] + base, t[2] + base, t[1] + base}
                                       : Triangle{t[0] + base, t[1] + base, t[2] + base});
  }
}

void decodeGltf(const std::string& bytes, bool binary, const std::filesystem::path& folder,
                const GltfPick& pick, const std::string& file, TriMesh& out) {
  gltfSceneToMesh(parseGltfModel(bytes, binary, folder, file), pick, file, out);
}

}  // namespace proxyvis::detail
