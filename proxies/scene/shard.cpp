#include "proxies/scene/shard.h"

#include "util/fnv1a.h"

namespace proxyvis {

namespace {

// A decimal integer of at most 7 digits (kMaxShards has 7), digits only.
std::optional<uint64_t> parseCount(const std::string& text) {
  if (text.empty() || text.size() > 7) return std::nullopt;
  uint64_t v = 0;
  for (char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    v = v * 10 + uint64_t(c - '0');
  }
  return v;
}

}  // namespace

std::optional<ShardSpec> parseShardSpec(const std::string& text) {
  const size_t slash = text.find('/');
  if (slash == std::string::npos) return std::nullopt;
  const std::optional<uint64_t> i = parseCount(text.substr(0, slash));
  const std::optional<uint64_t> n = parseCount(text.substr(slash + 1));
  if (!i || !n || *n < 1 || *n > kMaxShards || *i >= *n) return std::nullopt;
  return ShardSpec{*i, *n};
}

uint64_t shardOfMesh(const std::string& name, uint64_t count) {
  return fnv1a(name) % count;
}

}  // namespace proxyvis
