#pragma once
// proxy-gen --shard i/n: which meshes of a scene one shard generates. A mesh belongs to shard
// FNV-1a-64(its scene name, UTF-8 bytes) mod n, so the split depends neither on the order of the
// meshes nor on the program's build, and anyone can predict it (docs/proxy_gen_shards.md).
#include <cstdint>
#include <optional>
#include <string>

namespace proxyvis {

inline constexpr uint64_t kMaxShards = 1'000'000;

struct ShardSpec {
  uint64_t index = 0;  // i, in [0, count)
  uint64_t count = 1;  // n, in [1, kMaxShards]
  bool operator==(const ShardSpec&) const = default;
};

// "i/n" written with decimal digits only (no sign, space or exponent), 0 <= i < n <= kMaxShards;
// nullopt for anything else.
std::optional<ShardSpec> parseShardSpec(const std::string& text);

// The shard (0..count-1) of the mesh named `name`.
uint64_t shardOfMesh(const std::string& name, uint64_t count);

}  // namespace proxyvis
