// proxy-gen's proxy cache: keys change with every setting that changes a proxy, entries round
// trip, and a damaged entry (truncated or changed proxy file, garbage or foreign report, missing
// files) is a miss with a reason, never a hit and never a crash.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "json_round_trip.h"
#include "proxies/pipeline/proxy_cache.h"
#include "random_report.h"
#include "util/error.h"
#include "util/program_build_id.h"
#include "util/sha256.h"

namespace fs = std::filesystem;

namespace proxyvis {
namespace {

const std::string kInputHash(64, 'a');

class ProxyCacheTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("proxyvis_cache_test_" +
            std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static CachedProxy sampleEntry() {
    CachedProxy e;
    ProxyReport r;  // every key present; values of no importance here
    r.method = "hull";
    r.faces = 12;
    r.written_class = ProxyClass::kOutside;
    e.report.proxy = r;
    e.proxy_bytes = std::string("ply\nformat binary_little_endian 1.0\n\0\1\2\3", 40);
    return e;
  }
  static void overwrite(const fs::path& p, const std::string& bytes) {
    std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
  }
  fs::path dir_;
};

TEST(ProxyCacheKey, EverySettingThatChangesTheProxyChangesTheKey) {
  const ProxyGenOptions base;
  std::vector<ProxyGenOptions> variants(12, base);
  variants[1].kind = ProxyClass::kInside;
  variants[2].method = "hull";
  variants[3].alpha = 0.05;
  variants[4].offset = 0.01;
  variants[5].ratio = 0.1;
  variants[6].max_faces = 100;
  variants[7].erosion = 0.02;
  variants[8].voxel = 0.01;
  variants[9].fill_holes = true;
  variants[10].hard_budget = false;
  variants[11].seed = 7;
  std::set<std::string> keys;
  for (const ProxyGenOptions& o : variants)
    keys.insert(proxyCacheKey(kInputHash, proxyCacheSettings(o)));
  EXPECT_EQ(keys.size(), variants.size());
  // Another input, same settings: another key.
  EXPECT_FALSE(keys.contains(proxyCacheKey(std::string(64, 'b'), proxyCacheSettings(base))));
  // The time budget does not change a proxy that was made: same key.
  ProxyGenOptions slower = base;
  slower.max_seconds = 5;
  EXPECT_EQ(proxyCacheKey(kInputHash, proxyCacheSettings(slower)),
            proxyCacheKey(kInputHash, proxyCacheSettings(base)));
  // 64 lowercase hex digits, the same on every call.
  const std::string k = proxyCacheKey(kInputHash, proxyCacheSettings(base));
  EXPECT_EQ(k.size(), 64u);
  EXPECT_EQ(k.find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_EQ(k, proxyCacheKey(kInputHash, proxyCacheSettings(base)));
}

TEST(ProxyCacheKey, NearbyNumbersDoNotShareAKey) {
  ProxyGenOptions a, b;
  a.alpha = 0.1;
  b.alpha = 0.1 + 1e-15;
  EXPECT_NE(proxyCacheKey(kInputHash, proxyCacheSettings(a)),
            proxyCacheKey(kInputHash, proxyCacheSettings(b)));
}

TEST(ProxyCacheKey, BuildIdIsStable) {
  const std::string& id = programBuildId();
  EXPECT_FALSE(id.empty());
  EXPECT_EQ(&id, &programBuildId());
}

TEST_F(ProxyCacheTest, StoredEntryIsFoundWithItsBytes) {
  const ProxyCache cache(dir_);
  EXPECT_TRUE(fs::is_directory(dir_));
  std::string why;
  EXPECT_FALSE(cache.find("k1", &why));
  EXPECT_EQ(why, "");  // absent is not damaged
  const CachedProxy e = sampleEntry();
  cache.store("k1", e);
  const std::optional<CachedProxy> got = cache.find("k1", &why);
  ASSERT_TRUE(got) << why;
  EXPECT_EQ(got->proxy_bytes, e.proxy_bytes);
  EXPECT_EQ(got->report, e.report);
  // Nothing but the two files of the entry (no temporaries left).
  std::set<std::string> names;
  for (const auto& f : fs::directory_iterator(dir_)) names.insert(f.path().filename().string());
  EXPECT_EQ(names, (std::set<std::string>{"k1.json", "k1.ply"}));
}

TEST_F(ProxyCacheTest, SkippedEntryHasNoProxyFile) {
  const ProxyCache cache(dir_);
  CachedProxy e;
  e.report.skipped = "not cheaper";
  e.report.faces = 3;
  cache.store("k2", e);
  EXPECT_FALSE(fs::exists(dir_ / "k2.ply"));
  const std::optional<CachedProxy> got = cache.find("k2");
  ASSERT_TRUE(got);
  EXPECT_EQ(got->report.skipped.value_or(""), "not cheaper");
  EXPECT_EQ(got->report.faces, 3u);
}

TEST_F(ProxyCacheTest, TruncatedProxyFileIsAMiss) {
  const ProxyCache cache(dir_);
  const CachedProxy e = sampleEntry();
  cache.store("k", e);
  overwrite(dir_ / "k.ply", e.proxy_bytes.substr(0, 10));
  std::string why;
  EXPECT_FALSE(cache.find("k", &why));
  EXPECT_NE(why.find("SHA-256"), std::string::npos) << why;
  // Stored again, it is good again.
  cache.store("k", e);
  EXPECT_TRUE(cache.find("k"));
}

TEST_F(ProxyCacheTest, ChangedProxyByteIsAMiss) {
  const ProxyCache cache(dir_);
  CachedProxy e = sampleEntry();
  cache.store("k", e);
  e.proxy_bytes[5] ^= 1;
  overwrite(dir_ / "k.ply", e.proxy_bytes);
  EXPECT_FALSE(cache.find("k"));
}

TEST_F(ProxyCacheTest, DamagedReportsAreMisses) {
  const ProxyCache cache(dir_);
  const CachedProxy e = sampleEntry();
  cache.store("k", e);
  const fs::path meta = dir_ / "k.json";
  std::ifstream in(meta);
  const std::string good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  for (const std::string& bad :
       {std::string(), good.substr(0, good.size() / 2), std::string("[1, 2]"),
        std::string("{\"format\": 1, \"key\": \"other\", \"report\": {}}"),
        std::string("{\"format\": 99, \"key\": \"k\", \"report\": {}}"),
        std::string("{\"format\": 1, \"key\": \"k\", \"report\": {\"faces\": 1}}"),
        std::string("{\"format\": 1, \"key\": \"k\", \"report\": 5, \"proxy_sha256\": 3}"),
        std::string("\xff\xfe\x00garbage", 10)}) {
    overwrite(meta, bad);
    std::string why;
    EXPECT_FALSE(cache.find("k", &why)) << bad;
    EXPECT_FALSE(why.empty()) << bad;
  }
  // A missing proxy file.
  overwrite(meta, good);
  ASSERT_TRUE(cache.find("k"));
  fs::remove(dir_ / "k.ply");
  std::string why;
  EXPECT_FALSE(cache.find("k", &why));
  EXPECT_NE(why.find("missing"), std::string::npos) << why;
  // A folder where the proxy file should be.
  fs::create_directory(dir_ / "k.ply");
  EXPECT_FALSE(cache.find("k"));
}

// An entry's record: random records survive JSON text; each key, missing or of the wrong type,
// is an error naming it.
TEST(ProxyCacheRecordJson, RandomRecordsRoundTrip) {
  report_test::RandomReports random(20261206);
  for (int i = 0; i < 300; ++i) {
    const ProxyCacheRecord r{int(random.count() % 100000), random.text(), random.sceneMesh(),
                             random.maybe<std::string>([&] { return random.text(); })};
    ASSERT_EQ(report_test::throughText(r), r) << nlohmann::json(r).dump(1);
  }
}

TEST(ProxyCacheRecordJson, AMissingOrMistypedKeyIsNamed) {
  SceneMeshReport skipped;
  skipped.skipped = "no faces";
  skipped.faces = 0;
  const ProxyCacheRecord r{1, "k", skipped, "ab"};
  const nlohmann::json good = r;
  for (const char* key : {"format", "key", "report", "proxy_sha256"}) {
    nlohmann::json missing = good, mistyped = good;
    missing.erase(key);
    mistyped[key] = nlohmann::json::array();
    if (std::string(key) != "proxy_sha256") {  // optional: absent is a record without a proxy
      EXPECT_NE(report_test::readError<ProxyCacheRecord>(missing).find(key), std::string::npos)
          << key;
    }
    EXPECT_NE(report_test::readError<ProxyCacheRecord>(mistyped).find(key), std::string::npos)
        << key;
  }
}

TEST_F(ProxyCacheTest, AFileAsTheFolderIsAWriteError) {
  overwrite(dir_.string() + ".file", "x");
  try {
    const ProxyCache cache(dir_.string() + ".file");
    ADD_FAILURE() << "no error";
  } catch (const WriteError& e) {
    EXPECT_NE(std::string(e.what()).find(".file"), std::string::npos) << e.what();
  }
  fs::remove(dir_.string() + ".file");
}

TEST(ProxyCacheDir, FollowsXdgThenHome) {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  const char* home = std::getenv("HOME");
  const std::string saved_xdg = xdg ? xdg : "", saved_home = home ? home : "";
  setenv("XDG_CACHE_HOME", "/x/cache", 1);
  EXPECT_EQ(defaultProxyCacheDir(), fs::path("/x/cache/proxyvis/proxies"));
  setenv("XDG_CACHE_HOME", "relative/cache", 1);  // not absolute: ignored, as XDG says
  setenv("HOME", "/home/u", 1);
  EXPECT_EQ(defaultProxyCacheDir(), fs::path("/home/u/.cache/proxyvis/proxies"));
  unsetenv("XDG_CACHE_HOME");
  unsetenv("HOME");
  EXPECT_EQ(defaultProxyCacheDir(), fs::path());
  if (xdg) setenv("XDG_CACHE_HOME", saved_xdg.c_str(), 1);
  if (home) setenv("HOME", saved_home.c_str(), 1);
}

}  // namespace
}  // namespace proxyvis
