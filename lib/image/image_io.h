#pragma once
// Image files through OpenImageIO (library pv_image, separate from pv_render so that tests do not
// link OIIO). EXR keeps linear float values; PNG is tone-mapped for viewing: value * exposure,
// clamped to [0, 1], sRGB transfer curve, 8 bits.
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "util/image.h"

namespace proxyvis {

// One metadata entry of an image file (an OpenImageIO ImageSpec attribute: EXR header attributes,
// PNG text chunks), e.g. {"proxyvis:spp", 64}.
struct ImageAttribute {
  std::string name;
  std::variant<int, float, std::string> value;
};

// Writes `image` (any channel count; 1 and 3 are the usual) atomically. The format follows the
// extension: .exr (half float unless full_float), .png (tone-mapped), .pfm/.hdr also work
// through OIIO as linear. Throws WriteError when the file cannot be written.
struct ImageWriteOptions {
  float exposure = 1.0f;    // PNG only: scale before clamping
  bool full_float = false;  // EXR: 32-bit float channels instead of half
  // EXR: OpenEXR's compression by its OIIO name: none, rle, zips, zip, piz, pxr24, b44, b44a,
  // dwaa, dwab.
  std::string exr_compression = "zip";
  // EXR/TIFF channel names (one per channel); empty: OIIO's defaults (R, G, B, A, ...).
  std::vector<std::string> channel_names;
  std::vector<ImageAttribute> attributes;  // metadata written with the pixels
};
void writeImage(const Image& image, const std::filesystem::path& path,
                const ImageWriteOptions& options = {});

// What both writers (OpenEXR's and the OIIO module's) require, checked with PV_CHECK (a caller's
// bug): as many pixel values as the size says, and one name per channel when names are given.
void checkWritable(const Image& image, const ImageWriteOptions& options);

// Reads an image's metadata (every attribute, numbers as text) and channel names, for tests and
// tools. Throws Error naming the file on failure.
struct ImageHeader {
  int width = 0, height = 0;
  std::vector<std::string> channel_names;
  std::vector<std::pair<std::string, std::string>> attributes;
  // The value of attribute `name` as text; empty if it is missing.
  std::string attribute(const std::string& name) const;
};
ImageHeader readImageHeader(const std::filesystem::path& path);

// Reads an image as linear floats (PNG/JPEG are decoded from sRGB by OIIO's metadata only when
// the file says so: EXR is the format to read back). Throws Error naming the file on failure.
Image readImage(const std::filesystem::path& path);

// Exposure for a tone-mapped PNG: the 99th percentile of the image's brightest channel maps to 1
// (1 for a black image). render-compare takes it from the reference, for every image alike.
float autoExposure(const Image& image);

// The sRGB transfer curve (IEC 61966-2-1) of a linear value in [0, 1].
float linearToSrgb(float v);

}  // namespace proxyvis
