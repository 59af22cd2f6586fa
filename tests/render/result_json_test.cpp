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
  v.fill(r.spp, r.passes, r.seconds, r.cpu_seconds, r.shading_seconds, r.primary_seconds,
         r.visibility_seconds, r.rays.proxy, r.rays.original, r.rays.probe, r.primary_rays,
         r.shadow_segments, r.learned.regions, r.learned.var_exact, r.learned.costs.original[1]);
  r.proxy_class = ProxyClass(v.pick(3));
  return r;
}

CeilingMeasurement randomMeasurement(test::RandomValues& v) {
  CeilingMeasurement m;
  v.fill(m.num_lights, m.passes, m.seconds, m.ticks_per_ns, m.cpu_per_wall, m.segments);
  m.regions.resize(v.pick(5));
  for (CeilingRegionStats& r : m.regions)
    v.fill(r.light, r.segments, r.blocked, r.mh, r.hm, r.visibility_var, r.var_fv, r.f2_mh, r.f2_hm,
           r.cost_proxy, r.cost_original);
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
