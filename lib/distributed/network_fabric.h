#pragma once
// What a network costs, as an alpha-beta model (docs/data_parallel.md, "What a network costs"):
// a message of b bytes costs alpha + b / beta on its sender's link, a rank's messages go one
// after another, and a collective of P ranks costs ceil(log2 P) alpha (a tree or Bruck exchange
// of small messages). The renderer batches its forwards (one message per rank pair and round),
// so a forward costs 2 alpha / n + 33 B / beta at n segments per message: fractions of a
// microsecond on a cluster interconnect. The presets are published MPI figures (ping-pong
// latency and streaming bandwidth); `shm` is this machine's shared memory, measured by a
// ping-pong at the start of the run. `unbatched-20us` is the flat cost of one blocking round trip
// per forward over TCP: an upper bound for a design that does not batch, never a headline.
#include <cstdint>
#include <string>
#include <vector>

namespace proxyvis {

struct NetworkFabric {
  std::string name = "shm";  // a preset's name, or "custom"
  double alpha_us = 0;       // per message, microseconds
  double beta_gbps = 0;      // bytes per nanosecond (GB/s); 0: unlimited
  double per_item_us = 0;    // per forwarded segment (unbatched-20us only)
  bool measured = false;     // shm: alpha and beta measured on this run
  bool upper_bound = false;  // unbatched-20us: labelled as the bound it is

  // A message of `bytes` bytes holding `items` forwarded segments, in seconds.
  double messageSeconds(uint64_t bytes, uint64_t items) const;
  // `messages` messages of `bytes` bytes in all, sent one after another, in seconds.
  double sendSeconds(uint64_t messages, uint64_t bytes, uint64_t items) const;
  // A collective of small messages over `ranks` ranks: ceil(log2 ranks) alpha, in seconds.
  double collectiveSeconds(int ranks) const;
  // A reduction of `bytes` bytes over `ranks` ranks (a tree: ceil(log2 ranks) steps of a message
  // of that size), in seconds.
  double reductionSeconds(int ranks, uint64_t bytes) const;
  // One line for reports: "ib-hdr (alpha 1.6 us, beta 23 GB/s)".
  std::string describe() const;
};

// The preset names, in the order --help lists them.
const std::vector<std::string>& networkPresetNames();

// The fabric --network NAME --network-alpha-us A --network-beta-gbps B asks for (A or B < 0: not
// given; either one given makes a "custom" fabric from the preset's other figure). Throws Error
// (exit 2) for an unknown name or a negative, non-finite or zero-bandwidth figure. `shm` comes
// with alpha and beta 0 until the run measures them (withMeasured).
NetworkFabric networkFabric(const std::string& name, double alpha_us, double beta_gbps);

// `fabric` with this run's measured shared-memory figures, when it is `shm`.
NetworkFabric withMeasured(NetworkFabric fabric, double alpha_us, double beta_gbps);

// One rank's share of one phase of an exchange round: its wall time outside MPI calls, and the
// messages it sent (bytes and forwarded segments in them).
struct PhaseLoad {
  double compute_seconds = 0;
  uint64_t messages = 0, bytes = 0, items = 0;
};
// One rank's load in one exchange round, in its two phases: the requests (the local traces and
// routing since the previous round, then its request messages) and the answers (the traces of
// the requests it received, then its answer messages). An answer needs its request, so a round
// waits for the slowest rank of each phase in turn.
struct RoundLoad {
  PhaseLoad request, answer;
};

// The modelled time of a run from every rank's per-round loads (loads[rank][round]; every rank
// has the same rounds): the sum over rounds and phases of the slowest rank's (compute + its
// messages x alpha + its bytes / beta), plus each round's count exchange (a collective), plus
// `tail` (work after the last round, the slowest rank's) and `reductions` (the hit and image
// reductions, already priced).
struct ModelledTime {
  double seconds = 0;
  double compute_seconds = 0;  // sum over rounds and phases of the slowest rank's compute
  double message_seconds = 0;  // sum over rounds and phases of the busiest sender's messages
  double control_seconds = 0;  // the rounds' count exchanges and the reductions
  uint64_t rounds = 0;

  // Sums and means over runs (render-compare's seeds).
  ModelledTime& operator+=(const ModelledTime& other);
  ModelledTime meanOver(int runs) const;
};
ModelledTime modelTime(const NetworkFabric& fabric,
                       const std::vector<std::vector<RoundLoad>>& loads, double tail_seconds,
                       double reduction_seconds);

}  // namespace proxyvis
