#pragma once
// Where proxy-gen writes in scene mode: file names derived from scene mesh names.
#include <string>
#include <vector>

namespace proxyvis {

// One file stem per mesh name, safe to join to --out-dir: only [A-Za-z0-9._-] are kept (others
// become '_'), no leading dot (no "..", no hidden file), never empty, and unique ignoring case
// (a later duplicate gets "-2", "-3", ...), so no name can reach outside the directory or make
// two meshes share a file.
std::vector<std::string> proxyFileStems(const std::vector<std::string>& names);

}  // namespace proxyvis
