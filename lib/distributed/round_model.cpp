#include "distributed/round_model.h"

#include <algorithm>

namespace proxyvis {

ModelledTime modelAcrossRanks(const NetworkFabric& fabric, const std::vector<RoundLoad>& mine,
                              double tail, double reduction_seconds, const MpiComm& comm) {
  constexpr size_t kFields = 7;
  const size_t ranks = size_t(comm.size()), rank = size_t(comm.rank());
  const size_t rounds = mine.size();
  // Each rank fills its own rows and its tail; the sum gives every rank the whole table.
  std::vector<double> table(ranks * rounds * kFields + ranks, 0.0);
  for (size_t k = 0; k < rounds; ++k) {
    const RoundLoad& l = mine[k];
    const double fields[kFields] = {l.request.compute_seconds, double(l.request.messages),
                                    double(l.request.bytes),   double(l.request.items),
                                    l.answer.compute_seconds,  double(l.answer.messages),
                                    double(l.answer.bytes)};
    std::copy(fields, fields + kFields, &table[(rank * rounds + k) * kFields]);
  }
  table[ranks * rounds * kFields + rank] = tail;
  comm.sum(table);
  auto loads = std::vector<std::vector<RoundLoad>>(ranks, std::vector<RoundLoad>(rounds));
  double slowest_tail = 0;
  for (size_t r = 0; r < ranks; ++r) {
    for (size_t k = 0; k < rounds; ++k) {
      const double* row = &table[(r * rounds + k) * kFields];
      loads[r][k].request = {row[0], uint64_t(row[1]), uint64_t(row[2]), uint64_t(row[3])};
      loads[r][k].answer = {row[4], uint64_t(row[5]), uint64_t(row[6]), 0};
    }
    slowest_tail = std::max(slowest_tail, table[ranks * rounds * kFields + r]);
  }
  return modelTime(fabric, loads, slowest_tail, reduction_seconds);
}

}  // namespace proxyvis
