#pragma once
// Reading inputs safely. Only regular files are read (a FIFO would block forever, /dev/zero never
// ends), never more than a size limit, and every file read is remembered so that no output of
// the same run can replace it (util/atomic_write.h refuses such a target).
#include <cstdint>
#include <filesystem>
#include <string>

namespace proxyvis {

// The largest input file any loader reads (meshes, scenes, instance lists, reports).
inline constexpr uintmax_t kMaxInputBytes = uintmax_t(4) << 30;

// Checks that `path` names an existing, readable regular file (symlinks are followed) of at most
// kMaxInputBytes, registers it as an input of this run and returns its size. Throws Error naming
// the file otherwise (missing, a directory, a device or FIFO, too large).
uintmax_t checkInputFile(const std::filesystem::path& path);

// Reads a whole input file (after checkInputFile); throws Error naming the file on failure.
std::string readTextFile(const std::filesystem::path& path);

// Remembers `path` as an input of this run (checkInputFile does this itself).
void registerInput(const std::filesystem::path& path);

// True if `path` is the same file as an input of this run (through links and other spellings).
bool isRegisteredInput(const std::filesystem::path& path);

}  // namespace proxyvis
