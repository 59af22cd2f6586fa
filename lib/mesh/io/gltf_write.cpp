// Writing a glTF document (mesh/io/gltf_document.h) with tinygltf: positions and indices in
// buffer 0, plain or compressed (Draco, meshopt). What tinygltf 2.7 cannot serialize
// (extensions of buffer views and buffers, a buffer without data) is set in the written JSON
// afterwards, at the JSON pointers recorded while building.
#include <meshoptimizer.h>

#include <fmt/format.h>
#include <algorithm>
#include <cstring>
#include <sstream>

#include "mesh/io/gltf_document.h"
#include "mesh/io/internal/draco_io.h"
#include "mesh/io/internal/glb_container.h"
#include "mesh/io/internal/tiny_gltf.h"
#include "util/error.h"

namespace proxyvis::detail {
namespace {

using json = nlohmann::json;

tinygltf::Value toValue(const json& j) {
  switch (j.type()) {
    case json::value_t::boolean:
      return tinygltf::Value(j.get<bool>());
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
      // tinygltf keeps ints as int: larger integers (byte counts, seeds) go as doubles.
      if (j.is_number_integer() && j.get<int64_t>() >= INT32_MIN && j.get<int64_t>() <= INT32_MAX)
        return tinygltf::Value(int(j.get<int64_t>()));
      return tinygltf::Value(j.get<double>());
    case json::value_t::number_float:
      return tinygltf::Value(j.get<double>());
    case json::value_t::string:
      return tinygltf::Value(j.get<std::string>());
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
    default:
      return tinygltf::Value();
  }
}

size_t padded(size_t n) {
  return (n + 3) / 4 * 4;
}

struct GltfEncoding {
  bool binary = true;  // GLB; else .gltf with the buffer as a data: URI
  GltfCompression compression = GltfCompression::kNone;
  int draco_bits = 0;  // Draco position quantization (0: lossless floats)
  int draco_speed = 5;
};

class ModelBuilder {
 public:
  ModelBuilder(const GltfEncoding& encoding, const std::string& file)
      : encoding_(encoding), file_(file) {
    meshopt_encodeVertexVersion(0);  // what EXT_meshopt_compression decoders read
    meshopt_encodeIndexVersion(1);
    model_.asset.version = "2.0";
    model_.asset.generator = "proxyvis " PROXYVIS_VERSION;
    model_.buffers.emplace_back();
    if (encoding.compression == GltfCompression::kMeshopt) {
      model_.buffers.emplace_back();  // the fallback: byte counts only, set after writing
      use("EXT_meshopt_compression");
    }
    if (encoding.compression == GltfCompression::kDraco) use("KHR_draco_mesh_compression");
  }

  tinygltf::Model& model() { return model_; }

  tinygltf::Primitive primitive(const TriMesh& mesh) {
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    if (encoding_.compression == GltfCompression::kDraco) return dracoPrimitive(mesh);
    const bool narrow = mesh.vertices.size() <= 65535;
    const uint32_t* flat = mesh.triangles.front().data();
    const size_t index_count = mesh.triangles.size() * 3;
    int position_view = -1, index_view = -1;
    if (encoding_.compression == GltfCompression::kMeshopt) {
      position_view = meshoptView(mesh.vertices.data(), mesh.vertices.size(), sizeof(Vec3f),
                                  "ATTRIBUTES", TINYGLTF_TARGET_ARRAY_BUFFER);
      index_view = meshoptView(flat, index_count, narrow ? 2 : 4, "TRIANGLES",
                               TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    } else {
      position_view = view(mesh.vertices.data(), mesh.vertices.size() * sizeof(Vec3f),
                           TINYGLTF_TARGET_ARRAY_BUFFER);
      if (narrow) {
        const std::vector<uint16_t> indices(flat, flat + index_count);
        index_view = view(indices.data(), index_count * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
      } else {
        index_view = view(flat, index_count * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
      }
    }
    prim.attributes["POSITION"] = positions(position_view, mesh);
    prim.indices = indices(index_view, index_count, narrow);
    return prim;
  }

  void addMaterial(const GltfMaterialOut& in) {
    tinygltf::Material m;
    m.pbrMetallicRoughness.baseColorFactor = {in.base_color.x, in.base_color.y, in.base_color.z, 1};
    m.pbrMetallicRoughness.metallicFactor = 0;
    m.doubleSided = true;
    m.emissiveFactor = {in.emissive.x, in.emissive.y, in.emissive.z};
    if (in.emissive_strength != 1) {
      m.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(tinygltf::Value::Object{
          {"emissiveStrength", tinygltf::Value(double(in.emissive_strength))}});
      use("KHR_materials_emissive_strength", /*required=*/false);
    }
    model_.materials.push_back(m);
  }

  void addMesh(const GltfMeshOut& out) {
    if (out.mesh == nullptr || out.mesh->triangles.empty())
      throw WriteError(file_, "cannot write an empty mesh", "glTF primitives need triangles");
    tinygltf::Mesh mesh;
    mesh.name = out.name;
    tinygltf::Primitive prim = primitive(*out.mesh);
    prim.material = out.material;
    mesh.primitives.push_back(prim);
    if (!out.extras.is_null()) mesh.extras = toValue(out.extras);
    model_.meshes.push_back(mesh);
  }

  void addCamera(const GltfCameraOut& in) {
    tinygltf::Camera c;
    c.type = "perspective";
    c.perspective.yfov = in.yfov;
    c.perspective.aspectRatio = in.aspect;
    c.perspective.znear = in.znear;
    c.perspective.zfar = 1e7;  // beyond any scene (coordinates stay within 1e6)
    model_.cameras.push_back(c);
  }

  void addNode(const GltfNodeOut& out) {
    tinygltf::Node node;
    node.name = out.name;
    node.mesh = out.mesh;
    node.camera = out.camera;
    node.children = out.children;
    const Affine3f identity;
    if (out.transform && std::memcmp(out.transform->m, identity.m, sizeof identity.m) != 0) {
      const Affine3f& t = *out.transform;
      node.matrix.assign(16, 0.0);
      for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 4; ++col) node.matrix[size_t(col * 4 + row)] = t.m[row][col];
      node.matrix[15] = 1;
    }
    if (!out.extras.is_null()) node.extras = toValue(out.extras);
    const int index = int(model_.nodes.size());
    if (out.hidden) {
      // tinygltf 2.7 writes no node extensions: set after writing, like the buffer views'.
      patches_.emplace_back(fmt::format("/nodes/{}/extensions/KHR_node_visibility", index),
                            json{{"visible", false}});
      use("KHR_node_visibility", /*required=*/false);
    }
    if (!out.lod_nodes.empty()) {
      patches_.emplace_back(fmt::format("/nodes/{}/extensions/MSFT_lod", index),
                            json{{"ids", out.lod_nodes}});
      use("MSFT_lod", /*required=*/false);
    }
    model_.nodes.push_back(node);
    if (out.root) scene_.nodes.push_back(index);
  }

  // The file's bytes, with the recorded JSON set at its pointers.
  std::string write() {
    model_.scenes.push_back(scene_);
    model_.defaultScene = 0;
    if (encoding_.compression == GltfCompression::kMeshopt)
      patches_.emplace_back(
          "/buffers/1", json{{"byteLength", fallback_bytes_},
                             {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
    std::ostringstream stream(std::ios::out | std::ios::binary);
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model_, stream, /*prettyPrint=*/!encoding_.binary,
                                       encoding_.binary))
      throw WriteError(file_, "cannot write output", "tinygltf's writer failed");
    std::string bytes = std::move(stream).str();
    if (patches_.empty()) return bytes;
    GlbChunks chunks;
    if (encoding_.binary) chunks = splitGlb(bytes, file_);
    json doc = json::parse(encoding_.binary ? chunks.json : bytes);
    for (const auto& [pointer, value] : patches_) doc[json::json_pointer(pointer)] = value;
    return encoding_.binary ? joinGlb(doc.dump(), chunks) : doc.dump(2);
  }

 private:
  void use(const std::string& extension, bool required = true) {
    auto add = [&](std::vector<std::string>& list) {
      if (std::find(list.begin(), list.end(), extension) == list.end()) list.push_back(extension);
    };
    add(model_.extensionsUsed);
    if (required) add(model_.extensionsRequired);
  }

  // Appends `size` bytes to buffer 0 (4-byte aligned) and returns their offset.
  size_t append(const void* data, size_t size) {
    std::vector<unsigned char>& buffer = model_.buffers[0].data;
    const size_t offset = buffer.size();
    const auto* bytes = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), bytes, bytes + size);
    buffer.resize(padded(buffer.size()), 0);
    return offset;
  }

  int view(const void* data, size_t size, int target) {
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = append(data, size);
    v.byteLength = size;
    v.target = target;
    model_.bufferViews.push_back(v);
    return int(model_.bufferViews.size() - 1);
  }

  // A view of `count` elements of `stride` bytes in the fallback buffer, whose data is the
  // meshopt encoding in buffer 0 (EXT_meshopt_compression). Indices come as 32-bit values and
  // are written with `stride` 2 or 4.
  int meshoptView(const void* data, size_t count, size_t stride, const char* mode, int target) {
    std::vector<unsigned char> encoded;
    if (std::strcmp(mode, "ATTRIBUTES") == 0) {
      encoded.resize(meshopt_encodeVertexBufferBound(count, stride));
      encoded.resize(
          meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), data, count, stride));
    } else {
      const auto* indices = static_cast<const unsigned int*>(data);
      size_t vertices = 0;
      for (size_t i = 0; i < count; ++i) vertices = std::max<size_t>(vertices, indices[i] + 1);
      encoded.resize(meshopt_encodeIndexBufferBound(count, vertices));
      encoded.resize(meshopt_encodeIndexBuffer(encoded.data(), encoded.size(), indices, count));
    }
    if (encoded.empty())
      throw WriteError(file_, "meshopt cannot encode the mesh", "the encoder returned no bytes");
    const size_t offset = append(encoded.data(), encoded.size());
    tinygltf::BufferView v;
    v.buffer = 1;
    v.byteOffset = fallback_bytes_;
    v.byteLength = count * stride;
    if (target == TINYGLTF_TARGET_ARRAY_BUFFER) v.byteStride = stride;
    v.target = target;
    fallback_bytes_ += padded(count * stride);
    model_.bufferViews.push_back(v);
    const int index = int(model_.bufferViews.size() - 1);
    patches_.emplace_back(fmt::format("/bufferViews/{}/extensions", index),
                          json{{"EXT_meshopt_compression",
                                {{"buffer", 0},
                                 {"byteOffset", offset},
                                 {"byteLength", encoded.size()},
                                 {"byteStride", stride},
                                 {"count", count},
                                 {"mode", mode}}}});
    return index;
  }

  tinygltf::Primitive dracoPrimitive(const TriMesh& mesh) {
    const std::string bytes = encodeDraco(mesh, encoding_.draco_bits, encoding_.draco_speed, file_);
    // The accessors describe what a decoder gets: Draco may reorder and quantize points.
    TriMesh decoded;
    decodeDraco(bytes, file_, decoded);
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.attributes["POSITION"] = positions(-1, decoded);
    prim.indices = indices(-1, decoded.triangles.size() * 3, decoded.vertices.size() <= 65535);
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = append(bytes.data(), bytes.size());
    v.byteLength = bytes.size();
    model_.bufferViews.push_back(v);
    prim.extensions["KHR_draco_mesh_compression"] = tinygltf::Value(tinygltf::Value::Object{
        {"bufferView", tinygltf::Value(int(model_.bufferViews.size() - 1))},
        {"attributes",
         tinygltf::Value(tinygltf::Value::Object{{"POSITION", tinygltf::Value(0)}})}});
    return prim;
  }

  int positions(int view, const TriMesh& mesh) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.type = TINYGLTF_TYPE_VEC3;
    a.count = mesh.vertices.size();
    // Over every vertex, referenced or not: the validator checks min/max against all of them.
    a.minValues = {INFINITY, INFINITY, INFINITY};
    a.maxValues = {-INFINITY, -INFINITY, -INFINITY};
    for (const Vec3f& v : mesh.vertices)
      for (size_t c = 0; c < 3; ++c) {
        a.minValues[c] = std::min(a.minValues[c], double(v[int(c)]));
        a.maxValues[c] = std::max(a.maxValues[c], double(v[int(c)]));
      }
    model_.accessors.push_back(a);
    return int(model_.accessors.size() - 1);
  }

  int indices(int view, size_t count, bool narrow) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.type = TINYGLTF_TYPE_SCALAR;
    a.count = count;
    a.componentType =
        narrow ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    model_.accessors.push_back(a);
    return int(model_.accessors.size() - 1);
  }

  GltfEncoding encoding_;
  std::string file_;
  tinygltf::Model model_;
  tinygltf::Scene scene_;
  size_t fallback_bytes_ = 0;
  std::vector<std::pair<std::string, json>> patches_;
};

}  // namespace
}  // namespace proxyvis::detail

namespace proxyvis {

std::string encodeGltfDocument(const GltfDocumentOut& document, bool binary,
                               GltfCompression compression, int draco_bits, int draco_speed,
                               const std::string& file) {
  detail::GltfEncoding encoding;
  encoding.binary = binary;
  encoding.compression = compression;
  encoding.draco_bits = draco_bits;
  encoding.draco_speed = draco_speed;
  detail::ModelBuilder builder(encoding, file);
  if (!document.asset_extras.is_null())
    builder.model().asset.extras = detail::toValue(document.asset_extras);
  for (const GltfMaterialOut& m : document.materials) builder.addMaterial(m);
  for (const GltfMeshOut& m : document.meshes) builder.addMesh(m);
  for (const GltfCameraOut& c : document.cameras) builder.addCamera(c);
  for (const GltfNodeOut& n : document.nodes) builder.addNode(n);
  return builder.write();
}

}  // namespace proxyvis
