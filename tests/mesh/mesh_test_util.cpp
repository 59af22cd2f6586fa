#include "mesh_test_util.h"

#include <unistd.h>
#include <fstream>
#include <sstream>

namespace proxyvis::test {
namespace fs = std::filesystem;

fs::path dataFile(const std::string& relative) {
  return fs::path(PROXYVIS_DATA_DIR) / relative;
}
fs::path sharedFile(const std::string& relative) {
  return fs::path(PROXYVIS_SHARED_DATA_DIR) / relative;
}

ScratchDir::ScratchDir(const std::string& name) {
  path_ = fs::temp_directory_path() / ("proxyvis_mesh_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(path_);
  fs::create_directories(path_);
}
ScratchDir::~ScratchDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

void writeBytes(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TriMesh unitCube() {
  TriMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back(float(i & 1), float((i >> 1) & 1), float(i >> 2));
  // Corner i = (x, y, z) bits; each face as two triangles, counter-clockwise seen from outside.
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  m.source = "unit cube";
  return m;
}

}  // namespace proxyvis::test
