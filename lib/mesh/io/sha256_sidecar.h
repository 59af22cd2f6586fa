#pragma once
// The integrity sidecar of a mesh file: "<file>.sha256" beside it, one line in sha256sum's format
// ("<64 hex digits>  <file name>\n", so `sha256sum -c` checks it as well). Mesh formats carry no
// checksum (Draco decodes most single-byte corruptions to a different mesh without complaint), so
// saveMesh writes a sidecar after every mesh and loadMesh verifies it when one is present; a
// program that reads or stages a mesh's bytes itself (proxy-gen's scene cache) does the same.
#include <filesystem>
#include <string>

namespace proxyvis {

// `mesh` with ".sha256" appended to its file name.
std::filesystem::path sidecarPathOf(const std::filesystem::path& mesh);

// The sidecar's line for `mesh` whose content is `bytes`.
std::string sidecarLine(const std::filesystem::path& mesh, const std::string& bytes);

// When `mesh` has a sidecar, checks that `bytes` (the mesh file's content) has the hash it
// records. Throws Error naming the mesh on a mismatch, naming the sidecar when it is not a
// readable sha256sum line (a FIFO or device sidecar is refused, not read). No sidecar: no check.
void verifySidecar(const std::filesystem::path& mesh, const std::string& bytes);

}  // namespace proxyvis
