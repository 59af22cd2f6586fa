// Writing meshes as glTF 2.0 with tinygltf: one buffer, per mesh a position view and an index
// view, one node per mesh carrying its name and extras.
#include "mesh/io/internal/tiny_gltf.h"

#include <fmt/format.h>
#include <cstring>
#include <sstream>

#include "mesh/io/internal/gltf_io.h"
#include "util/error.h"

namespace proxyvis::detail {
namespace {

using json = nlohmann::json;

tinygltf::Value toValue(const json& j) {
  switch (j.type()) {
    case json::value_t::boolean: return tinygltf::Value(j.get<bool>());
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
      // tinygltf keeps ints as int: larger integers (byte counts, seeds) go as doubles.
      if (j.is_number_integer() && j.get<int64_t>() >= INT32_MIN && j.get<int64_t>() <= INT32_MAX)
        return tinygltf::Value(int(j.get<int64_t>()));
      return tinygltf::Value(j.get<double>());
    case json::value_t::number_float: return tinygltf::Value(j.get<double>());
    case json::value_t::string: return tinygltf::Value(j.get<std::string>());
    case json::value_t::array: {
      tinygltf::Value::Array a;
      for (const json& item : j) a.push_back(toValue(item));
      return tinygltf::Value(std::move(a));
    }
    case json::value_t::object: {
      tinygltf::Value::Object o;
      for (const auto& [key, item] : j.items()) o[key] = toValue(item);
      return tinygltf::Value(std::move(o));
    }
    default: return tinygltf::Value();
  }
}

void appendPadded(std::vector<unsigned char>& buffer, const void* data, size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  buffer.insert(buffer.end(), bytes, bytes + size);
  while (buffer.size() % 4) buffer.push_back(0);
}

// Adds a buffer view over `size` bytes at the end of buffer 0 and returns its index.
int addView(tinygltf::Model& model, const void* data, size_t size, int target) {
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = model.buffers[0].data.size();
  view.byteLength = size;
  view.target = target;
  appendPadded(model.buffers[0].data, data, size);
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size() - 1);
}

int addPositions(tinygltf::Model& model, const TriMesh& mesh) {
  tinygltf::Accessor a;
  a.bufferView = addView(model, mesh.vertices.data(), mesh.vertices.size() * sizeof(Vec3f),
                         TINYGLTF_TARGET_ARRAY_BUFFER);
  a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  a.type = TINYGLTF_TYPE_VEC3;
  a.count = mesh.vertices.size();
  const Bounds3f b = mesh.bounds();  // of the referenced vertices; unreferenced ones are kept too
  a.minValues = {b.lo.x, b.lo.y, b.lo.z};
  a.maxValues = {b.hi.x, b.hi.y, b.hi.z};
  for (const Vec3f& v : mesh.vertices)
    for (int c = 0; c < 3; ++c) {
      a.minValues[size_t(c)] = std::min(a.minValues[size_t(c)], double(v[c]));
      a.maxValues[size_t(c)] = std::max(a.maxValues[size_t(c)], double(v[c]));
    }
  model.accessors.push_back(a);
  return int(model.accessors.size() - 1);
}

int addIndices(tinygltf::Model& model, const TriMesh& mesh) {
  tinygltf::Accessor a;
  a.type = TINYGLTF_TYPE_SCALAR;
  a.count = mesh.triangles.size() * 3;
  const uint32_t* flat = mesh.triangles.front().data();
  if (mesh.vertices.size() <= 65535) {
    std::vector<uint16_t> narrow(flat, flat + a.count);
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    a.bufferView = addView(model, narrow.data(), narrow.size() * 2,
                           TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  } else {
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    a.bufferView = addView(model, flat, a.count * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  }
  model.accessors.push_back(a);
  return int(model.accessors.size() - 1);
}

}  // namespace

std::string encodeGltf(const std::vector<GltfMeshOut>& meshes, bool binary,
                       const json& asset_extras, const std::string& file) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "proxyvis " PROXYVIS_VERSION;
  if (!asset_extras.is_null()) model.asset.extras = toValue(asset_extras);
  model.buffers.emplace_back();
  tinygltf::Scene scene;
  bool any_hidden = false;
  for (const GltfMeshOut& out : meshes) {
    if (out.mesh == nullptr || out.mesh->triangles.empty())
      throw WriteError(file, "cannot write an empty mesh", "glTF primitives need triangles");
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.attributes["POSITION"] = addPositions(model, *out.mesh);
    prim.indices = addIndices(model, *out.mesh);
    tinygltf::Mesh mesh;
    mesh.name = out.name;
    mesh.primitives.push_back(prim);
    model.meshes.push_back(mesh);
    tinygltf::Node node;
    node.name = out.name;
    node.mesh = int(model.meshes.size() - 1);
    if (!out.extras.is_null()) node.extras = toValue(out.extras);
    if (out.hidden) {
      node.extensions["KHR_node_visibility"] =
          tinygltf::Value(tinygltf::Value::Object{{"visible", tinygltf::Value(false)}});
      any_hidden = true;
    }
    model.nodes.push_back(node);
    scene.nodes.push_back(int(model.nodes.size() - 1));
  }
  if (any_hidden) model.extensionsUsed.push_back("KHR_node_visibility");
  model.buffers[0].data.shrink_to_fit();
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  std::ostringstream stream(std::ios::out | std::ios::binary);
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, stream, /*prettyPrint=*/!binary, binary))
    throw WriteError(file, "cannot write output", "tinygltf's writer failed");
  return std::move(stream).str();
}

}  // namespace proxyvis::detail
