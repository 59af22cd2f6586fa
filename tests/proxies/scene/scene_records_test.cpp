// The typed files of proxy-gen's scene runs (proxies/scene): a shard's manifest and a run's
// report survive JSON text and come back equal, and a wrong type or a missing key names its path.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "../pipeline/json_round_trip.h"
#include "../pipeline/random_report.h"
#include "proxies/scene/scene_outputs.h"
#include "proxies/scene/shard_manifest.h"
#include "util/error.h"

namespace proxyvis {
namespace {

using nlohmann::json;
using namespace report_test;  // RandomReports, throughText, readError

ShardManifest randomManifest(RandomReports& random) {
  ShardManifest m;
  m.shard = {random.count() % 5, 5 + random.count() % 5};
  m.scene_hash = random.text();
  m.settings = {{"kind", random.text()}, {"max_faces", random.count()}, {"cache", nullptr}};
  m.build = random.text();
  for (uint64_t i = 0, n = random.count() % 4; i < n; ++i) {
    ShardMeshEntry e;
    random.fill(e.index, e.name, e.skipped, e.cache_note, e.error);
    e.report = random.sceneMesh();
    e.code = int(random.count() % 4);
    if (random.coin()) {
      e.proxy_file = random.text();
      e.proxy_sha256 = random.text();
    }
    m.meshes.push_back(std::move(e));
  }
  return m;
}

TEST(ShardManifestJson, RandomManifestsRoundTrip) {
  RandomReports random(31);
  for (int i = 0; i < 100; ++i) {
    const ShardManifest m = randomManifest(random);
    ASSERT_EQ(throughText(m), m) << "manifest " << i << ":\n" << json(m).dump(1);
  }
}

TEST(ShardManifestJson, KeysAreTheFileFormat) {
  RandomReports random(32);
  ShardManifest m = randomManifest(random);
  m.shard = {1, 3};
  const json j = m;
  EXPECT_EQ(j["proxy_gen_shard"], 1);
  EXPECT_EQ(j["shard"], 1);
  EXPECT_EQ(j["shards"], 3);
  EXPECT_EQ(j["meshes"].size(), m.meshes.size());
}

TEST(ShardManifestJson, ABadKeyIsNamed) {
  RandomReports random(33);
  ShardManifest m = randomManifest(random);
  m.meshes.resize(1);
  m.meshes[0].report = {};
  m.meshes[0].report.skipped = "2 faces";
  const json good = m;
  json bad = good;
  bad["meshes"][0].erase("code");
  EXPECT_NE(readError<ShardManifest>(bad).find("meshes[0].code: missing"), std::string::npos)
      << readError<ShardManifest>(bad);
  bad = good;
  bad["meshes"][0]["index"] = "first";
  EXPECT_NE(readError<ShardManifest>(bad).find("meshes[0].index:"), std::string::npos)
      << readError<ShardManifest>(bad);
  bad = good;
  bad["shards"] = -1;
  EXPECT_NE(readError<ShardManifest>(bad).find("shards:"), std::string::npos);
  bad = good;
  bad["settings"] = "hull";
  EXPECT_NE(readError<ShardManifest>(bad).find("settings:"), std::string::npos);
}

TEST(SceneRunReportJson, RandomReportsRoundTrip) {
  RandomReports random(41);
  for (int i = 0; i < 100; ++i) {
    SceneRunReport r;
    r.scene = random.text();
    r.scene_out = random.text();
    if (random.coin()) r.cache = ProxyCacheTally{random.text(), random.count(), random.count()};
    for (uint64_t k = 0, n = random.count() % 4; k < n; ++k) r.meshes.push_back(random.sceneMesh());
    ASSERT_EQ(throughText(r), r) << "report " << i << ":\n" << json(r).dump(1);
  }
}

TEST(SceneRunReportJson, NoCacheIsNullAndABadKeyIsNamed) {
  SceneRunReport r;
  r.scene = "s.json";
  r.scene_out = "out/scene.json";
  json j = r;
  EXPECT_TRUE(j["cache"].is_null());
  EXPECT_TRUE(j["meshes"].is_array());
  j["cache"] = {{"dir", "c"}, {"cached", 1}};
  EXPECT_NE(readError<SceneRunReport>(j).find("cache.generated: missing"), std::string::npos)
      << readError<SceneRunReport>(j);
}

}  // namespace
}  // namespace proxyvis
