// partitionByDomains: balanced by weight, spatially coherent, deterministic, any rank count.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "distributed/domain_partition.h"
#include "util/rng.h"

namespace proxyvis {
namespace {

std::vector<PartitionItem> grid(int side, uint64_t seed) {
  std::vector<PartitionItem> items;
  Rng rng(seed, 0);
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      PartitionItem it;
      const Vec3f c(float(i) * 2.0f, 0.0f, float(j) * 2.0f);
      it.bounds.extend(c - Vec3f(0.5f, 0.0f, 0.5f));
      it.bounds.extend(c + Vec3f(0.5f, 1.0f, 0.5f));
      it.weight = 1.0 + 9.0 * rng.uniformDouble();
      items.push_back(it);
    }
  return items;
}

TEST(DomainPartition, EveryRankGetsAShareCloseToTheMean) {
  const auto items = grid(20, 3);
  const double total =
      std::accumulate(items.begin(), items.end(), 0.0,
                      [](double s, const PartitionItem& i) { return s + i.weight; });
  const double largest = 10.0;
  for (int ranks : {1, 2, 3, 4, 7, 16}) {
    const std::vector<int> owner = partitionByDomains(items, ranks);
    std::vector<double> share(size_t(ranks), 0.0);
    for (size_t i = 0; i < items.size(); ++i) {
      ASSERT_GE(owner[i], 0);
      ASSERT_LT(owner[i], ranks);
      share[size_t(owner[i])] += items[i].weight;
    }
    // Each bisection level can be off by at most one item's weight per side.
    const int levels = int(std::ceil(std::log2(double(ranks)))) + 1;
    for (int r = 0; r < ranks; ++r)
      EXPECT_NEAR(share[size_t(r)], total / ranks, levels * largest)
          << "rank " << r << " of " << ranks;
  }
}

TEST(DomainPartition, DomainsAreSpatiallyCompact) {
  // Four domains of a 20 x 20 grid: each is a block, so the sum of the domains' box areas
  // stays close to the grid's (interleaved owners would give four boxes of the whole grid).
  const auto items = grid(20, 5);
  const std::vector<int> owner = partitionByDomains(items, 4);
  std::vector<Bounds3f> boxes(4);
  for (size_t i = 0; i < items.size(); ++i) boxes[size_t(owner[i])].extend(items[i].bounds);
  double area = 0;
  for (const Bounds3f& b : boxes) area += double(b.extent().x) * b.extent().z;
  const double grid_area = 39.0 * 39.0;
  EXPECT_LT(area, 1.25 * grid_area);
}

TEST(DomainPartition, DeterministicAndIndependentOfTies) {
  std::vector<PartitionItem> items(10);
  for (auto& it : items) it.bounds.extend(Vec3f(1, 1, 1));  // every centre equal
  const auto a = partitionByDomains(items, 3), b = partitionByDomains(items, 3);
  EXPECT_EQ(a, b);
  EXPECT_EQ(std::count(a.begin(), a.end(), 0) + std::count(a.begin(), a.end(), 1) +
                std::count(a.begin(), a.end(), 2),
            10);
}

TEST(DomainPartition, FewerItemsThanRanks) {
  const auto items = grid(1, 1);
  const std::vector<int> owner = partitionByDomains(items, 4);
  ASSERT_EQ(owner.size(), 1u);
  EXPECT_GE(owner[0], 0);
  EXPECT_TRUE(partitionByDomains({}, 4).empty());
}

}  // namespace
}  // namespace proxyvis
