#pragma once
// OpenImageIO is loaded only when a process first reads or writes an image file or colours a
// heat-map. Linked into a program it brings ~250 shared libraries (gdal, opencv, heif, ...) whose
// symbols the dynamic loader resolves at every start: ~0.4 s of CPU that render-compare's units
// and its plan, which never touch an image, paid for nothing. So the OIIO-backed code
// (image/image_io.cpp, image/color_map_oiio.cpp) is built into a loadable module that lives
// beside the executables, and image/image_io.h and image/color_map.h keep their plain function
// API: each call goes through the table below.
#include <filesystem>
#include <functional>
#include <future>
#include <span>
#include <string_view>
#include <vector>

#include "image/image_io.h"

namespace proxyvis {

// The module's file name; it is looked for in the folder of the running executable.
inline constexpr std::string_view kOiioModuleFile = "libpv_oiio.so";

// Changed whenever the tables or the types they pass change: a module of another build is refused
// instead of being called with the wrong layout.
inline constexpr int kOiioModuleAbi = 2;

// What the module does: the OIIO-backed functions of image_io.h and color_map.h.
struct OiioModule {
  int abi = 0;
  void (*write_image)(const Image&, const std::filesystem::path&, const ImageWriteOptions&);
  ImageHeader (*read_image_header)(const std::filesystem::path&);
  Image (*read_image)(const std::filesystem::path&);
  std::vector<float> (*color_map_rgb)(std::span<const float>, std::string_view);
};

// What the module takes from the program that loads it: the program's own writeAtomically, so
// that an image output is checked against this run's inputs and its temporary file is removed on
// an interrupt like every other output (that state lives in the program, not in the module).
struct OiioModuleHost {
  int abi = 0;
  void (*write_atomically)(const std::filesystem::path&,
                           const std::function<void(const std::filesystem::path&)>&);
};

// The module's table, loaded on the first call (thread-safe; later calls return it at once).
// Throws Error (exit 2) naming the module's path when it is missing, cannot be loaded or is of
// another build.
const OiioModule& oiioModule();

// Starts loading the module on another thread, so that its ~0.4 s of CPU in the dynamic loader
// overlaps the program's own start (loading a scene); get() waits and throws what oiioModule()
// throws: call it before the work whose result needs the module, so that a missing one fails early.
std::future<void> preloadOiioModule();

// preloadOiioModule() when writing `output` needs the module (any format but EXR, which
// image/exr_io.h writes; the rule lives with image_io.h's dispatch, image_io_loaded.cpp);
// otherwise a future that is ready at once.
std::future<void> preloadOiioModuleFor(const std::filesystem::path& output);

}  // namespace proxyvis

// The module's one exported symbol: its table, or null if `host` is of another build.
extern "C" const proxyvis::OiioModule* proxyvis_oiio_module(const proxyvis::OiioModuleHost* host);
