#include "unit_file.h"

#include <bit>
#include <cstring>
#include <fstream>

#include "util/atomic_write.h"
#include "util/error.h"
#include "util/input_file.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

static_assert(std::endian::native == std::endian::little, "unit files are little-endian");

constexpr std::string_view kMagic = "PVUNIT1\n";

// FNV-1a over 8-byte words (then the last bytes one by one): the checksum of the file, eight
// times faster than byte by byte on the hundreds of megabytes a merge reads.
uint64_t checksum(std::string_view bytes) {
  uint64_t h = 0xcbf29ce484222325ULL;
  size_t i = 0;
  for (; i + 8 <= bytes.size(); i += 8) {
    uint64_t word = 0;
    std::memcpy(&word, bytes.data() + i, 8);
    h = (h ^ word) * 0x100000001b3ULL;
  }
  for (; i < bytes.size(); ++i) h = (h ^ uint8_t(bytes[i])) * 0x100000001b3ULL;
  return h;
}

void appendU64(std::string& out, uint64_t v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

uint64_t readU64(std::string_view bytes, size_t at) {
  uint64_t v = 0;
  std::memcpy(&v, bytes.data() + at, sizeof v);
  return v;
}

[[noreturn]] void notAUnit(const fs::path& path, const std::string& why) {
  throw Error(path.string(), "not a complete render-compare unit result", why,
              "delete the unit's .done marker and run the unit again (submit.sh --resume)");
}

}  // namespace

void writeUnitFile(const fs::path& path, UnitFile file) {
  nlohmann::json list = nlohmann::json::array();
  size_t floats = 0;
  for (const Image& im : file.images) {
    list.push_back({{"width", im.width}, {"height", im.height}, {"channels", im.channels}});
    floats += im.pixels.size();
  }
  file.header["images"] = list;
  const std::string header = file.header.dump();
  std::string bytes;
  bytes.reserve(kMagic.size() + 16 + header.size() + 4 * floats);
  bytes += kMagic;
  appendU64(bytes, header.size());
  bytes += header;
  for (const Image& im : file.images)
    if (!im.pixels.empty())
      bytes.append(reinterpret_cast<const char*>(im.pixels.data()),
                   im.pixels.size() * sizeof(float));
  appendU64(bytes, checksum(bytes));
  writeTextAtomically(path, bytes);
}

UnitFile readUnitFile(const fs::path& path) {
  const std::string bytes = readTextFile(path);
  const std::string_view all(bytes);
  if (all.size() < kMagic.size() + 16 || all.substr(0, kMagic.size()) != kMagic)
    notAUnit(path, "it does not start with the unit file's signature");
  const size_t body = all.size() - 8;
  if (checksum(all.substr(0, body)) != readU64(all, body))
    notAUnit(path, "its checksum does not match its contents (truncated or altered)");
  const uint64_t header_size = readU64(all, kMagic.size());
  size_t at = kMagic.size() + 8;
  if (header_size > body - at) notAUnit(path, "its header runs past the end");
  UnitFile file;
  try {
    file.header = nlohmann::json::parse(all.substr(at, header_size));
    at += header_size;
    for (const nlohmann::json& j : file.header.at("images")) {
      Image im;
      im.width = j.at("width").get<int>();
      im.height = j.at("height").get<int>();
      im.channels = j.at("channels").get<int>();
      if (im.width < 0 || im.height < 0 || im.channels < 0)
        notAUnit(path, "an image has a negative size");
      const uint64_t n = uint64_t(im.width) * uint64_t(im.height) * uint64_t(im.channels);
      if (n > (body - at) / sizeof(float)) notAUnit(path, "an image runs past the end");
      im.pixels.resize(n);
      if (n > 0)  // an empty image has no buffer: memcpy must not get its null pointer
        std::memcpy(im.pixels.data(), all.data() + at, n * sizeof(float));
      at += n * sizeof(float);
      file.images.push_back(std::move(im));
    }
  } catch (const nlohmann::json::exception& e) {
    notAUnit(path, std::string("its header is not what a unit writes: ") + e.what());
  }
  if (at != body) notAUnit(path, "it has bytes after its last image");
  return file;
}

}  // namespace proxyvis
