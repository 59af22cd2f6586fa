#include "distributed/route_choice.h"

#include "util/error.h"

namespace proxyvis {

const char* proxyRouteName(ProxyRoute r) {
  return r == ProxyRoute::kAlways ? "always" : "measured";
}

ProxyRoute parseProxyRoute(const std::string& name) {
  for (ProxyRoute r : {ProxyRoute::kMeasured, ProxyRoute::kAlways})
    if (name == proxyRouteName(r)) return r;
  throw Error("", "--proxy-route: unknown choice '" + name + "'", {},
              "use measured (per region, the cheaper of proxies and instance boxes) or always");
}

RouteChoice::RouteChoice(size_t regions, ProxyRoute mode)
    : mode_(mode), figures_(regions * 2), prefer_(regions, 1) {}

bool RouteChoice::useProxies(uint32_t region, uint64_t key) const {
  if (mode_ == ProxyRoute::kAlways) return true;
  // Bits above the timing sample's, so that exploring and timed segments are independent.
  const uint64_t bits = key >> 16;
  if (!learned_) return bits % 2 != 0;
  const bool explore = bits % kExploreEvery == 0;
  return (prefer_[region] != 0) != explore;
}

void RouteChoice::add(uint32_t region, bool proxies, double route_seconds, uint32_t forwards) {
  Figures& f = figures_[size_t(region) * 2 + (proxies ? 1 : 0)];
  f.routed += 1;
  f.forwards += forwards;
  if (route_seconds >= 0) {
    f.timed += 1;
    f.seconds += route_seconds;
  }
  ++routed_[proxies ? 1 : 0];
}

void RouteChoice::Figures::add(const Figures& o) {
  routed += o.routed;
  forwards += o.forwards;
  timed += o.timed;
  seconds += o.seconds;
}

// A region's cost per routed segment in microseconds, its figures pulled toward the pooled
// `prior` by kPrior segments' worth (kPrior / kTimedEvery timed ones).
double RouteChoice::costUs(const Figures& f, const Figures& prior, double forward_cost_us,
                           int threads) const {
  const double w_routed = kPrior, w_timed = kPrior / double(kTimedEvery);
  const double forwards =
      (f.forwards + w_routed * prior.forwards / prior.routed) / (f.routed + w_routed);
  const double route_us =
      1e6 * (f.seconds + w_timed * prior.seconds / prior.timed) / (f.timed + w_timed);
  return route_us / double(threads) + forwards * forward_cost_us;
}

void RouteChoice::update(double forward_cost_us, int threads) {
  if (mode_ == ProxyRoute::kAlways) return;
  Figures pooled[2];
  const size_t regions = prefer_.size();
  for (size_t g = 0; g < regions; ++g)
    for (int k = 0; k < 2; ++k) pooled[k].add(figures_[g * 2 + size_t(k)]);
  // Nothing to compare yet on this rank (no segment of one route was timed).
  if (pooled[0].timed == 0 || pooled[1].timed == 0) return;
  learned_ = true;
  threads = threads > 0 ? threads : 1;
  for (size_t g = 0; g < regions; ++g) {
    const double boxes = costUs(figures_[g * 2], pooled[0], forward_cost_us, threads);
    const double proxies = costUs(figures_[g * 2 + 1], pooled[1], forward_cost_us, threads);
    prefer_[g] = proxies <= boxes ? 1 : 0;
  }
}

}  // namespace proxyvis
