#pragma once
// Private to pv_proxy_shared: remembered answers of InputBound::touches. A bounded collapse asks
// about the same triangle again and again: CGAL re-evaluates an edge whose star did not change,
// the collapse-time filter replays the placement's tests, the relaxation retries a vertex. On the
// bunny at 300 faces half of 1.1 M questions were repeats. The answer is a function of the
// triangle's corners alone (in any order), so a repeat is answered from here, exactly.
//
// Direct-mapped and fixed in size: memory stays small however long the run, and the repeats
// come soon after the first question (the same neighbourhood), so overwriting old slots costs
// few hits.
#include <array>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "util/fnv1a.h"
#include "util/vec3.h"

namespace proxyvis::cgal {

class TouchCache {
 public:
  using Key = std::array<double, 9>;

  // The corners in lexicographic order, so that every order of one triangle is one key.
  static Key keyOf(const std::array<Vec3d, 3>& t) {
    std::array<const Vec3d*, 3> p = {&t[0], &t[1], &t[2]};
    auto less = [](const Vec3d* a, const Vec3d* b) {
      return a->x != b->x ? a->x < b->x : a->y != b->y ? a->y < b->y : a->z < b->z;
    };
    if (less(p[1], p[0])) std::swap(p[0], p[1]);
    if (less(p[2], p[1])) std::swap(p[1], p[2]);
    if (less(p[1], p[0])) std::swap(p[0], p[1]);
    return {p[0]->x, p[0]->y, p[0]->z, p[1]->x, p[1]->y, p[1]->z, p[2]->x, p[2]->y, p[2]->z};
  }

  std::optional<bool> find(const Key& key) const {
    const Slot& s = slots_[slotOf(key)];
    if (s.state == kEmpty || std::memcmp(s.key.data(), key.data(), sizeof(Key)) != 0)
      return std::nullopt;
    return s.state == kTouches;
  }

  void store(const Key& key, bool touches) {
    Slot& s = slots_[slotOf(key)];
    s.key = key;
    s.state = touches ? kTouches : kClear;
  }

 private:
  // 2^16 slots of 80 bytes: 5 MiB. Measured on the bunny at 300 faces: 2^14 slots answered 43 %
  // of the questions, 2^16 48 %, 2^20 50 % (every repeat).
  static constexpr int kSlotBits = 16;
  enum State : uint8_t { kEmpty, kClear, kTouches };
  struct Slot {
    Key key{};
    State state = kEmpty;
  };

  // FNV-1a over the coordinates' bits, folded to the slot index. +0.0 and -0.0 are different
  // keys: a miss, never a wrong answer (the memcmp decides).
  static size_t slotOf(const Key& key) {
    const uint64_t h =
        fnv1aWords(std::string_view(reinterpret_cast<const char*>(key.data()), sizeof(Key)));
    return size_t((h ^ (h >> 29) ^ (h >> 43)) & ((uint64_t(1) << kSlotBits) - 1));
  }

  std::vector<Slot> slots_ = std::vector<Slot>(size_t(1) << kSlotBits);
};

}  // namespace proxyvis::cgal
