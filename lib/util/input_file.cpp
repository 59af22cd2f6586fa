#include "util/input_file.h"

#include <algorithm>
#include <fstream>
#include <mutex>
#include <sstream>
#include <system_error>
#include <vector>

#include "util/error.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {
std::mutex g_inputs_mutex;
std::vector<fs::path>& inputs() {
  static std::vector<fs::path> paths;
  return paths;
}
}  // namespace

void registerInput(const fs::path& path) {
  std::error_code ec;
  fs::path canonical = fs::weakly_canonical(path, ec);
  const fs::path input = ec ? fs::absolute(path, ec) : canonical;
  std::lock_guard<std::mutex> lock(g_inputs_mutex);
  // A long run reads the same files again (references, caches): remember each once.
  if (std::find(inputs().begin(), inputs().end(), input) == inputs().end())
    inputs().push_back(input);
}

bool isRegisteredInput(const fs::path& path) {
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(path, ec);
  std::lock_guard<std::mutex> lock(g_inputs_mutex);
  for (const fs::path& input : inputs()) {
    if (!ec && canonical == input) return true;
    // Hard links and bind mounts: the same inode under another name.
    std::error_code eq_ec;
    if (fs::equivalent(path, input, eq_ec) && !eq_ec) return true;
  }
  return false;
}

uintmax_t checkInputFile(const fs::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);  // follows symlinks
  if (ec || !fs::exists(st)) {
    if (fs::is_symlink(fs::symlink_status(path, ec)))
      throw Error(name, "broken symbolic link", "its target does not exist", "check the link");
    throw Error(name, "file not found", {}, "check the path");
  }
  if (fs::is_directory(st))
    throw Error(name, "is a directory, not a file", {}, "name a file in it");
  if (!fs::is_regular_file(st))
    throw Error(name, "not a regular file",
                "devices, FIFOs and sockets are not read (they may block or never end)",
                "copy the data to a file first");
  const uintmax_t size = fs::file_size(path, ec);
  if (ec) throw Error(name, "cannot read file size", ec.message());
  if (size > kMaxInputBytes)
    throw Error(name, "file too large",
                std::to_string(size) + " bytes, the limit is " + std::to_string(kMaxInputBytes),
                "split the input");
  registerInput(path);
  return size;
}

std::string readTextFile(const fs::path& path) {
  const uintmax_t size = checkInputFile(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string(), "cannot open file", "permission denied", "check its mode");
  std::string bytes(size, '\0');
  in.read(bytes.data(), std::streamsize(size));
  if (in.gcount() != std::streamsize(size))
    throw Error(path.string(), "cannot read file", "it changed size while being read",
                "retry when nothing else writes it");
  return bytes;
}

}  // namespace proxyvis
