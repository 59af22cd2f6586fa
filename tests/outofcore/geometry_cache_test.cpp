// The geometry budget's parser and the cache of built originals: least recently used out, the
// budget never exceeded by the resident entries, an entry loaded alone when it is all that fits.
#include <gtest/gtest.h>

#include "mesh/primitives.h"
#include "outofcore/geometry_budget.h"
#include "outofcore/geometry_cache.h"
#include "util/error.h"

namespace proxyvis {
namespace {

TEST(GeometryBudget, ParsesBytesAndShares) {
  EXPECT_EQ(parseGeometryBudget("123456").bytes, 123456u);
  EXPECT_EQ(parseGeometryBudget("64K").bytes, 64u * 1024);
  EXPECT_EQ(parseGeometryBudget("500M").bytes, 500ull << 20);
  EXPECT_EQ(parseGeometryBudget("2G").bytes, 2ull << 30);
  EXPECT_EQ(parseGeometryBudget("2GiB").bytes, 2ull << 30);
  EXPECT_EQ(parseGeometryBudget("1.5G").bytes, 3ull << 29);
  const GeometryBudget quarter = parseGeometryBudget("25%");
  EXPECT_DOUBLE_EQ(quarter.share, 0.25);
  EXPECT_EQ(quarter.resolve(1000), 250u);
  EXPECT_EQ(parseGeometryBudget("100%").resolve(777), 777u);
  EXPECT_EQ(parseGeometryBudget("2G").resolve(1), 2ull << 30);  // bytes ignore the in-core size
}

TEST(GeometryBudget, RefusesWhatIsNotABudget) {
  for (const char* bad :
       {"", "abc", "-1G", "0", "0%", "101%", "12X", "1e3", "G", "%", "1..5M", "nan", "1e30T"}) {
    SCOPED_TRACE(bad);
    try {
      parseGeometryBudget(bad);
      FAIL() << "accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("--geometry-budget"), std::string::npos) << e.what();
    }
  }
}

// Box meshes built as scenes: every entry takes the same bytes, measured on the device.
struct BoxScenes {
  TraceDevice device;
  std::vector<uint32_t> loaded;  // the loader's calls, in order
  GeometryLoad load(uint32_t mesh) {
    loaded.push_back(mesh);
    GeometryLoad out;
    const uint64_t before = device.bytesInUse();
    TraceSceneBuilder builder(device);
    builder.addMesh(makeBoxMesh({float(mesh), 0, 0}, {float(mesh) + 1, 1, 1}), mesh);
    out.scene = builder.build();
    out.bytes = device.bytesInUse() - before;
    out.file_bytes = 100;
    return out;
  }
};

TEST(GeometryCache, EvictsTheLeastRecentlyUsedWithinTheBudget) {
  BoxScenes boxes;
  const uint64_t one = boxes.load(0).bytes;
  boxes.loaded.clear();
  ASSERT_GT(one, 0u);
  // Room for two entries, not three.
  GeometryCache cache(std::vector<uint64_t>(4, one), 2 * one + one / 2,
                      [&](uint32_t m) { return boxes.load(m); });
  for (uint32_t m : {0u, 1u, 0u, 2u, 1u, 0u, 0u}) {
    const TraceScene& s = cache.acquire(m);
    EXPECT_EQ(s.triangleCount(), 12u);
    EXPECT_LE(cache.stats().resident_bytes, cache.budgetBytes());
  }
  // 0, 1 load; 0 hits; 2 evicts 1 (0 was used since); 1 evicts 0; 0 evicts 2; 0 hits.
  EXPECT_EQ(boxes.loaded, (std::vector<uint32_t>{0, 1, 2, 1, 0}));
  EXPECT_EQ(cache.stats().loads, 5u);
  EXPECT_EQ(cache.stats().hits, 2u);
  EXPECT_EQ(cache.stats().evictions, 3u);
  EXPECT_EQ(cache.stats().bytes_read, 500u);
  EXPECT_TRUE(cache.resident(0));
  EXPECT_TRUE(cache.resident(1));
  EXPECT_FALSE(cache.resident(2));
  EXPECT_LE(cache.stats().peak_resident_bytes, cache.budgetBytes());
}

TEST(GeometryCache, AnEntryLargerThanTheBudgetIsLoadedAlone) {
  BoxScenes boxes;
  const uint64_t one = boxes.load(0).bytes;
  boxes.loaded.clear();
  GeometryCache cache(std::vector<uint64_t>(3, one), one / 2,
                      [&](uint32_t m) { return boxes.load(m); });
  cache.acquire(0);
  cache.acquire(1);
  EXPECT_FALSE(cache.resident(0));
  EXPECT_TRUE(cache.resident(1));
  EXPECT_EQ(cache.stats().evictions, 1u);
}

// A load's peak (its build scratch) is evicted for too: the resident entries and the load in
// progress fit the budget together.
TEST(GeometryCache, EvictsForALoadsPeakNotJustItsEntry) {
  BoxScenes boxes;
  const uint64_t one = boxes.load(0).bytes;
  boxes.loaded.clear();
  // Entries of `one` whose loads need twice that; room for three entries' bytes.
  GeometryCache cache(
      std::vector<uint64_t>(4, one), 3 * one, [&](uint32_t m) { return boxes.load(m); },
      std::vector<uint64_t>(4, 2 * one));
  cache.acquire(0);
  cache.acquire(1);  // 1 resident + a load of 2 fit 3
  EXPECT_EQ(cache.stats().evictions, 0u);
  cache.acquire(2);  // 2 resident + 2 do not: 0 goes, though 3 entries' bytes would fit
  EXPECT_EQ(cache.stats().evictions, 1u);
  EXPECT_FALSE(cache.resident(0));
  EXPECT_TRUE(cache.resident(1));
  EXPECT_TRUE(cache.resident(2));
  EXPECT_LE(cache.stats().peak_loading_bytes, cache.budgetBytes());
  EXPECT_EQ(cache.stats().peak_loading_bytes, 3 * one);
}

}  // namespace
}  // namespace proxyvis
