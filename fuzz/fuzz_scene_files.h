#pragma once
// A scratch folder for the scene targets: the scene file's folder, holding the few files the
// seed scenes refer to (fuzz/make_seeds.py renames every reference to one of these), so that the
// fuzzer gets past "file not found" into the rest of the validation. Their contents are never
// read by the parse stage. Removed at exit.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace proxyvis::fuzz {

inline const std::filesystem::path& sceneFolder() {
  static const std::filesystem::path folder = [] {
    std::string templ = (std::filesystem::temp_directory_path() / "proxyvis-fuzz-XXXXXX").string();
    if (!mkdtemp(templ.data())) std::abort();
    const std::filesystem::path dir = templ;
    for (const char* name : {"a.obj", "b.ply", "c.off", "d.drc", "p.ply", "i.txt"})
      std::ofstream(dir / name) << "x\n";
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(sceneFolder(), ec);
    });
    return dir;
  }();
  return folder;
}

}  // namespace proxyvis::fuzz
