// The GLB container: a 12-byte header, a JSON chunk and an optional BIN chunk (glTF 2.0, 4.4).
#include "mesh/io/internal/glb_container.h"

#include <fmt/format.h>
#include <cstring>

#include "util/error.h"

namespace proxyvis::detail {
namespace {

constexpr uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534A;
constexpr uint32_t kChunkBin = 0x004E4942;

uint32_t readU32(const std::string& bytes, size_t at) {
  uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;  // glTF is little-endian, as every machine we build for
}

}  // namespace

GlbChunks splitGlb(const std::string& bytes, const std::string& file) {
  if (bytes.size() < 20)
    throw Error(file, "truncated GLB",
                fmt::format("{} bytes, a GLB header alone is 20", bytes.size()),
                "the file was not written completely; re-export it");
  if (readU32(bytes, 0) != kGlbMagic)
    throw Error(file, "not a GLB file", "it does not start with the magic 'glTF'",
                "a JSON glTF file must be named .gltf");
  if (readU32(bytes, 4) != 2)
    throw Error(file, fmt::format("GLB version {}", readU32(bytes, 4)), "only glTF 2.0 is read",
                "re-export as glTF 2.0");
  const uint64_t total = readU32(bytes, 8);
  if (total != bytes.size())
    throw Error(file, "GLB header length lies",
                fmt::format("the header says {} bytes, the file has {}", total, bytes.size()),
                total > bytes.size() ? "the file is truncated; re-export it"
                                     : "the file is corrupt; re-export it");
  GlbChunks chunks;
  size_t at = 12;
  for (int index = 0; at < bytes.size(); ++index) {
    if (bytes.size() - at < 8)
      throw Error(file, fmt::format("GLB chunk {} header is truncated", index),
                  fmt::format("{} bytes left at offset {}", bytes.size() - at, at),
                  "the file is corrupt; re-export it");
    const uint64_t length = readU32(bytes, at);
    const uint32_t type = readU32(bytes, at + 4);
    if (length > bytes.size() - at - 8)
      throw Error(file, fmt::format("GLB chunk {} length lies", index),
                  fmt::format("it claims {} bytes, {} are left", length, bytes.size() - at - 8),
                  "the file is truncated or corrupt; re-export it");
    std::string data = bytes.substr(at + 8, length);
    if (index == 0) {
      if (type != kChunkJson)
        throw Error(file, "GLB chunk 0 is not JSON", "the first chunk must hold the document",
                    "the file is corrupt; re-export it");
      chunks.json = std::move(data);
    } else if (index == 1 && type == kChunkBin) {
      chunks.bin = std::move(data);
      chunks.has_bin = true;
    }  // other chunks are to be ignored (glTF 2.0, 4.4.3)
    at += 8 + length;
  }
  if (chunks.json.empty())
    throw Error(file, "GLB has no JSON chunk", "the file holds only its header",
                "the file is corrupt; re-export it");
  return chunks;
}

std::string joinGlb(const std::string& json_text, const GlbChunks& chunks) {
  auto chunk = [](std::string data, uint32_t type, char pad) {
    while (data.size() % 4) data.push_back(pad);
    std::string out(8, '\0');
    const uint32_t length = uint32_t(data.size());
    std::memcpy(out.data(), &length, 4);
    std::memcpy(out.data() + 4, &type, 4);
    return out + data;
  };
  std::string body = chunk(json_text, kChunkJson, ' ');
  if (chunks.has_bin) body += chunk(chunks.bin, kChunkBin, '\0');
  std::string header(12, '\0');
  const uint32_t version = 2, length = uint32_t(12 + body.size());
  std::memcpy(header.data(), &kGlbMagic, 4);
  std::memcpy(header.data() + 4, &version, 4);
  std::memcpy(header.data() + 8, &length, 4);
  return header + body;
}

}  // namespace proxyvis::detail
