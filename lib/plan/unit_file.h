#pragma once
// The file a work unit of a plan writes (units/K.result): a JSON header and raw float
// images, closed by a checksum, so that the merge reads back exactly the bits the unit had and
// refuses a truncated or altered file.
//
// Layout: "PVUNIT1\n", the header's length (8 bytes, little-endian), the header (JSON text), each
// image's floats in the order of the header's "images" list ({"width", "height", "channels"}),
// then a checksum of everything before it (8 bytes: FNV-1a 64 over 8-byte words).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "util/image.h"

namespace proxyvis {

struct UnitFile {
  nlohmann::json header;  // "images" is filled in by writeUnitFile
  std::vector<Image> images;
};

// Writes `file` atomically (temporary name, then rename).
void writeUnitFile(const std::filesystem::path& path, UnitFile file);

// Reads and checks a unit file; throws Error naming `path` if it is not one (truncated, altered,
// another format).
UnitFile readUnitFile(const std::filesystem::path& path);

}  // namespace proxyvis
