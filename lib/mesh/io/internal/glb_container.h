#pragma once
// Splitting a GLB into its chunks (every length checked against the file) and joining chunks
// into a GLB.
#include <string>

namespace proxyvis::detail {

struct GlbChunks {
  std::string json;
  std::string bin;
  bool has_bin = false;
};

// The JSON and BIN chunks of a GLB. Throws Error naming `file` and the chunk for a truncated file,
// lengths that lie, another magic or version, or a first chunk that is not JSON.
GlbChunks splitGlb(const std::string& bytes, const std::string& file);

// A GLB of `json_text` and the BIN chunk of `chunks` (when it has one), padded as the format
// wants (JSON with spaces, BIN with zeros).
std::string joinGlb(const std::string& json_text, const GlbChunks& chunks);

}  // namespace proxyvis::detail
