#pragma once
// Shared helpers of mesh_tests: where the data is, scratch directories, small meshes.
#include <cstdint>
#include <filesystem>
#include <string>

#include "mesh/tri_mesh.h"
#include "tests/support/scratch_dir.h"

namespace proxyvis::test {

std::filesystem::path dataFile(const std::string& relative);  // data/<relative>
// A number as data/README.md prints it ("69,451").
uint64_t readmeNumber(std::string text);

void writeBytes(const std::filesystem::path& path, const std::string& bytes);
std::string readBytes(const std::filesystem::path& path);

// Unit cube [0,1]^3 as 12 outward-oriented triangles (volume 1, closed, genus 0).
TriMesh unitCube();

}  // namespace proxyvis::test
