// A glTF file as one triangle mesh: primitives decoded (plain, Draco, meshopt, quantized), nodes
// walked from the default scene with their transforms applied.
#include "mesh/io/internal/tiny_gltf.h"

#include <fmt/format.h>
#include <array>
#include <cmath>

#include "mesh/io/internal/draco_io.h"
#include "mesh/io/internal/gltf_accessors.h"
#include "mesh/io/internal/gltf_io.h"
#include "util/error.h"

namespace proxyvis::detail {
namespace {

// More triangles than this after instancing is refused (about 1.6 GB of mesh): a small file whose
// nodes repeat a large mesh many times would otherwise exhaust memory.
constexpr size_t kMaxExpandedTriangles = size_t(1) << 26;

using Mat4 = std::array<double, 16>;  // column-major, as glTF stores it

Mat4 identity() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row)
      for (int k = 0; k < 4; ++k) r[c * 4 + row] += a[k * 4 + row] * b[c * 4 + k];
  return r;
}

Mat4 trsMatrix(const double* t, const double* r, const double* sc) {
  Mat4 m = identity();
  if (sc)
    for (int i = 0; i < 3; ++i) m[i * 4 + i] = sc[i];
  if (r) {
    const double x = r[0], y = r[1], z = r[2], w = r[3];
    const Mat4 rot = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w), 0,
                      2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w), 0,
                      2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y), 0,
                      0, 0, 0, 1};
    m = multiply(rot, m);
  }
  if (t)
    for (int i = 0; i < 3; ++i) m[12 + i] = t[i];
  return m;
}

// The node's local transform: its matrix, or T * R * S.
Mat4 localTransform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    Mat4 m;
    std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
    return m;
  }
  return trsMatrix(node.translation.size() == 3 ? node.translation.data() : nullptr,
                   node.rotation.size() == 4 ? node.rotation.data() : nullptr,
                   node.scale.size() == 3 ? node.scale.data() : nullptr);
}

// EXT_mesh_gpu_instancing: the node's mesh drawn once per instance, each with its own T * R * S
// after the node's world transform. Empty when the node has no such extension.
std::vector<Mat4> gpuInstances(const tinygltf::Node& node, int index, GltfAccessors& data,
                               const std::string& file) {
  const auto ext = node.extensions.find("EXT_mesh_gpu_instancing");
  if (ext == node.extensions.end()) return {};
  const std::string at = fmt::format("nodes[{}].extensions.EXT_mesh_gpu_instancing", index);
  const tinygltf::Value& attributes = ext->second.Get("attributes");
  std::vector<double> values[3];
  const char* names[3] = {"TRANSLATION", "ROTATION", "SCALE"};
  const int components[3] = {3, 4, 3};
  size_t count = SIZE_MAX;
  for (int k = 0; k < 3; ++k) {
    if (!attributes.Has(names[k])) continue;
    const tinygltf::Value& accessor = attributes.Get(names[k]);
    values[k] = data.readValues(accessor.IsNumber() ? accessor.GetNumberAsInt() : -1,
                                components[k], at + ".attributes." + names[k]);
    const size_t n = values[k].size() / size_t(components[k]);
    if (count != SIZE_MAX && n != count)
      throw Error(file, at + " attributes differ in count",
                  fmt::format("{} has {} instances, another {}", names[k], n, count),
                  "the file is corrupt; re-export it");
    count = n;
  }
  if (count == SIZE_MAX)
    throw Error(file, at + " has no attributes", "instances need a translation, rotation or scale",
                "the file is corrupt; re-export it");
  std::vector<Mat4> out(count);
  for (size_t i = 0; i < count; ++i)
    out[i] = trsMatrix(values[0].empty() ? nullptr : &values[0][3 * i],
                       values[1].empty() ? nullptr : &values[1][4 * i],
                       values[2].empty() ? nullptr : &values[2][3 * i]);
  return out;
}

double determinant3(const Mat4& m) {
  return m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
         m[8] * (m[1] * m[6] - m[5] * m[2]);
}

struct Placement {
  int mesh;
  Mat4 world;
};

// The (mesh, world transform) pairs of the default scene; every mesh once, untransformed, when
// the file has no scene or no nodes.
// The one index of `items` whose name is `name`; Error naming the choices otherwise.
template <typename T>
int pickByName(const std::vector<T>& items, const std::string& name, const char* what,
               const char* whats, const char* flag, const std::string& file) {
  std::vector<int> found;
  std::string names;
  for (size_t i = 0; i < items.size(); ++i) {
    if (items[i].name == name) found.push_back(int(i));
    if (i < 8) names += (names.empty() ? "'" : ", '") + printableText(items[i].name) + "'";
  }
  if (items.size() > 8) names += fmt::format(" and {} more", items.size() - 8);
  if (found.size() == 1) return found[0];
  throw Error(file,
              found.empty() ? fmt::format("no {} is named '{}'", what, printableText(name))
                            : fmt::format("{} {} are named '{}'", found.size(), whats,
                                          printableText(name)),
              fmt::format("the file's {}: {}", whats, names.empty() ? "none" : names),
              fmt::format("give {} one of those names", flag));
}

std::vector<Placement> placements(const tinygltf::Model& model, GltfAccessors& data,
                                  const GltfPick& pick, const std::string& file) {
  std::vector<Placement> out;
  if (!pick.mesh.empty()) {
    out.push_back({pickByName(model.meshes, pick.mesh, "mesh", "meshes", "--mesh", file), identity()});
    return out;
  }
  const int picked_node =
      pick.node.empty() ? -1 : pickByName(model.nodes, pick.node, "node", "nodes", "--node", file);
  bool picked_reached = false;
  std::vector<int> roots;
  if (!model.scenes.empty()) {
    const int s = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (size_t(s) >= model.scenes.size())
      throw Error(file, fmt::format("scene {} is the default", s),
                  fmt::format("the file has {} scenes", model.scenes.size()),
                  "the file is corrupt; re-export it");
    roots = model.scenes[size_t(s)].nodes;
  }
  if (roots.empty() && picked_node < 0) {
    for (size_t m = 0; m < model.meshes.size(); ++m) out.push_back({int(m), identity()});
    return out;
  }
  // Depth-first with the path on a stack: a node met again on its own path is a cycle; a node
  // reached twice otherwise has two parents, which glTF forbids as well.
  std::vector<int> visits(model.nodes.size(), 0);
  struct Frame {
    int node;
    Mat4 parent;
    bool picked;  // in the subtree of --node (or no --node given)
  };
  std::vector<Frame> stack;
  for (int r : roots) stack.push_back({r, identity(), picked_node < 0});
  while (!stack.empty()) {
    const Frame f = stack.back();
    stack.pop_back();
    if (f.node < 0 || size_t(f.node) >= model.nodes.size())
      throw Error(file, fmt::format("a scene or node names nodes[{}]", f.node),
                  fmt::format("the file has {} nodes", model.nodes.size()),
                  "the file is corrupt; re-export it");
    if (visits[size_t(f.node)]++ > 0)
      throw Error(file, fmt::format("nodes[{}] is reached twice", f.node),
                  "the node graph has a cycle or a node with two parents (glTF 2.0 3.5.3)",
                  "the file is corrupt; re-export it");
    const tinygltf::Node& node = model.nodes[size_t(f.node)];
    const Mat4 world = multiply(f.parent, localTransform(node));
    const bool picked = f.picked || f.node == picked_node;
    picked_reached = picked_reached || f.node == picked_node;
    if (node.mesh >= 0 && picked) {
      const std::vector<Mat4> instances = gpuInstances(node, f.node, data, file);
      if (instances.empty()) out.push_back({node.mesh, world});
      for (const Mat4& instance : instances) out.push_back({node.mesh, multiply(world, instance)});
    }
    for (int c : node.children) stack.push_back({c, world, picked});
  }
  if (picked_node >= 0 && !picked_reached)
    throw Error(file, fmt::format("node '{}' is not in the default scene", printableText(pick.node)),
                "only the scene's nodes have a place in the world", "pick a node of the scene");
  return out;
}

const char* modeName(int mode) {
  static const char* names[] = {"points", "lines", "a line loop", "a line strip"};
  return mode >= 0 && mode < 4 ? names[mode] : "an unknown mode";
}

// The triangles of one primitive in its mesh's space, appended to `local` (positions after the
// ones already there).
void appendPrimitive(const tinygltf::Model& model, GltfAccessors& data, size_t mesh_index,
                     size_t prim_index, const std::string& file, TriMesh& local) {
  const tinygltf::Mesh& mesh = model.meshes[mesh_index];
  const tinygltf::Primitive& prim = mesh.primitives[prim_index];
  const std::string where = fmt::format("meshes[{}].primitives[{}]", mesh_index, prim_index);
  const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
  if (mode < TINYGLTF_MODE_TRIANGLES || mode > TINYGLTF_MODE_TRIANGLE_FAN)
    throw Error(file, fmt::format("{} (mesh '{}') draws {}", where, printableText(mesh.name), modeName(mode)),
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
  const std::vector<double> p = data.readValues(position->second, 3, where + ".attributes.POSITION");
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
                  fmt::format("the primitive has {} vertices", n), "the file is corrupt; re-export it");
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

}  // namespace

void gltfSceneToMesh(const tinygltf::Model& model, const GltfPick& pick, const std::string& file,
                     TriMesh& out) {
  GltfAccessors data(model, file);
  const std::vector<Placement> placed = placements(model, data, pick, file);
  std::vector<TriMesh> local(model.meshes.size());
  std::vector<bool> decoded(model.meshes.size(), false);
  size_t expanded = 0;
  for (const Placement& p : placed) {
    if (p.mesh < 0 || size_t(p.mesh) >= model.meshes.size())
      throw Error(file, fmt::format("a node names meshes[{}]", p.mesh),
                  fmt::format("the file has {} meshes", model.meshes.size()),
                  "the file is corrupt; re-export it");
    const size_t m = size_t(p.mesh);
    if (!decoded[m]) {
      for (size_t k = 0; k < model.meshes[m].primitives.size(); ++k)
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
    for (const Vec3f& v : mesh.vertices) {
      const double x = v.x, y = v.y, z = v.z;
      out.vertices.push_back(Vec3f(float(w[0] * x + w[4] * y + w[8] * z + w[12]),
                                   float(w[1] * x + w[5] * y + w[9] * z + w[13]),
                                   float(w[2] * x + w[6] * y + w[10] * z + w[14])));
    }
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
