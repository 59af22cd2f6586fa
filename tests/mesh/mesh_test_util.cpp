#include "mesh_test_util.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "mesh/primitives.h"

namespace proxyvis::test {
namespace fs = std::filesystem;

fs::path dataFile(const std::string& relative) {
  return fs::path(PROXYVIS_DATA_DIR) / relative;
}
uint64_t readmeNumber(std::string text) {
  std::erase(text, ',');
  return std::stoull(text);
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
