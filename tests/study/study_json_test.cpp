// study/scene_facts.h, study/ceiling_phase.h, study/unit.h: what a unit result's header holds,
// read back exactly, every key required.
#include <gtest/gtest.h>

#include "study/ceiling_phase.h"
#include "study/scene_facts.h"
#include "study/unit.h"
#include "tests/support/json_round_trip.h"

namespace proxyvis {
namespace {

ProxyClassRecord randomRecord(test::RandomValues& v) {
  return {v.text(), v.text(), v.text(), v.text(), v.text(), v.text()};
}

SceneFacts randomFacts(test::RandomValues& v) {
  SceneFacts f;
  f.proxy_class = ProxyClass(v.pick(3));
  f.uses_proxies = v.flag();
  f.instances_flattened = v.flag();
  f.build = v.text();
  f.build_reason = v.text();
  f.build_description = v.text();
  f.original_triangles = v.u64();
  f.proxy_triangles = v.u64();
  f.warnings = v.texts();
  for (uint64_t i = 0, n = v.pick(3); i < n; ++i) f.proxy_classes.push_back(randomRecord(v));
  f.trust_notes = v.texts();
  return f;
}

CeilingUnitMeasurement randomCeiling(test::RandomValues& v) {
  CeilingUnitMeasurement c;
  c.seconds = v.number();
  c.pixels = v.number();
  c.measurement.num_lights = v.u32();
  c.measurement.passes = v.smallInt();
  c.measurement.segments = v.u64();
  c.measurement.regions.resize(v.pick(3));
  for (CeilingRegionStats& r : c.measurement.regions) {
    r.light = v.u32();
    r.f2_hm = v.number();
    r.cost_original[1] = v.number();
  }
  return c;
}

UnitResult randomResult(test::RandomValues& v) {
  UnitResult r;
  r.facts = randomFacts(v);
  r.renders.resize(v.pick(4));
  for (RenderResult& render : r.renders) {
    render.spp = v.smallInt();
    render.seconds = v.number();
    render.rays.probe = v.u64();
    render.learned.p_proxy_blocked = v.number();
  }
  if (v.flag()) r.ceiling = randomCeiling(v);
  return r;
}

TEST(StudyJson, RandomProxyClassRecordsRoundTrip) {
  test::expectRoundTrips<ProxyClassRecord>(randomRecord);
}

TEST(StudyJson, RandomSceneFactsRoundTrip) {
  test::expectRoundTrips<SceneFacts>(randomFacts);
}

TEST(StudyJson, RandomCeilingMeasurementsRoundTrip) {
  test::expectRoundTrips<CeilingUnitMeasurement>(randomCeiling);
}

TEST(StudyJson, RandomUnitResultsRoundTrip) {
  test::expectRoundTrips<UnitResult>(randomResult);
}

TEST(StudyJson, EveryKeyIsRequiredAndTyped) {
  test::RandomValues v(17);
  test::expectEveryKeyChecked(randomRecord(v));
  test::expectEveryKeyChecked(randomFacts(v));
  test::expectEveryKeyChecked(randomCeiling(v));
  UnitResult r = randomResult(v);
  r.ceiling = randomCeiling(v);
  test::expectEveryKeyChecked(r, {"ceiling"});
}

TEST(StudyJson, AProxyClassRecordKeepsTheReportsKeys) {
  const nlohmann::json j = ProxyClassRecord{"m", "p.ply", "none", "outside", "verified", "ok"};
  EXPECT_EQ(j.dump(), R"({"claimed":"none","class":"outside","class_status":"verified","mesh":"m",)"
                      R"("proxy":"p.ply","reason":"ok"})");
}

}  // namespace
}  // namespace proxyvis
