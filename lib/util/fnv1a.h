#pragma once
// FNV-1a 64 (Fowler, Noll, Vo): tiny, dependency-free, and good enough for cache keys (scene
// hashes, cached references). Not for security: use util/sha256.h for file identity.
#include <cstdint>
#include <string_view>

namespace proxyvis {

// Incremental: add() the parts in order; `h` is the hash of their concatenation.
struct Fnv1a {
  uint64_t h = 0xcbf29ce484222325ULL;
  void add(std::string_view bytes) {
    for (unsigned char c : bytes) {
      h ^= c;
      h *= 0x100000001b3ULL;
    }
  }
};

inline uint64_t fnv1a(std::string_view bytes) {
  Fnv1a f;
  f.add(bytes);
  return f.h;
}

}  // namespace proxyvis
