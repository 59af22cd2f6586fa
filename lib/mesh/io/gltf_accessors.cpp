#include "mesh/io/internal/gltf_accessors.h"

#include <meshoptimizer.h>
#include "mesh/io/internal/tiny_gltf.h"

#include <fmt/format.h>
#include <algorithm>
#include <cstring>
#include <limits>
#include <type_traits>

#include "util/error.h"

namespace proxyvis::detail {
namespace {

// A meshopt view decodes to at most this many times its compressed size (the vertex codec's best
// case is 64:1 on constant data): more means a count that lies.
constexpr size_t kMaxMeshoptRatio = 256;

size_t componentSize(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

template <class T>
T readAs(const char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// A component of integer type T; normalized: signed ones map to [-1, 1], unsigned to [0, 1].
template <class T>
double readInteger(const char* p, bool normalized) {
  const double v = readAs<T>(p), top = double(std::numeric_limits<T>::max());
  if (!normalized) return v;
  return std::is_signed_v<T> ? std::max(v / top, -1.0) : v / top;
}

double readComponent(const char* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return readInteger<int8_t>(p, normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return readInteger<uint8_t>(p, normalized);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return readInteger<int16_t>(p, normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return readInteger<uint16_t>(p, normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return readAs<uint32_t>(p);
    default:
      return readAs<float>(p);
  }
}

// The byte span of `count` elements of `element` bytes every `stride` from `offset` must lie in
// `size` bytes (no overflow on lying counts).
bool fits(size_t offset, size_t count, size_t stride, size_t element, size_t size) {
  if (count == 0) return offset <= size;
  if (offset > size || element > size - offset) return false;
  return (count - 1) <= (size - offset - element) / stride;
}

}  // namespace

GltfAccessors::GltfAccessors(const tinygltf::Model& model, const std::string& file)
    : model_(model), file_(file) {
  for (const tinygltf::Buffer& b : model.buffers) stored_bytes_ += b.data.size();
}

size_t GltfAccessors::count(int accessor, const std::string& where) const {
  if (accessor < 0 || size_t(accessor) >= model_.accessors.size())
    throw Error(file_, fmt::format("{} names accessor {}", where, accessor),
                fmt::format("the file has {} accessors", model_.accessors.size()),
                "the file is corrupt; re-export it");
  return model_.accessors[size_t(accessor)].count;
}

std::string_view GltfAccessors::viewBytes(int view, const std::string& where) {
  if (view < 0 || size_t(view) >= model_.bufferViews.size())
    throw Error(file_, fmt::format("{} names bufferViews[{}]", where, view),
                fmt::format("the file has {} buffer views", model_.bufferViews.size()),
                "the file is corrupt; re-export it");
  const tinygltf::BufferView& v = model_.bufferViews[size_t(view)];
  if (v.extensions.count("EXT_meshopt_compression")) return decodeMeshoptView(view, where);
  if (v.buffer < 0 || size_t(v.buffer) >= model_.buffers.size())
    throw Error(file_, fmt::format("bufferViews[{}] names buffers[{}]", view, v.buffer),
                fmt::format("the file has {} buffers", model_.buffers.size()),
                "the file is corrupt; re-export it");
  const std::vector<unsigned char>& data = model_.buffers[size_t(v.buffer)].data;
  if (!fits(v.byteOffset, 1, 1, v.byteLength, data.size()))
    throw Error(file_, fmt::format("bufferViews[{}] lies outside its buffer", view),
                fmt::format("bytes {}..{} of a {}-byte buffer", v.byteOffset,
                            v.byteOffset + v.byteLength, data.size()),
                "the file is corrupt; re-export it");
  return {reinterpret_cast<const char*>(data.data()) + v.byteOffset, v.byteLength};
}

std::string_view GltfAccessors::decodeMeshoptView(int view, const std::string& where) {
  if (auto it = decoded_views_.find(view); it != decoded_views_.end()) return it->second;
  const tinygltf::BufferView& v = model_.bufferViews[size_t(view)];
  const tinygltf::Value& ext = v.extensions.at("EXT_meshopt_compression");
  const std::string at = fmt::format("bufferViews[{}].extensions.EXT_meshopt_compression", view);
  auto number = [&](const char* key) -> size_t {
    const tinygltf::Value& value = ext.Get(key);
    const double d = value.IsNumber() ? value.GetNumberAsDouble() : -1;
    if (!(d >= 0 && d < 1e15))
      throw Error(file_, fmt::format("{}.{} is missing or not a count", at, key), "",
                  "the file is corrupt; re-export it");
    return size_t(d);
  };
  auto text = [&](const char* key, const char* fallback) {
    const tinygltf::Value& value = ext.Get(key);
    return value.IsString() ? value.Get<std::string>() : std::string(fallback);
  };
  if (!ext.IsObject())
    throw Error(file_, at + " is not an object", "", "the file is corrupt; re-export it");
  const size_t buffer = number("buffer"), offset = ext.Has("byteOffset") ? number("byteOffset") : 0;
  const size_t length = number("byteLength"), stride = number("byteStride"),
               count = number("count");
  const std::string mode = text("mode", ""), filter = text("filter", "NONE");
  if (buffer >= model_.buffers.size() ||
      !fits(offset, 1, 1, length, model_.buffers[buffer].data.size()))
    throw Error(file_, at + " lies outside its buffer",
                fmt::format("bytes {}..{} of buffers[{}]", offset, offset + length, buffer),
                "the file is corrupt; re-export it");
  if (stride == 0 || stride > 256 || count > (length * kMaxMeshoptRatio + 4096) / stride)
    throw Error(file_, fmt::format("{} declares {} elements of {} bytes", at, count, stride),
                fmt::format("from {} compressed bytes that cannot be", length),
                "the file is corrupt; re-export it");
  std::string out(count * stride, '\0');
  const unsigned char* src = model_.buffers[buffer].data.data() + offset;
  int status = -1;
  if (mode == "ATTRIBUTES" && stride % 4 == 0)
    status = meshopt_decodeVertexBuffer(out.data(), count, stride, src, length);
  else if (mode == "TRIANGLES" && (stride == 2 || stride == 4) && count % 3 == 0)
    status = meshopt_decodeIndexBuffer(out.data(), count, stride, src, length);
  else if (mode == "INDICES" && (stride == 2 || stride == 4))
    status = meshopt_decodeIndexSequence(out.data(), count, stride, src, length);
  if (status != 0)
    throw Error(file_, at + " does not decode",
                fmt::format("mode '{}', {} elements of {} bytes from {} bytes", printableText(mode),
                            count, stride, length),
                "the file is corrupt; re-export it");
  if (filter == "OCTAHEDRAL" && (stride == 4 || stride == 8))
    meshopt_decodeFilterOct(out.data(), count, stride);
  else if (filter == "QUATERNION" && stride == 8)
    meshopt_decodeFilterQuat(out.data(), count, stride);
  else if (filter == "EXPONENTIAL" && stride % 4 == 0)
    meshopt_decodeFilterExp(out.data(), count, stride);
  else if (filter != "NONE")
    throw Error(
        file_, fmt::format("{} filter '{}' on {}-byte elements", at, printableText(filter), stride),
        "that filter does not apply to such elements", "the file is corrupt; re-export it");
  (void)where;
  return decoded_views_.emplace(view, std::move(out)).first->second;
}

std::vector<double> GltfAccessors::readValues(int index, int components, const std::string& where) {
  count(index, where);
  const tinygltf::Accessor& a = model_.accessors[size_t(index)];
  const std::string at = fmt::format("accessors[{}] ({})", index, where);
  const size_t component = componentSize(a.componentType);
  if (component == 0 || tinygltf::GetNumComponentsInType(uint32_t(a.type)) != components)
    throw Error(file_, at + " has the wrong type",
                fmt::format("component type {}, type {}; {} components were expected",
                            a.componentType, a.type, components),
                "the file is corrupt; re-export it");
  const size_t element = component * size_t(components);
  std::string_view bytes;
  size_t stride = element;
  if (a.bufferView >= 0) {
    bytes = viewBytes(a.bufferView, at);
    const size_t view_stride = model_.bufferViews[size_t(a.bufferView)].byteStride;
    if (view_stride != 0) stride = view_stride;
    if (stride < element || !fits(a.byteOffset, a.count, stride, element, bytes.size()))
      throw Error(file_, at + " reaches past its buffer view",
                  fmt::format("{} elements of {} bytes every {} from offset {} in {} bytes",
                              a.count, element, stride, a.byteOffset, bytes.size()),
                  "the file is corrupt; re-export it");
  } else if (a.count > stored_bytes_ + 4096) {
    throw Error(file_, fmt::format("{} declares {} elements and no data", at, a.count),
                fmt::format("more than the file's {} bytes could describe", stored_bytes_),
                "the file is corrupt; re-export it");
  }
  std::vector<double> values(a.count * size_t(components), 0.0);
  for (size_t i = 0; i < a.count && !bytes.empty(); ++i)
    for (int c = 0; c < components; ++c)
      values[i * size_t(components) + size_t(c)] =
          readComponent(bytes.data() + a.byteOffset + i * stride + size_t(c) * component,
                        a.componentType, a.normalized);
  if (a.sparse.isSparse) {
    const size_t n = size_t(std::max(a.sparse.count, 0));
    const size_t index_size = componentSize(a.sparse.indices.componentType);
    const std::string_view idx = viewBytes(a.sparse.indices.bufferView, at + ".sparse.indices");
    const std::string_view val = viewBytes(a.sparse.values.bufferView, at + ".sparse.values");
    const size_t idx_offset = size_t(std::max(a.sparse.indices.byteOffset, 0));
    const size_t val_offset = size_t(std::max(a.sparse.values.byteOffset, 0));
    // glTF allows only unsigned integer indices; a float index could be NaN or fractional.
    const int index_type = a.sparse.indices.componentType;
    if (n > a.count || index_size == 0 ||
        (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
         index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
         index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) ||
        !fits(idx_offset, n, index_size, index_size, idx.size()) ||
        !fits(val_offset, n, element, element, val.size()))
      throw Error(file_, at + " has a sparse part that does not fit",
                  fmt::format("{} of {} elements, index type {}", n, a.count,
                              a.sparse.indices.componentType),
                  "the file is corrupt; re-export it");
    for (size_t k = 0; k < n; ++k) {
      const double target = readComponent(idx.data() + idx_offset + k * index_size,
                                          a.sparse.indices.componentType, false);
      if (target >= double(a.count))
        throw Error(file_, fmt::format("{}.sparse index {} is {}", at, k, target),
                    fmt::format("the accessor has {} elements", a.count),
                    "the file is corrupt; re-export it");
      for (int c = 0; c < components; ++c)
        values[size_t(target) * size_t(components) + size_t(c)] =
            readComponent(val.data() + val_offset + k * element + size_t(c) * component,
                          a.componentType, a.normalized);
    }
  }
  return values;
}

std::vector<uint32_t> GltfAccessors::readIndices(int index, const std::string& where) {
  count(index, where);
  const int type = model_.accessors[size_t(index)].componentType;
  if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    throw Error(file_, fmt::format("accessors[{}] ({}) has component type {}", index, where, type),
                "indices are unsigned bytes, shorts or ints", "the file is corrupt; re-export it");
  const std::vector<double> values = readValues(index, 1, where);
  return std::vector<uint32_t>(values.begin(), values.end());
}

}  // namespace proxyvis::detail
