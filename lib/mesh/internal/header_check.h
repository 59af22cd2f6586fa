#pragma once
// Plausibility of the element counts a PLY or OFF header declares, checked against the file size
// before any reader sees the file: a header that claims 2^31 vertices in a 1 KB file is an Error,
// not an 8 GB allocation (OpenMesh reserves what the header says).
#include <string>

namespace proxyvis::detail {

// Throws Error naming `file` when the header of `bytes` (the whole file) is unreadable or declares
// more elements than the file could hold. `ext` is "ply" or "off"; other formats are not checked.
void checkDeclaredCounts(const std::string& bytes, const std::string& ext, const std::string& file);

}  // namespace proxyvis::detail
