#pragma once
// Shared by the proxy-gen tests: where the real meshes are (data/ of the repository, or the
// shared data folder while data/ is being filled) and a cached loader.
#include <filesystem>
#include <map>
#include <mutex>
#include <string>

#include "mesh/mesh_io.h"

namespace proxyvis::gen_test {

// A bundled mesh by file name: data/ (bunny.off, dragon.drc, foliage/YELLOWFLOWER1.ply, ...),
// else the shared data folder (meshes/, foliage/ecosys/; dragon.ply for dragon.drc).
inline std::filesystem::path meshPath(const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path data(PROXYVIS_DATA_DIR), shared(PROXYVIS_SHARED_DATA_DIR);
  const fs::path ply = fs::path(name).replace_extension(".ply");
  for (const fs::path& p : {data / name, data / "foliage" / name, shared / "meshes" / name,
                            shared / "foliage" / "ecosys" / name, shared / "meshes" / ply})
    if (fs::exists(p)) return p;
  return data / name;
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
