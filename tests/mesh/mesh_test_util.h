#pragma once
// Shared helpers of mesh_tests: where the data is, scratch directories, small meshes.
#include <filesystem>
#include <string>

#include "mesh/tri_mesh.h"

namespace proxyvis::test {

std::filesystem::path dataFile(const std::string& relative);    // data/<relative>
std::filesystem::path sharedFile(const std::string& relative);  // ../shared/data/<relative>

// A fresh empty directory under the system temp dir, removed by the destructor.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name);
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& file) const { return path_ / file; }

 private:
  std::filesystem::path path_;
};

void writeBytes(const std::filesystem::path& path, const std::string& bytes);
std::string readBytes(const std::filesystem::path& path);

// Unit cube [0,1]^3 as 12 outward-oriented triangles (volume 1, closed, genus 0).
TriMesh unitCube();

}  // namespace proxyvis::test
