// The ceiling in the report writers: of_ceiling = efficiency / ceiling on a row (null without
// either), meta.ceiling in the JSON, and Markdown and HTML sections whose tables survive the '|'
// of "c_p|0".
#include "metrics/ceiling_report.h"

#include <gtest/gtest.h>

#include "metrics/html_report.h"
#include "metrics/report.h"

namespace proxyvis {
namespace {

ReportCeiling sampleCeiling() {
  ReportCeiling c;
  c.result.explanation = "First <sentence>. Second one.";
  c.model = "Model.";
  c.passes = 8;
  c.result.scene.regions = 4;
  c.result.scene.regions_roulette = 1;
  c.result.scene.ceiling = 1.25;  // the scene's line, "all"; no per-light lines
  return c;
}

TEST(CeilingReport, RowsCarryCeilingAndOfCeiling) {
  ReportRow row;
  row.efficiency = 1.1;
  row.ceiling = 1.25;
  nlohmann::json j = rowToJson(row);
  EXPECT_DOUBLE_EQ(j.at("ceiling").get<double>(), 1.25);
  EXPECT_DOUBLE_EQ(j.at("of_ceiling").get<double>(), 0.88);  // 1.1 / 1.25
  EXPECT_EQ(ofCeilingText(row), "88 %");
  row.efficiency = 0;  // no exact baseline
  j = rowToJson(row);
  EXPECT_TRUE(j.at("of_ceiling").is_null());
  EXPECT_EQ(ofCeilingText(row), "n/a");
  row.ceiling = 0;  // not measured
  j = rowToJson(row);
  EXPECT_TRUE(j.at("ceiling").is_null());
  EXPECT_TRUE(j.contains("of_ceiling"));
}

TEST(CeilingReport, JsonMetaHoldsThePerLightTable) {
  Report report;
  report.meta["scene"] = "s.json";
  report.ceiling = sampleCeiling();
  const nlohmann::json j = reportToJson(report);
  EXPECT_DOUBLE_EQ(j.at("meta").at("ceiling").at("value").get<double>(), 1.25);
  EXPECT_EQ(j.at("meta").at("ceiling").at("lights").at(0).at("regions_roulette").get<int>(), 1);
  EXPECT_EQ(j.at("meta").at("scene"), "s.json");
  EXPECT_FALSE(report.meta.contains("ceiling"));  // the report's own meta is left as it was
}

TEST(CeilingReport, MarkdownTableKeepsItsColumns) {
  const std::string md = ceilingMarkdown(sampleCeiling());
  EXPECT_NE(md.find("## Ceiling: 1.250× exact"), std::string::npos) << md;
  EXPECT_NE(md.find("| c_p\\|0 | c_p\\|1 |"), std::string::npos) << md;
  // Header, rule and the one line have the same number of unescaped '|'.
  auto pipes = [](const std::string& line) {
    int n = 0;
    for (size_t i = 0; i < line.size(); ++i) n += line[i] == '|' && (i == 0 || line[i - 1] != '\\');
    return n;
  };
  std::vector<std::string> lines;
  for (size_t a = 0, b; (b = md.find('\n', a)) != std::string::npos; a = b + 1)
    if (md.compare(a, 1, "|") == 0) lines.push_back(md.substr(a, b - a));
  ASSERT_EQ(lines.size(), 3u) << md;
  EXPECT_EQ(pipes(lines[0]), 14);  // 13 columns
  EXPECT_EQ(pipes(lines[1]), 14);
  EXPECT_EQ(pipes(lines[2]), 14);
}

TEST(CeilingReport, HtmlSectionIsEscaped) {
  Report report;
  report.ceiling = sampleCeiling();
  const std::string html = reportToHtml(report, {});
  EXPECT_NE(html.find("<h2>Ceiling: "), std::string::npos);
  EXPECT_NE(html.find("First &lt;sentence&gt;. Second one."), std::string::npos);
  EXPECT_EQ(html.find("<sentence>"), std::string::npos);
}

}  // namespace
}  // namespace proxyvis
