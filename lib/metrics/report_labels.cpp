#include "metrics/report_labels.h"

#include <algorithm>
#include <utility>

namespace proxyvis {

std::string reportLabel(std::string_view key) {
  static const std::pair<std::string_view, std::string_view> kLabels[] = {
      {"scene", "scene file"},
      {"scene_name", "scene"},
      {"scene_hash", "scene hash"},
      {"build", "exact baseline BVH (flat or instanced)"},
      {"build_reason", "why this BVH build"},
      {"resolution", "resolution (pixels)"},
      {"spp", "samples per pixel (equal-samples tables)"},
      {"spp_max", "samples per pixel (most of one seed)"},
      {"equal_time_seconds", "time per render, equal-time table (s)"},
      {"seeds", "seeds per cell"},
      {"seed", "base seed"},
      {"threads", "threads"},
      {"proxy_class", "proxy class relied on"},
      {"proxy_classes", "proxies"},
      {"uses_proxies", "scene has proxies"},
      {"original_triangles", "triangles, original meshes"},
      {"proxy_triangles", "triangles, proxies"},
      {"reference_spp", "reference: samples per pixel"},
      {"reference_variance_of_mean", "reference: variance of its mean"},
      {"reference_file", "reference image (EXR)"},
      {"reference_cached", "reference taken from the cache"},
      {"reference_to_min_mse", "reference variance / smallest MSE"},
      {"relmse_epsilon", "relMSE ε"},
      {"mesh", "mesh"},
      {"proxy", "proxy file"},
      {"claimed", "class claimed"},
      {"class", "class used"},
      {"class_status", "status"},
      {"reason", "why"},
  };
  auto it = std::find_if(std::begin(kLabels), std::end(kLabels),
                         [&](const auto& entry) { return entry.first == key; });
  if (it != std::end(kLabels)) return std::string(it->second);
  std::string label(key);
  std::replace(label.begin(), label.end(), '_', ' ');
  return label;
}

}  // namespace proxyvis
