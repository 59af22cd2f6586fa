#pragma once
// Reading a mesh file as loadMesh does, for the readers that parse it their own way (a glTF file
// read as a scene).
#include <filesystem>
#include <string>

namespace proxyvis::detail {

// The file's bytes (only a regular file; Error otherwise), checked against its "<file>.sha256"
// sidecar when it has one.
std::string readMeshFile(const std::filesystem::path& path);

// The folder the file's relative references resolve in: its parent, "." for a bare file name.
std::filesystem::path folderOf(const std::filesystem::path& path);

}  // namespace proxyvis::detail
