#pragma once
// FNV-1a 64 (Fowler, Noll, Vo): tiny, dependency-free, and good enough for cache keys (scene
// hashes, cached references). Not for security: use util/sha256.h for file identity.
#include <cstdint>
#include <cstring>
#include <string_view>

namespace proxyvis {

// Incremental: add() the parts in order; `h` is the hash of their concatenation.
inline constexpr uint64_t kFnv1aPrime = 0x100000001b3ULL;

struct Fnv1a {
  uint64_t h = 0xcbf29ce484222325ULL;
  void add(std::string_view bytes) {
    for (unsigned char c : bytes) {
      h ^= c;
      h *= kFnv1aPrime;
    }
  }
};

inline uint64_t fnv1a(std::string_view bytes) {
  Fnv1a f;
  f.add(bytes);
  return f.h;
}

// FNV-1a over 8-byte little-endian words, then the last bytes one by one: a checksum of large
// files (plan unit results) eight times faster than byte by byte; not equal to fnv1a().
inline uint64_t fnv1aWords(std::string_view bytes) {
  uint64_t h = Fnv1a{}.h;
  size_t i = 0;
  for (; i + 8 <= bytes.size(); i += 8) {
    uint64_t word = 0;
    std::memcpy(&word, bytes.data() + i, 8);
    h = (h ^ word) * kFnv1aPrime;
  }
  for (; i < bytes.size(); ++i) h = (h ^ uint8_t(bytes[i])) * kFnv1aPrime;
  return h;
}

}  // namespace proxyvis
