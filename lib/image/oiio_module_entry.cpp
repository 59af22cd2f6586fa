// The entry point of the OIIO module (libpv_oiio.so; image/oiio_module.h): built into the module
// only, never into a program.
#include "image/color_map_oiio.h"
#include "image/oiio_module.h"
#include "util/atomic_write.h"

namespace proxyvis {

namespace {
const OiioModuleHost* g_host = nullptr;
}  // namespace

// image_io.cpp writes through the loading program's writeAtomically (see OiioModuleHost); the
// module links no copy of its own.
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path&)>& write) {
  g_host->write_atomically(target, write);
}

}  // namespace proxyvis

extern "C" __attribute__((visibility("default"))) const proxyvis::OiioModule* proxyvis_oiio_module(
    const proxyvis::OiioModuleHost* host) {
  using namespace proxyvis;
  if (!host || host->abi != kOiioModuleAbi || !host->write_atomically) return nullptr;
  g_host = host;
  static const OiioModule table{kOiioModuleAbi, &writeImage, &readImageHeader, &readImage,
                                &colorMapRgbOiio};
  return &table;
}
