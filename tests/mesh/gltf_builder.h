#pragma once
// glTF documents written by hand for the loader tests: JSON through nlohmann and raw bytes in one
// buffer, so that what the loader reads was not produced by proxyvis's own writer.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace proxyvis::test {

class GltfBuilder {
 public:
  GltfBuilder();

  // Appends `bytes` (4-byte aligned) as a buffer view of buffer 0; returns the view's index.
  int view(const std::string& bytes, int stride = 0);
  template <typename T>
  int view(const std::vector<T>& values, int stride = 0) {
    std::string bytes(values.size() * sizeof(T), '\0');
    if (!values.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
    return view(bytes, stride);
  }
  // An accessor over `view` (-1: none); returns its index.
  int accessor(int view, int component_type, size_t count, const std::string& type,
               bool normalized = false, size_t offset = 0);
  // A mesh of one primitive; returns the mesh index.
  int mesh(int positions, int indices = -1, int mode = 4, const std::string& name = "m");
  // A node; returns its index. Roots must be listed with root().
  int node(nlohmann::json node);
  void root(int node);

  nlohmann::json doc;
  std::string bin;

  // The document as a GLB with `bin` as its BIN chunk.
  std::string glb() const;
  // The document with buffer 0 at `uri` (the caller writes `bin` there).
  std::string gltf(const std::string& uri) const;
};

// A GLB of `json_text` and `bin`, chunk lengths and padding as the format wants.
std::string glbBytes(const std::string& json_text, const std::string& bin);

}  // namespace proxyvis::test
