#include "mesh_test_util.h"

#include <unistd.h>
#include <fstream>
#include <sstream>

#include "mesh/primitives.h"

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
  return makeBoxMesh({0, 0, 0}, {1, 1, 1}, "unit cube");
}

}  // namespace proxyvis::test
