// render() with the estimator made from the settings; kept apart so that pv_render builds (and its
// tests run with their own estimators) before lib/estimate exists.
#include "render/renderer.h"

namespace proxyvis {

RenderResult render(const RenderScene& scene, const RenderSettings& settings) {
  const auto estimator = makeEstimator(estimatorSetupFor(scene, settings));
  return render(scene, settings, *estimator);
}

}  // namespace proxyvis
