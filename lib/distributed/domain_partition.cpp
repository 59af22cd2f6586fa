#include "distributed/domain_partition.h"

#include <algorithm>
#include <numeric>

#include "util/error.h"

namespace proxyvis {

namespace {

void bisect(const std::vector<PartitionItem>& items, std::vector<uint32_t>& ids, size_t begin,
            size_t end, int first_rank, int ranks, std::vector<int>& owner) {
  if (ranks == 1 || end - begin <= 1) {
    for (size_t i = begin; i < end; ++i) owner[ids[i]] = first_rank;
    return;
  }
  Bounds3f centres;
  double total = 0;
  for (size_t i = begin; i < end; ++i) {
    centres.extend(items[ids[i]].bounds.center());
    total += items[ids[i]].weight;
  }
  const Vec3f e = centres.extent();
  const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
  std::sort(ids.begin() + long(begin), ids.begin() + long(end), [&](uint32_t a, uint32_t b) {
    const float ca = items[a].bounds.center()[axis], cb = items[b].bounds.center()[axis];
    return ca != cb ? ca < cb : a < b;
  });
  const int left_ranks = ranks / 2;
  const double target = total * double(left_ranks) / double(ranks);
  // The split whose left weight is closest to the target, each side keeping one item at least.
  size_t split = begin + 1;
  double left = items[ids[begin]].weight, best = std::abs(left - target);
  double running = left;
  for (size_t i = begin + 1; i + 1 < end; ++i) {
    running += items[ids[i]].weight;
    const double d = std::abs(running - target);
    if (d < best) {
      best = d;
      split = i + 1;
    }
  }
  bisect(items, ids, begin, split, first_rank, left_ranks, owner);
  bisect(items, ids, split, end, first_rank + left_ranks, ranks - left_ranks, owner);
}

}  // namespace

std::vector<int> partitionByDomains(const std::vector<PartitionItem>& items, int ranks) {
  PV_CHECK_MSG(ranks >= 1, "partitionByDomains: ranks must be >= 1");
  std::vector<int> owner(items.size(), 0);
  std::vector<uint32_t> ids(items.size());
  std::iota(ids.begin(), ids.end(), 0u);
  bisect(items, ids, 0, ids.size(), 0, ranks, owner);
  return owner;
}

}  // namespace proxyvis
