// proxy-gen's typed report (proxies/pipeline/proxy_report.h): random reports survive JSON text
// and come back equal, and a key of the wrong type or a missing key is an error naming its path.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "json_round_trip.h"
#include "random_report.h"
#include "util/error.h"

namespace proxyvis {
namespace {

using nlohmann::json;
using report_test::RandomReports;
using report_test::readError;
using report_test::throughText;

TEST(ProxyReportJson, RandomReportsRoundTrip) {
  RandomReports random(20261206);
  for (int i = 0; i < 300; ++i) {
    const ProxyReport r = random.report();
    const ProxyReport back = throughText(r);
    ASSERT_EQ(back, r) << "report " << i << ":\n" << json(r).dump(1);
    // The text is a fixed point too: the same report writes the same bytes.
    EXPECT_EQ(json(back).dump(1), json(r).dump(1));
  }
}

TEST(ProxyReportJson, RandomSceneMeshesRoundTrip) {
  RandomReports random(7);
  for (int i = 0; i < 300; ++i) {
    const SceneMeshReport m = random.sceneMesh();
    ASSERT_EQ(throughText(m), m) << "mesh " << i << ":\n" << json(m).dump(1);
  }
}

// The keys of the documented layout, written by hand (docs/proxy_reports.md).
TEST(ProxyReportJson, KeysAndTypesAreTheDocumentedOnes) {
  ProxyReport r;
  r.input.path = "in.off";
  r.input.faces = 10;
  r.kind = ProxyClass::kInside;
  r.method = "wrap";
  r.parameters.budget = "hard";
  r.parameters.alpha = 0.02;
  r.seconds = {{"build", 1.5}, {"total", 2.0}};
  r.written_class = ProxyClass::kGeneral;
  r.class_reason = "holes";
  r.hausdorff = {0.5, 0.25, 2.0};
  const json j = r;
  EXPECT_EQ(j["input"]["path"], "in.off");
  EXPECT_TRUE(j["input"]["faces"].is_number_unsigned());
  EXPECT_EQ(j["kind"], "inside");
  EXPECT_EQ(j["class"], "general");
  EXPECT_EQ(j["class_reason"], "holes");
  EXPECT_TRUE(j["volume_ratio"].is_null());
  EXPECT_EQ(j["parameters"]["alpha"], 0.02);
  EXPECT_FALSE(j["parameters"].contains("offset"));  // not read by the method: no key
  EXPECT_FALSE(j.contains("budget_ladder"));         // no fallback tried: no key
  EXPECT_FALSE(j.contains("budget_reached"));
  EXPECT_EQ(j["seconds"].dump(), R"({"build":1.5,"total":2.0})");
  EXPECT_EQ(j["hausdorff"]["original_to_proxy_fraction_of_diagonal"], 0.25);
  EXPECT_EQ(j["hausdorff"]["unit"], "scene units");
  r.written_class.reset();
  EXPECT_TRUE(json(r)["class"].is_null());
}

TEST(ProxyReportJson, AMissingKeyIsNamed) {
  RandomReports random(11);
  const json good = random.report();
  const std::vector<std::vector<std::string>> paths = {
      {"input", "faces"},        {"kind"},  {"parameters", "seed"}, {"checks", "closed"},
      {"hausdorff", "diagonal"}, {"faces"}, {"verified"},           {"seconds"}};
  for (const std::vector<std::string>& path : paths) {
    json bad = good;
    json* parent = &bad;
    std::string dotted;
    for (size_t i = 0; i + 1 < path.size(); ++i) {
      parent = &(*parent)[path[i]];
      dotted += path[i] + ".";
    }
    parent->erase(path.back());
    dotted += path.back();
    EXPECT_NE(readError<ProxyReport>(bad).find(dotted + ": missing"), std::string::npos)
        << dotted << ": " << readError<ProxyReport>(bad);
  }
}

TEST(ProxyReportJson, AWrongTypeIsNamed) {
  RandomReports random(12);
  const json good = random.report();
  const std::vector<std::pair<json::json_pointer, json>> cases = {
      {json::json_pointer("/input/faces"), "many"},
      {json::json_pointer("/input/faces"), -3},
      {json::json_pointer("/input/closed"), 1},
      {json::json_pointer("/kind"), "sideways"},
      {json::json_pointer("/parameters/max_faces"), 1.5},
      {json::json_pointer("/class"), 3},
      {json::json_pointer("/volume_ratio"), "big"},
      {json::json_pointer("/seconds"), json::array()},
      {json::json_pointer("/hausdorff/proxy_to_original"), nullptr},
      {json::json_pointer("/budget_ladder"), json::object()}};
  for (const auto& [pointer, value] : cases) {
    json bad = good;
    bad[pointer] = value;
    std::string dotted = pointer.to_string().substr(1);
    std::replace(dotted.begin(), dotted.end(), '/', '.');
    const std::string message = readError<ProxyReport>(bad);
    EXPECT_NE(message.find(dotted + ":"), std::string::npos) << dotted << ": " << message;
  }
}

TEST(SceneMeshReportJson, AProxyEntryNeedsTheProxyKeys) {
  const json skipped = {{"name", "ground"}, {"skipped", "2 faces"}, {"faces", 2}};
  const SceneMeshReport m = skipped.get<SceneMeshReport>();
  EXPECT_EQ(m.skipped, "2 faces");
  EXPECT_EQ(m.faces, 2u);
  EXPECT_FALSE(m.proxy);
  // Neither skipped nor failed: a proxy's report, whose keys are required.
  const json partial = {{"name", "a"}, {"faces", 12}};
  EXPECT_NE(readError<SceneMeshReport>(partial).find("input: missing"), std::string::npos)
      << readError<SceneMeshReport>(partial);
}

}  // namespace
}  // namespace proxyvis
