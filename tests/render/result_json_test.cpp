// RenderResult's numbers and CeilingMeasurement as JSON (render/renderer.h,
// render/ceiling_stats.h): what a unit result stores, read back exactly.
#include <gtest/gtest.h>

#include "render/ceiling_stats.h"
#include "render/renderer.h"
#include "tests/support/json_round_trip.h"

namespace proxyvis {
namespace {

// The numbers of a render; images stay empty (the unit file holds them, not the JSON).
RenderResult randomRender(test::RandomValues& v) {
  RenderResult r;
  r.spp = v.smallInt();
  r.passes = v.smallInt();
  r.seconds = v.number();
  r.cpu_seconds = v.number();
  r.shading_seconds = v.number();
  r.primary_seconds = v.number();
  r.visibility_seconds = v.number();
  r.rays = {v.u64(), v.u64(), v.u64()};
  r.primary_rays = v.u64();
  r.shadow_segments = v.u64();
  r.proxy_class = ProxyClass(v.pick(3));
  r.learned.regions = v.u32();
  r.learned.var_exact = v.number();
  r.learned.costs.original[1] = v.number();
  return r;
}

CeilingMeasurement randomMeasurement(test::RandomValues& v) {
  CeilingMeasurement m;
  m.num_lights = v.u32();
  m.passes = v.smallInt();
  m.seconds = v.number();
  m.ticks_per_ns = v.number();
  m.cpu_per_wall = v.number();
  m.segments = v.u64();
  for (uint64_t i = 0, n = v.pick(5); i < n; ++i) {
    CeilingRegionStats r;
    r.light = v.u32();
    r.segments = v.number();
    r.blocked = v.number();
    r.mh = v.number();
    r.hm = v.number();
    r.visibility_var = v.number();
    r.var_fv = v.number();
    r.f2_mh = v.number();
    r.f2_hm = v.number();
    for (int c = 0; c < 2; ++c) {
      r.cost_proxy[c] = v.number();
      r.cost_original[c] = v.number();
    }
    m.regions.push_back(r);
  }
  return m;
}

PROXYVIS_JSON_PROPERTY_TESTS(RenderResultJson, RenderResult, randomRender, 3)

TEST(RenderResultJson, ImagesAreNotWritten) {
  RenderResult r;
  r.radiance = Image{1, 1, 3, {1, 2, 3}};
  const RenderResult back = JsonField(nlohmann::json(r)).get<RenderResult>();
  EXPECT_TRUE(back.radiance.pixels.empty());
}

TEST(RenderResultJson, AnUnknownProxyClassIsNamed) {
  nlohmann::json j = RenderResult{};
  j["proxy_class"] = "outsideish";
  EXPECT_EQ(test::errorPath<RenderResult>(j), "proxy_class");
}

TEST(CeilingMeasurementJson, RandomValuesRoundTrip) {
  test::expectRoundTrips<CeilingMeasurement>(randomMeasurement);
}

TEST(CeilingMeasurementJson, EveryKeyIsRequiredAndTyped) {
  test::RandomValues v(5);
  CeilingMeasurement m = randomMeasurement(v);
  m.regions.resize(2);
  test::expectEveryKeyChecked(m);
}

TEST(CeilingMeasurementJson, ARegionIsThirteenNumbers) {
  CeilingMeasurement m;
  m.regions.resize(2);
  nlohmann::json j = m;
  ASSERT_EQ(j.at("regions").at(1).size(), 13u);
  j["regions"][1].erase(12);
  EXPECT_EQ(test::errorPath<CeilingMeasurement>(j), "regions[1]");
}

}  // namespace
}  // namespace proxyvis
