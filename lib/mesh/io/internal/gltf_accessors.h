#pragma once
// Reading glTF accessors with every bound checked before anything is allocated or read: views
// inside their buffers, elements inside their views, sparse indices inside the accessor, and
// meshopt-compressed views decoded once (EXT_meshopt_compression).
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace tinygltf {
class Model;
}

namespace proxyvis::detail {

class GltfAccessors {
 public:
  GltfAccessors(const tinygltf::Model& model, const std::string& file);

  // `components` values per element, as doubles; normalized integers are mapped to [0, 1] or
  // [-1, 1] (KHR_mesh_quantization), other integers keep their value. `where` names the user
  // (e.g. "meshes[0].primitives[1].attributes.POSITION") in errors.
  std::vector<double> readValues(int accessor, int components, const std::string& where);

  // An index accessor (unsigned byte, short or int scalars).
  std::vector<uint32_t> readIndices(int accessor, const std::string& where);

  // The element count an accessor declares, after checking that it exists.
  size_t count(int accessor, const std::string& where) const;

  // The bytes of a buffer view (decoded when meshopt-compressed).
  std::string_view viewBytes(int view, const std::string& where);

 private:
  std::string_view decodeMeshoptView(int view, const std::string& where);

  const tinygltf::Model& model_;
  std::string file_;
  size_t stored_bytes_ = 0;  // all buffers together: the most an accessor without a view may hold
  std::map<int, std::string> decoded_views_;
};

}  // namespace proxyvis::detail
