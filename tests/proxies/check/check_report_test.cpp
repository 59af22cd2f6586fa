// proxy-check's text and JSON report (proxies/check/check_report.h) and the shared distance
// presentation (proxies/check/distance_report.h), on hand-made reports with known numbers.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "proxies/check/check_report.h"
#include "proxies/check/distance_report.h"

namespace proxyvis {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// An original whose bounding-box diagonal is 2 and distances of 0.5 and 0.1 scene units.
PairCheckReport report(bool original_closed, bool proxy_closed) {
  PairCheckReport r;
  r.original = {"original.off", 12, 8, original_closed, 1.0};
  r.proxy = {"proxy.off", 12, 8, proxy_closed, 2.0};
  r.distance_original_to_proxy = 0.5;
  r.distance_proxy_to_original = 0.1;
  r.original_diagonal = 2.0;
  return r;
}

TEST(CheckReport, HausdorffInSceneUnitsAndFractionsOfTheDiagonal) {
  const nlohmann::json j = toJson(report(true, true));
  const nlohmann::json& h = j.at("hausdorff");
  EXPECT_DOUBLE_EQ(h.at("original_to_proxy").get<double>(), 0.5);  // kept: scene units
  EXPECT_DOUBLE_EQ(h.at("proxy_to_original").get<double>(), 0.1);
  EXPECT_EQ(h.at("unit"), "scene units");
  EXPECT_DOUBLE_EQ(h.at("diagonal").get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(h.at("original_to_proxy_fraction_of_diagonal").get<double>(), 0.25);
  EXPECT_DOUBLE_EQ(h.at("proxy_to_original_fraction_of_diagonal").get<double>(), 0.05);
  const std::string text = formatHumanReport(report(true, true));
  EXPECT_TRUE(contains(text, "original->proxy 0.5 (25 % of the diagonal)")) << text;
  EXPECT_TRUE(contains(text, "proxy->original 0.1 (5 %)")) << text;
  EXPECT_TRUE(contains(text, "in scene units")) << text;
}

TEST(CheckReport, ClosedMeshesHaveVolumesAndARatio) {
  const nlohmann::json j = toJson(report(true, true));
  EXPECT_DOUBLE_EQ(j["original"]["volume"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(j["volume_ratio"].get<double>(), 2.0);
  EXPECT_FALSE(j.contains("volume_ratio_note"));
  EXPECT_FALSE(j["original"].contains("volume_note"));
  EXPECT_TRUE(
      contains(formatHumanReport(report(true, true)), "volume ratio proxy/original 2.0000"));
}

TEST(CheckReport, AnOpenOriginalHasNoVolumeAndSaysWhy) {
  const PairCheckReport r = report(false, true);
  const nlohmann::json j = toJson(r);
  EXPECT_TRUE(j["original"]["volume"].is_null());
  EXPECT_TRUE(contains(j["original"]["volume_note"].get<std::string>(), "open"));
  EXPECT_DOUBLE_EQ(j["proxy"]["volume"].get<double>(), 2.0);
  EXPECT_TRUE(j["volume_ratio"].is_null());
  EXPECT_EQ(j["volume_ratio_note"], "the original is open: it bounds no volume");
  const std::string text = formatHumanReport(r);
  EXPECT_TRUE(contains(text, "no volume (open)")) << text;
  EXPECT_FALSE(contains(text, "volume 1")) << text;  // the meaningless number is not shown
  EXPECT_TRUE(contains(text, "volume ratio proxy/original: none (the original is open")) << text;
}

TEST(CheckReport, AnOpenProxyOrBothOpenSayWhich) {
  EXPECT_EQ(toJson(report(true, false))["volume_ratio_note"],
            "the proxy is open: it bounds no volume");
  EXPECT_EQ(toJson(report(false, false))["volume_ratio_note"],
            "both meshes are open: neither bounds a volume");
}

TEST(DistanceReport, RoundTripsAndAZeroDiagonalHasNoFraction) {
  const HausdorffDistances d{0.3, 0.2, 1.5};
  const HausdorffDistances back = hausdorffFromJson(hausdorffJson(d));
  EXPECT_DOUBLE_EQ(back.original_to_proxy, 0.3);
  EXPECT_DOUBLE_EQ(back.proxy_to_original, 0.2);
  EXPECT_DOUBLE_EQ(back.diagonal, 1.5);
  const nlohmann::json zero = hausdorffJson({0.3, 0.2, 0.0});
  EXPECT_TRUE(zero["original_to_proxy_fraction_of_diagonal"].is_null());
  EXPECT_TRUE(contains(hausdorffText({0.3, 0.2, 0.0}), "n/a"));
}

}  // namespace
}  // namespace proxyvis
