#pragma once
// How proxy-gen and proxy-check both report the sampled Hausdorff distances between an original
// and its proxy: in the files' own coordinates (scene units) and as a share of the original's
// bounding-box diagonal, so the two programs' numbers can be compared and each is labelled.
#include <nlohmann/json_fwd.hpp>
#include <string>

namespace proxyvis {

struct HausdorffDistances {
  double original_to_proxy = 0, proxy_to_original = 0;  // scene units (sampled one-sided maxima)
  double diagonal = 0;  // the original's bounding-box diagonal, scene units
  bool operator==(const HausdorffDistances&) const = default;
};

// {"original_to_proxy", "proxy_to_original" (scene units), "unit", "diagonal",
//  "original_to_proxy_fraction_of_diagonal", "proxy_to_original_fraction_of_diagonal" (null for a
//  zero diagonal), "method"}.
nlohmann::json hausdorffJson(const HausdorffDistances& distances);

// The inverse of hausdorffJson (a report read back); throws nlohmann::json errors on other JSON.
HausdorffDistances hausdorffFromJson(const nlohmann::json& j);

// One line without a newline: "original->proxy 0.00666 (2.66 % of the diagonal), proxy->original
// 0.013 (5.21 %), in scene units (diagonal 0.25)".
std::string hausdorffText(const HausdorffDistances& distances);

}  // namespace proxyvis
