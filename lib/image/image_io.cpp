#include "image/image_io.h"

#include <OpenImageIO/imageio.h>

#include <cmath>

#include "util/atomic_write.h"
#include "util/error.h"
#include "util/lower_case.h"

namespace proxyvis {

namespace {

// The image's reader, or an Error naming the file.
std::unique_ptr<OIIO::ImageInput> openImage(const std::filesystem::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw Error(path.string(), "cannot read image", OIIO::geterror());
  return in;
}

}  // namespace

void writeImage(const Image& image, const std::filesystem::path& path,
                const ImageWriteOptions& options) {
  checkWritable(image, options);
  const std::string ext = lowerExtension(path);
  const bool ldr = ext == ".png" || ext == ".jpg" || ext == ".jpeg";
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    // OIIO picks the format from the file name, so the temporary keeps the real extension.
    const std::filesystem::path named = tmp.string() + ext;
    auto out = OIIO::ImageOutput::create(named.string());
    if (!out) throw WriteError(path.string(), "unsupported image format", OIIO::geterror());
    OIIO::ImageSpec spec(
        image.width, image.height, image.channels,
        ldr ? OIIO::TypeDesc::UINT8
            : (options.full_float || ext != ".exr" ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::HALF));
    if (!options.channel_names.empty()) spec.channelnames = options.channel_names;
    if (ext == ".png") {
      // Rendered images are noisy: zlib's fastest level, no row filter: 4-5x less CPU than OIIO's
      // default (level 6, adaptive filters) and smaller files (a 512x512 report's PNGs 9.2 MB, not
      // 12.7; smooth maps grow a third; docs/slurm.md "Measured"). Same pixels, other encoding.
      spec.attribute("png:compressionLevel", 1);
      spec.attribute("png:filter", 8);  // PNG_FILTER_NONE
    }
    if (ext == ".exr") spec.attribute("compression", options.exr_compression);
    for (const ImageAttribute& a : options.attributes)
      std::visit([&](const auto& v) { spec.attribute(a.name, v); }, a.value);
    bool ok = out->open(named.string(), spec);
    if (ok && ldr) {
      std::vector<uint8_t> bytes(image.pixels.size());
      for (size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = uint8_t(std::lround(255.0f * linearToSrgb(image.pixels[i] * options.exposure)));
      ok = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
    } else if (ok) {
      ok = out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
    }
    const std::string error = ok ? std::string() : out->geterror();
    ok = out->close() && ok;
    std::error_code ec;
    if (!ok) {
      std::filesystem::remove(named, ec);
      throw WriteError(path.string(), "cannot write image", error);
    }
    std::filesystem::rename(named, tmp, ec);
    if (ec) throw WriteError(path.string(), "cannot write image", ec.message());
  });
}

ImageHeader readImageHeader(const std::filesystem::path& path) {
  const auto in = openImage(path);
  const OIIO::ImageSpec& spec = in->spec();
  ImageHeader header;
  header.width = spec.width;
  header.height = spec.height;
  header.channel_names = spec.channelnames;
  for (const OIIO::ParamValue& p : spec.extra_attribs)
    header.attributes.emplace_back(p.name().string(), p.type() == OIIO::TypeDesc::STRING
                                                          ? std::string(p.get_ustring().string())
                                                          : spec.metadata_val(p));
  in->close();
  return header;
}

Image readImage(const std::filesystem::path& path) {
  const auto in = openImage(path);
  const OIIO::ImageSpec& spec = in->spec();
  Image image{spec.width, spec.height, spec.nchannels,
              std::vector<float>(size_t(spec.width) * spec.height * spec.nchannels)};
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw Error(path.string(), "cannot read image", in->geterror());
  in->close();
  return image;
}

}  // namespace proxyvis
