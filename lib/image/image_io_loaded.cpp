// image_io.h's file functions as programs and tests link them: each call goes to the OIIO module,
// loaded on the first one (image/oiio_module.h), so a process that never touches an image file
// never loads OpenImageIO. The module itself links image_io.cpp instead of this file.
#include "image/image_io.h"
#include "image/oiio_module.h"

namespace proxyvis {

void writeImage(const Image& image, const std::filesystem::path& path,
                const ImageWriteOptions& options) {
  oiioModule().write_image(image, path, options);
}

ImageHeader readImageHeader(const std::filesystem::path& path) {
  return oiioModule().read_image_header(path);
}

Image readImage(const std::filesystem::path& path) {
  return oiioModule().read_image(path);
}

}  // namespace proxyvis
