#include "gltf_builder.h"

namespace proxyvis::test {
using json = nlohmann::json;

GltfBuilder::GltfBuilder() {
  doc = {{"asset", {{"version", "2.0"}}},
         {"buffers", json::array({json::object()})},
         {"bufferViews", json::array()},
         {"accessors", json::array()},
         {"meshes", json::array()},
         {"nodes", json::array()},
         {"scenes", json::array({{{"nodes", json::array()}}})},
         {"scene", 0}};
}

int GltfBuilder::view(const std::string& bytes, int stride) {
  json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes.size()}};
  if (stride > 0) v["byteStride"] = stride;
  bin += bytes;
  while (bin.size() % 4) bin.push_back('\0');
  doc["bufferViews"].push_back(v);
  return int(doc["bufferViews"].size() - 1);
}

int GltfBuilder::accessor(int view, int component_type, size_t count, const std::string& type,
                          bool normalized, size_t offset) {
  json a = {{"componentType", component_type}, {"count", count}, {"type", type}};
  if (view >= 0) a["bufferView"] = view;
  if (offset > 0) a["byteOffset"] = offset;
  if (normalized) a["normalized"] = true;
  doc["accessors"].push_back(a);
  return int(doc["accessors"].size() - 1);
}

int GltfBuilder::mesh(int positions, int indices, int mode, const std::string& name) {
  json prim = {{"attributes", {{"POSITION", positions}}}, {"mode", mode}};
  if (indices >= 0) prim["indices"] = indices;
  doc["meshes"].push_back({{"name", name}, {"primitives", json::array({prim})}});
  return int(doc["meshes"].size() - 1);
}

int GltfBuilder::node(json n) {
  doc["nodes"].push_back(n);
  return int(doc["nodes"].size() - 1);
}

void GltfBuilder::root(int n) {
  doc["scenes"][0]["nodes"].push_back(n);
}

std::string glbBytes(const std::string& json_text, const std::string& bin) {
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  std::string text = json_text;
  while (text.size() % 4) text.push_back(' ');
  std::string padded = bin;
  while (padded.size() % 4) padded.push_back('\0');
  std::string body = u32(uint32_t(text.size())) + u32(0x4E4F534A) + text;
  if (!padded.empty()) body += u32(uint32_t(padded.size())) + u32(0x004E4942) + padded;
  return u32(0x46546C67) + u32(2) + u32(uint32_t(12 + body.size())) + body;
}

std::string GltfBuilder::glb() const {
  json d = doc;
  d["buffers"][0] = {{"byteLength", bin.size()}};
  return glbBytes(d.dump(), bin);
}

std::string GltfBuilder::gltf(const std::string& uri) const {
  json d = doc;
  d["buffers"][0] = {{"byteLength", bin.size()}, {"uri", uri}};
  return d.dump();
}

}  // namespace proxyvis::test
