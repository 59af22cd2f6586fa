#pragma once
// Which route a shadow segment takes under --forwarding proxies (docs/data_parallel.md, "Where
// the proxies pay"). Two routes give the same exact answer:
//   - through the proxies (distributed_scene.h): the remote instance boxes the segment enters,
//     then those objects' inside and outside proxies; more local work, fewer forwards;
//   - through the instance boxes alone: every remote rank whose box the segment enters is
//     asked; little local work, more forwards.
// Which is cheaper depends on the scene and the fabric: a fine porous proxy costs more to trace
// than the forward it saves on a fast fabric, and less on a slow one. Per region (screen tile x
// light) the cost of a routed segment is measured for each route from earlier rounds only:
//     cost = route seconds / threads + forwards x (forward cost: network share + remote trace),
// with the route timed on a sample of the segments (one in kTimedEvery) and the forwards counted
// on all. The cheaper route takes the region's segments, except a share (one in kExploreEvery,
// chosen by a hash of pixel and pass) that takes the other, so that both figures stay current.
// A region's figures are pulled toward the rank's pooled ones (kPrior segments' worth) while
// they are few. Before anything is measured (the first round), each route takes half.
// Exact images do not depend on the choice (an answer is the same whichever ranks are asked);
// under roulette the choice changes which segments are undecided, never the estimate's mean.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace proxyvis {

enum class ProxyRoute {
  kMeasured,  // per region, the cheaper of proxies and instance boxes (measured)
  kAlways     // every segment through the proxies
};
const char* proxyRouteName(ProxyRoute r);  // "measured", "always"
// Throws Error naming --proxy-route for anything else.
ProxyRoute parseProxyRoute(const std::string& name);

class RouteChoice {
 public:
  static constexpr uint64_t kTimedEvery = 8;
  static constexpr uint64_t kExploreEvery = 16;
  static constexpr double kPrior = 64;

  RouteChoice(size_t regions, ProxyRoute mode);

  // True if the segment keyed `key` (a hash of pixel and pass) of `region` goes through the
  // proxies in this round.
  bool useProxies(uint32_t region, uint64_t key) const;
  // True if that segment's route is to be timed.
  static bool timed(uint64_t key) { return key % kTimedEvery == 0; }

  // One routed segment: which route, its route seconds (< 0: not timed), the forwards it took.
  void add(uint32_t region, bool proxies, double route_seconds, uint32_t forwards);
  // After a round: the forward cost in microseconds of wall time (network share + remote trace
  // CPU time / threads) and
  // the threads the route ran on; recomputes every region's choice.
  void update(double forward_cost_us, int threads);

  // For reports: segments routed each way so far.
  uint64_t routedByProxies() const { return routed_[1]; }
  uint64_t routedByBoxes() const { return routed_[0]; }

 private:
  struct Figures {
    double routed = 0, forwards = 0, timed = 0, seconds = 0;
    void add(const Figures& o);
  };
  double costUs(const Figures& f, const Figures& prior, double forward_cost_us, int threads) const;

  ProxyRoute mode_;
  std::vector<Figures> figures_;  // [region * 2 + proxies]
  std::vector<uint8_t> prefer_;   // per region: 1 proxies, 0 boxes
  bool learned_ = false;
  uint64_t routed_[2] = {0, 0};
};

}  // namespace proxyvis
