// The node graph of a glTF scene: transforms (matrix or T * R * S, GPU instances), the walk from
// the default scene's roots, and picking a node or mesh by name.
#include "mesh/io/internal/gltf_nodes.h"

#include <fmt/format.h>

#include "mesh/io/internal/gltf_accessors.h"
#include "mesh/io/internal/tiny_gltf.h"
#include "util/error.h"

namespace proxyvis::detail {
namespace {

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
    const Mat4 rot = {1 - 2 * (y * y + z * z),
                      2 * (x * y + z * w),
                      2 * (x * z - y * w),
                      0,
                      2 * (x * y - z * w),
                      1 - 2 * (x * x + z * z),
                      2 * (y * z + x * w),
                      0,
                      2 * (x * z + y * w),
                      2 * (y * z - x * w),
                      1 - 2 * (x * x + y * y),
                      0,
                      0,
                      0,
                      0,
                      1};
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
    values[k] = data.readValues(accessor.IsNumber() ? accessor.GetNumberAsInt() : -1, components[k],
                                at + ".attributes." + names[k]);
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
              found.empty()
                  ? fmt::format("no {} is named '{}'", what, printableText(name))
                  : fmt::format("{} {} are named '{}'", found.size(), whats, printableText(name)),
              fmt::format("the file's {}: {}", whats, names.empty() ? "none" : names),
              fmt::format("give {} one of those names", flag));
}

// KHR_node_visibility: "visible": false hides the node and everything below it.
bool hiddenNode(const tinygltf::Node& node) {
  const auto ext = node.extensions.find("KHR_node_visibility");
  if (ext == node.extensions.end() || !ext->second.IsObject()) return false;
  const tinygltf::Value& visible = ext->second.Get("visible");
  return visible.IsBool() && !visible.Get<bool>();
}

void checkIndex(int index, size_t count, const char* what, int node, const std::string& file) {
  if (index >= 0 && size_t(index) >= count)
    throw Error(file, fmt::format("nodes[{}] names {} {}", node, what, index),
                fmt::format("the file has {} of them", count), "the file is corrupt; re-export it");
}

}  // namespace

Mat4 identity() {
  return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
}

double determinant3(const Mat4& m) {
  return m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
         m[8] * (m[1] * m[6] - m[5] * m[2]);
}

Vec3f transformPoint(const Mat4& w, const Vec3f& v) {
  const double x = v.x, y = v.y, z = v.z;
  return Vec3f(float(w[0] * x + w[4] * y + w[8] * z + w[12]),
               float(w[1] * x + w[5] * y + w[9] * z + w[13]),
               float(w[2] * x + w[6] * y + w[10] * z + w[14]));
}

std::vector<Placement> placements(const tinygltf::Model& model, GltfAccessors& data,
                                  const GltfPick& pick, const std::string& file,
                                  std::vector<Placement>* cameras) {
  std::vector<Placement> out;
  if (pick.mesh_index >= 0) {
    if (size_t(pick.mesh_index) >= model.meshes.size())
      throw Error(file, fmt::format("no meshes[{}]", pick.mesh_index),
                  fmt::format("the file has {} meshes", model.meshes.size()),
                  "the file changed since the scene was read; run again");
    out.push_back({pick.mesh_index, identity(), -1});
    return out;
  }
  if (!pick.mesh.empty()) {
    out.push_back(
        {pickByName(model.meshes, pick.mesh, "mesh", "meshes", "--mesh", file), identity(), -1});
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
    for (size_t m = 0; m < model.meshes.size(); ++m) out.push_back({int(m), identity(), -1});
    return out;
  }
  // Depth-first with the path on a stack: a node met again on its own path is a cycle; a node
  // reached twice otherwise has two parents, which glTF forbids as well.
  std::vector<int> visits(model.nodes.size(), 0);
  struct Frame {
    int node;
    Mat4 parent;
    bool picked;   // in the subtree of --node (or no --node given)
    bool visible;  // no KHR_node_visibility hides it or an ancestor (below a picked node)
  };
  std::vector<Frame> stack;
  for (int r : roots) stack.push_back({r, identity(), picked_node < 0, true});
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
    // A node picked by name is taken even when hidden; what it hides below it is not.
    const bool visible = f.node == picked_node || (f.visible && !hiddenNode(node));
    // Every index a placement carries is in range: its users index the model's arrays with it.
    checkIndex(node.mesh, model.meshes.size(), "mesh", f.node, file);
    checkIndex(node.camera, model.cameras.size(), "camera", f.node, file);
    if (cameras && node.camera >= 0 && picked && visible)
      cameras->push_back({node.camera, world, f.node});
    if (node.mesh >= 0 && picked && visible) {
      const std::vector<Mat4> instances = gpuInstances(node, f.node, data, file);
      if (instances.empty()) out.push_back({node.mesh, world, f.node});
      for (const Mat4& instance : instances)
        out.push_back({node.mesh, multiply(world, instance), f.node});
    }
    for (int c : node.children) stack.push_back({c, world, picked, visible});
  }
  if (picked_node >= 0 && !picked_reached)
    throw Error(file,
                fmt::format("node '{}' is not in the default scene", printableText(pick.node)),
                "only the scene's nodes have a place in the world", "pick a node of the scene");
  return out;
}

}  // namespace proxyvis::detail
