#include "outofcore/load_q_learner.h"

#include <algorithm>
#include <cmath>

namespace proxyvis {

LoadQLearner::LoadQLearner(size_t meshes, double q_min) : meshes_(meshes), q_min_(q_min) {}

void LoadQLearner::observe(uint32_t mesh, size_t items, double wrong_w2, bool loaded,
                           double load_seconds, double trace_seconds) {
  MeshStats& m = meshes_[mesh];
  m.items += double(items);
  m.wrong_w2 += wrong_w2;
  m.trace_seconds += trace_seconds;
  if (loaded) {
    m.loads += 1;
    m.load_seconds += load_seconds;
  }
}

double LoadQLearner::q(uint32_t mesh, size_t items, bool resident, double variance_spp2,
                       double seconds) const {
  const MeshStats& m = meshes_[mesh];
  if (m.items <= 0 || m.loads <= 0 || !(variance_spp2 > 0) || !(seconds > 0)) return 1.0;
  const double n = double(items);
  const double wrong = m.wrong_w2 / m.items * n;
  const double cost = (resident ? 0.0 : m.load_seconds / m.loads) + m.trace_seconds / m.items * n;
  if (!(cost > 0)) return 1.0;
  return std::clamp(std::sqrt(wrong * seconds / (cost * variance_spp2)), q_min_, 1.0);
}

double frameVarianceSpp2(const std::vector<SampleSums>& sums,
                         const std::vector<double>& square_sums, int passes, int spp) {
  if (passes < 2) return 0;
  const double n = passes;
  double sum = 0;
  for (size_t p = 0; p < sums.size(); ++p) {
    const Vec3d mean = sums[p].radiance / n;
    const double var =
        (square_sums[p] / n - (mean.x * mean.x + mean.y * mean.y + mean.z * mean.z)) * n / (n - 1);
    sum += std::max(0.0, var);
  }
  return sum * double(spp);
}

}  // namespace proxyvis
