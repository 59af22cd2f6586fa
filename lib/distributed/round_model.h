#pragma once
// The alpha-beta model of a data-parallel run across its ranks (network_fabric.h prices it):
// every rank's per-round loads gathered into one table, then priced on the fabric.
#include <vector>

#include "distributed/mpi_comm.h"
#include "distributed/network_fabric.h"

namespace proxyvis {

// Collective. `mine`: this rank's loads per exchange round (every rank has as many); `tail`:
// its work after the last round; `reduction_seconds`: the reductions, already priced.
ModelledTime modelAcrossRanks(const NetworkFabric& fabric, const std::vector<RoundLoad>& mine,
                              double tail, double reduction_seconds, const MpiComm& comm);

}  // namespace proxyvis
