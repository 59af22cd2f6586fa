#include "util/atomic_write.h"

#include <unistd.h>
#include <atomic>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <system_error>

#include "util/error.h"
#include "util/input_file.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {
fs::path temporaryPathFor(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  // Keep the extension last: writers (OpenImageIO, Draco, OpenMesh) choose the format by it.
  std::string name = ".";
  name += target.stem().string();
  name += ".tmp" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
  name += target.extension().string();
  return target.parent_path() / name;
}
}  // namespace

void writeAtomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
  if (isRegisteredInput(target))
    throw Error(target.string(), "refusing to overwrite an input of this run", {},
                "choose another output path");
  fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw WriteError(target.string(), "cannot write output",
                     "directory '" + dir.string() + "' does not exist", "create it first");
  fs::path tmp = temporaryPathFor(target);
  try {
    write(tmp);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  if (!fs::exists(tmp, ec))
    throw WriteError(target.string(), "cannot write output", "the writer produced no file");
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw WriteError(target.string(), "cannot write output", ec.message());
  }
}

void writeTextAtomically(const fs::path& target, const std::string& text) {
  if (target == "-") {
    std::cout << text << std::flush;
    return;
  }
  writeAtomically(target, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw WriteError(target.string(), "cannot write output", "write failed (disk full?)");
  });
}

}  // namespace proxyvis
