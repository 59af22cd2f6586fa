#pragma once
// What one rank's exchange rounds carried and cost: the figures the alpha-beta model, the run's
// statistics, roulette's forward cost and the route choice read (data_parallel_render.cpp).
#include <cstdint>
#include <vector>

#include "distributed/mpi_comm.h"
#include "distributed/network_fabric.h"

namespace proxyvis {

class ExchangeLedger {
 public:
  // One exchange round that ended when this rank's compute wall time (outside MPI calls,
  // answering included) was `compute_wall`.
  void record(const MpiComm::RoundStats& round, double compute_wall);
  // A new pass round: the forward costs below price its messages.
  void startBatch() { batch_ = {}; }

  // Roulette's cost of a forward in microseconds: what `fabric` charges for the current pass
  // round's messages per forwarded segment (alpha amortised over their batch size) plus the
  // measured wall time of answering one (the remote trace, as another rank pays it). The last
  // figure again when the round sent nothing.
  double forwardCostUs(const NetworkFabric& fabric);
  // The route choice's cost of a forward in microseconds of wall time: the fabric's share as
  // above plus the CPU time of answering one over `threads`. CPU rather than wall time, as the
  // route's own cost is a few microseconds timed between two clock reads: on a host whose ranks
  // share cores, the answers' wall time counts the time slices other ranks ran and favoured the
  // proxies' route for work it did not save. forwardCostUs's last figure when nothing was sent
  // or answered yet.
  double routeForwardCostUs(const NetworkFabric& fabric, int threads) const;

  double exchangeSeconds() const { return exchange_seconds_; }
  double emulatedWaitSeconds() const { return emulated_wait_; }
  uint64_t itemsSent() const { return items_sent_; }
  uint64_t bytesSent() const { return bytes_sent_; }
  uint64_t messagesSent() const { return messages_sent_; }
  const std::vector<RoundLoad>& loads() const { return loads_; }
  double lastRoundWall() const { return last_round_wall_; }

 private:
  double networkShareSeconds(const NetworkFabric& fabric) const;

  double exchange_seconds_ = 0, emulated_wait_ = 0;
  uint64_t items_sent_ = 0, bytes_sent_ = 0, messages_sent_ = 0;
  uint64_t answered_items_ = 0;
  double answer_seconds_ = 0, answer_cpu_seconds_ = 0;
  std::vector<RoundLoad> loads_;  // per round: the model's request and answer phases
  double last_round_wall_ = 0;
  PhaseLoad batch_;  // the current pass round's messages
  double last_forward_us_ = 1;
};

}  // namespace proxyvis
