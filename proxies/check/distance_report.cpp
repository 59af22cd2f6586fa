#include "proxies/check/distance_report.h"

#include <fmt/core.h>

#include <nlohmann/json.hpp>

namespace proxyvis {

namespace {
nlohmann::json fractionOfDiagonal(double distance, double diagonal) {
  return diagonal > 0 ? nlohmann::json(distance / diagonal) : nlohmann::json(nullptr);
}

std::string percentOfDiagonal(double distance, double diagonal) {
  return diagonal > 0 ? fmt::format("{:.3g} %", 100 * distance / diagonal) : std::string("n/a");
}
}  // namespace

nlohmann::json hausdorffJson(const HausdorffDistances& d) {
  return {{"original_to_proxy", d.original_to_proxy},
          {"proxy_to_original", d.proxy_to_original},
          {"unit", "scene units"},
          {"diagonal", d.diagonal},
          {"original_to_proxy_fraction_of_diagonal",
           fractionOfDiagonal(d.original_to_proxy, d.diagonal)},
          {"proxy_to_original_fraction_of_diagonal",
           fractionOfDiagonal(d.proxy_to_original, d.diagonal)},
          {"method", "sampled one-sided maximum (lower bound)"}};
}

HausdorffDistances hausdorffFromJson(const nlohmann::json& j) {
  return {j.at("original_to_proxy").get<double>(), j.at("proxy_to_original").get<double>(),
          j.at("diagonal").get<double>()};
}

std::string hausdorffText(const HausdorffDistances& d) {
  return fmt::format(
      "original->proxy {:.4g} ({} of the diagonal), proxy->original {:.4g} ({}), in scene units "
      "(the original's bounding-box diagonal is {:.4g})",
      d.original_to_proxy, percentOfDiagonal(d.original_to_proxy, d.diagonal), d.proxy_to_original,
      percentOfDiagonal(d.proxy_to_original, d.diagonal), d.diagonal);
}

}  // namespace proxyvis
