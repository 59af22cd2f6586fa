#pragma once
// Where proxy-gen writes: file names derived from scene mesh names, and the check, made before
// any work, that no output would replace an input of the run.
#include <filesystem>
#include <string>
#include <vector>

namespace proxyvis {

// One file stem per mesh name, safe to join to --out-dir: only [A-Za-z0-9._-] are kept (others
// become '_'), no leading dot (no "..", no hidden file), never empty, and unique ignoring case
// (a later duplicate gets "-2", "-3", ...), so no name can reach outside the directory or make
// two meshes share a file.
std::vector<std::string> proxyFileStems(const std::vector<std::string>& names);

// Throws Error (exit code 2) naming the first of `outputs` that is the same file as an input
// registered so far (util/input_file.h), or that appears twice among `outputs`.
void refuseOutputsOverInputs(const std::vector<std::filesystem::path>& outputs);

}  // namespace proxyvis
