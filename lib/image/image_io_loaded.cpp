// image_io.h's file functions as programs and tests link them: EXR through OpenEXR
// (image/exr_io.h), every other format through the OIIO module, loaded on the first such call
// (image/oiio_module.h), so that a process that only writes EXR never loads OpenImageIO. The
// module itself links image_io.cpp instead of this file.
#include "image/exr_io.h"
#include "image/image_io.h"
#include "image/oiio_module.h"
#include "util/atomic_write.h"

namespace proxyvis {

namespace {

// The one rule for which files go through the module: every format but EXR.
bool needsModule(const std::filesystem::path& path) {
  return !isExrPath(path);
}

}  // namespace

void writeImage(const Image& image, const std::filesystem::path& path,
                const ImageWriteOptions& options) {
  if (needsModule(path)) return oiioModule().write_image(image, path, options);
  checkWritable(image, options);
  writeAtomically(path,
                  [&](const std::filesystem::path& tmp) { writeExr(image, tmp, options, path); });
}

ImageHeader readImageHeader(const std::filesystem::path& path) {
  return needsModule(path) ? oiioModule().read_image_header(path) : readExrHeader(path);
}

Image readImage(const std::filesystem::path& path) {
  return needsModule(path) ? oiioModule().read_image(path) : readExr(path);
}

std::future<void> preloadOiioModuleFor(const std::filesystem::path& output) {
  if (needsModule(output)) return preloadOiioModule();
  std::promise<void> nothing_to_load;
  nothing_to_load.set_value();
  return nothing_to_load.get_future();
}

}  // namespace proxyvis
