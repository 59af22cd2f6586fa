#pragma once
// Union-find with path halving over dense ids 0..n-1 (mesh components, welded vertices).
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace proxyvis {

struct DisjointSets {
  std::vector<uint32_t> parent;
  explicit DisjointSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  uint32_t find(uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  // The smaller root stays the root: a set's representative is its smallest id.
  void unite(uint32_t a, uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace proxyvis
