// image_io.h's file functions as programs and tests link them: EXR through OpenEXR
// (image/exr_io.h), every other format through the OIIO module, loaded on the first such call
// (image/oiio_module.h), so that a process that only writes EXR never loads OpenImageIO. The
// module itself links image_io.cpp instead of this file.
#include "image/exr_io.h"
#include "image/image_io.h"
#include "image/oiio_module.h"
#include "util/atomic_write.h"
#include "util/error.h"

namespace proxyvis {

void writeImage(const Image& image, const std::filesystem::path& path,
                const ImageWriteOptions& options) {
  if (!isExrPath(path)) return oiioModule().write_image(image, path, options);
  PV_CHECK(image.pixels.size() == size_t(image.width) * image.height * image.channels);
  PV_CHECK(options.channel_names.empty() || int(options.channel_names.size()) == image.channels);
  writeAtomically(path,
                  [&](const std::filesystem::path& tmp) { writeExr(image, tmp, options, path); });
}

ImageHeader readImageHeader(const std::filesystem::path& path) {
  return isExrPath(path) ? readExrHeader(path) : oiioModule().read_image_header(path);
}

Image readImage(const std::filesystem::path& path) {
  return isExrPath(path) ? readExr(path) : oiioModule().read_image(path);
}

}  // namespace proxyvis
