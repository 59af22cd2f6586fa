// Parsing a glTF document with tinygltf, behind the checks tinygltf does not make: GLB chunk
// lengths, URIs that would leave the asset's folder, required extensions we cannot honour.
#include "mesh/io/internal/tiny_gltf.h"

#include <fmt/format.h>
#include <cstring>
#include <regex>
#include <set>
#include <system_error>

#include "mesh/io/internal/glb_container.h"
#include "mesh/io/internal/gltf_io.h"
#include "mesh/io/internal/printable.h"
#include "util/error.h"
#include "util/input_file.h"

namespace proxyvis::detail {
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

// Extensions that change what a loader must do with the geometry and that we implement, and
// those that only concern what we ignore (materials, textures, visibility, LODs).
const std::set<std::string> kSupportedRequired = {
    "KHR_draco_mesh_compression",      "KHR_mesh_quantization",
    "EXT_meshopt_compression",         "EXT_mesh_gpu_instancing",
    "KHR_materials_emissive_strength", "KHR_node_visibility",
    "KHR_texture_transform",           "KHR_materials_unlit"};

std::string percentDecoded(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(uint8_t(uri[i + 1])) &&
        std::isxdigit(uint8_t(uri[i + 2]))) {
      out.push_back(char(std::stoi(uri.substr(i + 1, 2), nullptr, 16)));
      i += 2;
    } else {
      out.push_back(uri[i]);
    }
  }
  return out;
}

// Why `uri` may not be read (empty when it may): only relative paths inside the asset's folder
// and data: URIs are.
std::string uriRefusal(const std::string& uri) {
  if (uri.rfind("data:", 0) == 0) return {};
  static const std::regex scheme("^[A-Za-z][A-Za-z0-9+.-]*:");
  if (std::regex_search(uri, scheme))
    return "it names a URI scheme (only data: and relative paths are read)";
  const std::string path = percentDecoded(uri);
  if (path.empty()) return {};
  if (path.find('\0') != std::string::npos) return "it holds a NUL byte";
  if (path[0] == '/' || path[0] == '\\') return "it is an absolute path";
  size_t begin = 0;
  while (begin <= path.size()) {
    const size_t end = path.find_first_of("/\\", begin);
    const std::string part = path.substr(begin, end == std::string::npos ? end : end - begin);
    if (part == "..") return "it climbs out of the asset's folder with '..'";
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  return {};
}

// Calls `f` on every object of the array `key` of `parent` (when both are what they should be).
template <typename F>
void forEachObject(json& parent, const char* key, F&& f) {
  if (!parent.is_object() || !parent.contains(key) || !parent[key].is_array()) return;
  for (json& item : parent[key])
    if (item.is_object()) f(item);
}

const json* extensionOf(const json& object, const char* name) {
  const auto ext = object.find("extensions");
  if (ext == object.end() || !ext->is_object()) return nullptr;
  const auto it = ext->find(name);
  return it == ext->end() ? nullptr : &*it;
}

// The checks on the document itself; returns the JSON to hand to tinygltf.
std::string checkedDocument(const std::string& text, const std::string& file, bool* changed) {
  json doc = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded() || !doc.is_object())
    throw Error(file, "the glTF JSON does not parse",
                "'" + printableExcerpt(text, 40) + "...' is not a JSON object",
                "the file is corrupt; re-export it");
  const json required = doc.value("extensionsRequired", json::array());
  if (!required.is_array())
    throw Error(file, "extensionsRequired is not an array", "", "fix the file");
  for (size_t i = 0; i < required.size(); ++i) {
    const std::string name = required[i].is_string() ? required[i].get<std::string>() : "?";
    if (!kSupportedRequired.count(name))
      throw Error(
          file, fmt::format("extensionsRequired[{}] '{}' is not supported", i, printableText(name)),
          "the file cannot be read correctly without it",
          "re-export without it (proxyvis reads Draco, meshopt and quantized meshes)");
  }
  // glTF requires byteLength >= 1; tinygltf reads byte 0 of an empty GLB buffer (and throws).
  if (doc.contains("buffers") && doc["buffers"].is_array())
    for (size_t i = 0; i < doc["buffers"].size(); ++i) {
      const json& b = doc["buffers"][i];
      const json length = b.is_object() ? b.value("byteLength", json()) : json();
      if (!length.is_number_unsigned() || length.get<uint64_t>() == 0)
        throw Error(file, fmt::format("buffers[{}].byteLength is missing or 0", i),
                    "every buffer holds at least one byte", "the file is corrupt; re-export it");
    }
  for (const char* array : {"buffers", "images"}) {
    const auto it = doc.find(array);
    if (it == doc.end() || !it->is_array()) continue;
    for (size_t i = 0; i < it->size(); ++i) {
      const json& item = (*it)[i];
      if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) continue;
      const std::string uri = item["uri"].get<std::string>();
      const std::string why = uriRefusal(uri);
      if (!why.empty())
        throw Error(file,
                    fmt::format("{}[{}].uri '{}' leaves the asset's folder", array, i,
                                printableExcerpt(uri)),
                    why, "keep buffers beside the .gltf file or inside it");
    }
  }
  *changed = false;
  // What tinygltf would refuse although glTF allows it: a meshopt fallback buffer has no data
  // (it gets 4 zero bytes), a Draco primitive's index accessor no buffer view (the indices come
  // from the Draco data, so the reference is dropped).
  forEachObject(doc, "buffers", [&](json& buffer) {
    const json* ext = extensionOf(buffer, "EXT_meshopt_compression");
    if (ext == nullptr || buffer.contains("uri")) return;
    buffer["uri"] = "data:application/octet-stream;base64,AAAAAA==";
    buffer["byteLength"] = 4;
    *changed = true;
  });
  forEachObject(doc, "meshes", [&](json& mesh) {
    forEachObject(mesh, "primitives", [&](json& primitive) {
      if (extensionOf(primitive, "KHR_draco_mesh_compression") && primitive.contains("indices")) {
        primitive.erase("indices");
        *changed = true;
      }
    });
  });
  return *changed ? doc.dump() : text;
}

struct FolderGuard {
  fs::path folder;  // canonical; empty: nothing may be read
};

// Inside the guard's folder after resolving links ("never read outside it").
bool insideFolder(const FolderGuard& guard, const std::string& path) {
  if (guard.folder.empty()) return false;
  std::error_code ec;
  const fs::path real = fs::weakly_canonical(path, ec);
  if (ec) return false;
  const auto [folder_end, real_end] =
      std::mismatch(guard.folder.begin(), guard.folder.end(), real.begin(), real.end());
  return folder_end == guard.folder.end();
}

bool guardedFileExists(const std::string& path, void* user) {
  std::error_code ec;
  return insideFolder(*static_cast<FolderGuard*>(user), path) && fs::is_regular_file(path, ec);
}

std::string unexpandedPath(const std::string& path, void*) {
  return path;
}  // no wordexp

bool guardedReadWholeFile(std::vector<unsigned char>* out, std::string* err,
                          const std::string& path, void* user) {
  if (!insideFolder(*static_cast<FolderGuard*>(user), path)) {
    *err = "outside the asset's folder";
    return false;
  }
  try {
    const std::string bytes = readTextFile(path);
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const Error& e) {
    *err = e.what();
    return false;
  }
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  *err = "reading never writes";
  return false;
}

// Textures are not used: accept every image without decoding it.
bool ignoreImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                 const unsigned char*, int, void*) {
  return true;
}

std::string firstLine(const std::string& text) {
  const size_t end = text.find('\n');
  return printableText(end == std::string::npos ? text : text.substr(0, end));
}

}  // namespace

tinygltf::Model parseGltfModel(const std::string& bytes, bool binary, const fs::path& folder,
                               const std::string& file) {
  GlbChunks chunks;
  if (binary) chunks = splitGlb(bytes, file);
  bool changed = false;
  const std::string document = checkedDocument(binary ? chunks.json : bytes, file, &changed);

  FolderGuard guard;
  std::error_code ec;
  if (!folder.empty()) guard.folder = fs::weakly_canonical(folder, ec);
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks(
      {guardedFileExists, unexpandedPath, guardedReadWholeFile, refuseWrite, &guard});
  loader.SetImageLoader(ignoreImage, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  const std::string base =
      guard.folder.empty() ? std::string("/nonexistent") : guard.folder.string();
  bool ok = false;
  try {
    if (binary) {
      const std::string glb = changed ? joinGlb(document, chunks) : bytes;
      ok = loader.LoadBinaryFromMemory(&model, &err, &warn,
                                       reinterpret_cast<const unsigned char*>(glb.data()),
                                       unsigned(glb.size()), base);
    } else {
      ok = loader.LoadASCIIFromString(&model, &err, &warn, document.data(),
                                      unsigned(document.size()), base);
    }
  } catch (const std::exception& e) {  // tinygltf indexes with at() in places
    ok = false;
    err = std::string("tinygltf: ") + e.what();
  }
  if (!ok)
    throw Error(file, "glTF file cannot be read", firstLine(err.empty() ? warn : err),
                "the file is corrupt or needs files that are missing; re-export it");
  return model;
}

}  // namespace proxyvis::detail
