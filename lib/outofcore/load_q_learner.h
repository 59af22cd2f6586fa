#pragma once
// Learned q for the load-level roulette (docs/out_of_core.md, "Learned q"): per mesh, the
// probability of loading it and tracing its queue in a batch, from what earlier batches of the
// same render measured only, so the estimate stays unbiased (a batch's q is fixed before its
// draws).
//
// Skipping a queue of n segments adds (1/q - 1) E to the frame's summed pixel variance, where E
// is the sum over its segments the proxies answer wrongly of |w|^2 / spp^2 (w the sample's
// weight); tracing it costs C seconds (the load, unless resident, and the traces). With V the
// frame's variance and T its seconds, (V + sum (1/q - 1) E)(T + sum q C) is least at
// q = sqrt(E T / (C V)) per queue, as the per-ray roulette's q (docs/design.md). E per segment
// and C's parts come from the queues traced so far; a mesh never traced yet is traced (q = 1).
#include <cstdint>
#include <vector>

#include "render/integrator_steps.h"

namespace proxyvis {

// The frame's variance as LoadQLearner::q wants it (the sum over pixels and channels of the
// pixel mean's variance, times spp^2): spp x the per-sample variance, from `passes` passes'
// pixel sums and sums of squared |w v| (square_sums); 0 before two passes.
double frameVarianceSpp2(const std::vector<SampleSums>& sums,
                         const std::vector<double>& square_sums, int passes, int spp);

class LoadQLearner {
 public:
  LoadQLearner(size_t meshes, double q_min);

  // A traced queue of mesh `mesh`: `items` queued segments, `wrong_w2` the sum of |w|^2 over
  // those whose proxy answer was not the original's; the load's seconds when it loaded, the
  // traces' seconds.
  void observe(uint32_t mesh, size_t items, double wrong_w2, bool loaded, double load_seconds,
               double trace_seconds);

  // q for a queue of `items` segments of `mesh`, given whether the mesh is resident, the frame's
  // projected variance (sum over pixels and channels of the pixel mean's variance, times spp^2)
  // and projected seconds. 1 where nothing is known yet.
  double q(uint32_t mesh, size_t items, bool resident, double variance_spp2, double seconds) const;

 private:
  struct MeshStats {
    double items = 0, wrong_w2 = 0, trace_seconds = 0;
    double loads = 0, load_seconds = 0;
  };
  std::vector<MeshStats> meshes_;
  double q_min_;
};

}  // namespace proxyvis
