#pragma once
// Shared by the proxy-gen tests: where the real meshes are (data/ of the repository, or the
// shared data folder while data/ is being filled) and a cached loader.
#include <filesystem>
#include <map>
#include <mutex>
#include <string>

#include "mesh/mesh_io.h"

namespace proxyvis::gen_test {

inline std::filesystem::path meshPath(const std::string& relative) {
  for (const char* root : {PROXYVIS_DATA_DIR, PROXYVIS_SHARED_DATA_DIR}) {
    std::filesystem::path p = std::filesystem::path(root) / relative;
    if (std::filesystem::exists(p)) return p;
  }
  return std::filesystem::path(PROXYVIS_SHARED_DATA_DIR) / relative;
}

// Meshes are loaded once per test executable.
inline const TriMesh& mesh(const std::string& relative) {
  static std::map<std::string, TriMesh> cache;
  static std::mutex mutex;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(relative);
  if (it == cache.end()) it = cache.emplace(relative, loadMesh(meshPath(relative))).first;
  return it->second;
}

}  // namespace proxyvis::gen_test
