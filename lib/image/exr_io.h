#pragma once
// EXR files through OpenEXR itself, without OpenImageIO: most images a run writes or reads are
// EXR (renders, study units, AOVs), and loading the OIIO module costs ~0.4 s of CPU per process
// (image/oiio_module.h), more than a small render. image_io.h sends .exr paths here and every
// other format to the module. The files are what OIIO wrote: ZIP compression, half float unless
// full_float, the attributes under their own names, OIIO's "DateTime" as EXR's capDate.
#include <filesystem>

#include "image/image_io.h"

namespace proxyvis {

// True for a path ending in .exr (any case).
bool isExrPath(const std::filesystem::path& path);

// Writes `image` to `file` as it is (writeImage gives it a temporary); errors name `target`.
// Throws WriteError.
void writeExr(const Image& image, const std::filesystem::path& file,
              const ImageWriteOptions& options, const std::filesystem::path& target);

// Reads an EXR's header (attributes as text, channels in the order readExr returns them) or
// its pixels as floats. Channels are ordered as OIIO orders them: unlayered ones first, R G B A
// leading, then each layer's (sorted by layer name). Throws Error naming the file.
ImageHeader readExrHeader(const std::filesystem::path& path);
Image readExr(const std::filesystem::path& path);

}  // namespace proxyvis
