// RouteChoice: the shares it sends each way before and after learning, and its per-region
// choice against costs written out by hand.
#include <gtest/gtest.h>

#include "distributed/route_choice.h"
#include "util/error.h"
#include "util/rng.h"

namespace proxyvis {
namespace {

// The share of 16,000 hashed keys that `choice` sends through the proxies in `region`.
double proxiesShare(const RouteChoice& choice, uint32_t region) {
  int n = 0;
  for (uint64_t i = 0; i < 16000; ++i) n += choice.useProxies(region, hashKeys(i, 3, 8));
  return n / 16000.0;
}

// `count` segments of one route in `region`, each timed at `route_us` with `forwards` forwards.
void feed(RouteChoice& c, uint32_t region, bool proxies, int count, double route_us,
          uint32_t forwards) {
  for (int i = 0; i < count; ++i) c.add(region, proxies, route_us * 1e-6, forwards);
}

TEST(RouteChoice, AlwaysRoutesThroughTheProxies) {
  RouteChoice c(2, ProxyRoute::kAlways);
  feed(c, 0, false, 100, 0.1, 0);
  feed(c, 0, true, 100, 50, 3);
  c.update(0.01, 1);
  EXPECT_EQ(proxiesShare(c, 0), 1.0);
}

TEST(RouteChoice, SplitsEvenlyBeforeLearning) {
  RouteChoice c(1, ProxyRoute::kMeasured);
  EXPECT_NEAR(proxiesShare(c, 0), 0.5, 0.02);
  // One route timed is not yet a comparison.
  feed(c, 0, true, 100, 1, 0);
  c.update(1, 1);
  EXPECT_NEAR(proxiesShare(c, 0), 0.5, 0.02);
}

TEST(RouteChoice, PicksTheCheaperRoutePerRegion) {
  RouteChoice c(2, ProxyRoute::kMeasured);
  // Region 0: proxies 2 us and 0.1 forwards per segment; boxes 0.5 us and 1 forward.
  // Region 1: proxies 0.8 us and 0 forwards; boxes 0.5 us and 1 forward.
  for (int i = 0; i < 1000; ++i) {
    c.add(0, true, 2e-6, i % 10 == 0 ? 1 : 0);
    c.add(0, false, 0.5e-6, 1);
    c.add(1, true, 0.8e-6, 0);
    c.add(1, false, 0.5e-6, 1);
  }
  // Forward 0.6 us, 1 thread. Region 0: proxies 2 + 0.06 > boxes 0.5 + 0.6: boxes, but for the
  // explored sixteenth. Region 1: proxies 0.8 < 1.1: proxies.
  c.update(0.6, 1);
  EXPECT_NEAR(proxiesShare(c, 0), 1.0 / 16, 0.01);
  EXPECT_NEAR(proxiesShare(c, 1), 15.0 / 16, 0.01);
  // At 4 threads the route's share of the wall time is a quarter: region 0's proxies
  // 0.5 + 0.06 < 0.125 + 0.6.
  c.update(0.6, 4);
  EXPECT_NEAR(proxiesShare(c, 0), 15.0 / 16, 0.01);
  // A dear forward (20 us) favours the proxies everywhere.
  c.update(20, 1);
  EXPECT_NEAR(proxiesShare(c, 0), 15.0 / 16, 0.01);
  EXPECT_EQ(c.routedByProxies(), 2000u);
  EXPECT_EQ(c.routedByBoxes(), 2000u);
}

TEST(RouteChoice, AFewSegmentsOfARegionLeanOnThePooledFigures) {
  RouteChoice c(2, ProxyRoute::kMeasured);
  // Region 0 has plenty: proxies clearly dearer (5 us, 1 forward) than boxes (0.5 us, 1 forward).
  feed(c, 0, true, 1000, 5, 1);
  feed(c, 0, false, 1000, 0.5, 1);
  // Region 1 has two segments saying the opposite; the pooled figures outweigh them.
  feed(c, 1, true, 1, 0.1, 0);
  feed(c, 1, false, 1, 5, 2);
  c.update(1, 1);
  EXPECT_NEAR(proxiesShare(c, 1), 1.0 / 16, 0.01);
}

TEST(RouteChoice, NamesAndErrors) {
  EXPECT_EQ(parseProxyRoute("measured"), ProxyRoute::kMeasured);
  EXPECT_EQ(parseProxyRoute("always"), ProxyRoute::kAlways);
  EXPECT_THROW(parseProxyRoute("sometimes"), Error);
  EXPECT_STREQ(proxyRouteName(ProxyRoute::kAlways), "always");
}

}  // namespace
}  // namespace proxyvis
