#pragma once
// Image files through OpenImageIO (library pv_image, separate from pv_render so that tests do not
// link OIIO). EXR keeps linear float values; PNG is tone-mapped for viewing: value * exposure,
// clamped to [0, 1], sRGB transfer curve, 8 bits.
#include <filesystem>
#include <string>
#include <vector>

#include "util/image.h"

namespace proxyvis {

// Writes `image` (any channel count; 1 and 3 are the usual) atomically. The format follows the
// extension: .exr (half float unless full_float), .png (tone-mapped), .pfm/.hdr also work
// through OIIO as linear. Throws WriteError when the file cannot be written.
struct ImageWriteOptions {
  float exposure = 1.0f;    // PNG only: scale before clamping
  bool full_float = false;  // EXR: 32-bit float channels instead of half
  // EXR/TIFF channel names (one per channel); empty: OIIO's defaults (R, G, B, A, ...).
  std::vector<std::string> channel_names;
};
void writeImage(const Image& image, const std::filesystem::path& path,
                const ImageWriteOptions& options = {});

// Reads an image as linear floats (PNG/JPEG are decoded from sRGB by OIIO's metadata only when
// the file says so: EXR is the format to read back). Throws Error naming the file on failure.
Image readImage(const std::filesystem::path& path);

// The sRGB transfer curve (IEC 61966-2-1) of a linear value in [0, 1].
float linearToSrgb(float v);

}  // namespace proxyvis
