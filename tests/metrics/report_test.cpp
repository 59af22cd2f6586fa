#include "metrics/report.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "metrics/html_report.h"

namespace proxyvis {
namespace {

ReportRow row(std::string table, std::string est, double spp, double seconds, double mse) {
  ReportRow r;
  r.table = std::move(table);
  r.estimator = std::move(est);
  r.spp = spp;
  r.seconds = seconds;
  r.mse = mse;
  r.mse_stderr = mse / 10;
  r.relmse = mse * 3;
  r.rays = {100, 50, 0};
  r.pixels = 10;
  r.seeds = 3;
  return r;
}

Report sampleReport() {
  Report rep;
  rep.title = "render-compare: <test> & co";
  rep.meta["scene"] = "scenes/tiny.json";
  rep.notes.push_back("reference variance 1e-9 ≪ smallest MSE");
  rep.rows = {
      row("equal-spp", "exact", 4, 1.0, 4e-3),   row("equal-spp", "roulette", 4, 0.5, 4e-3),
      row("equal-spp", "exact", 16, 4.0, 1e-3),  row("equal-spp", "roulette", 16, 2.0, 2e-3),
      row("equal-time", "exact", 20, 2.0, 1e-3), row("equal-time", "culling", 30, 2.0, 5e-4)};
  fillRelativeEfficiency(rep.rows, kEqualSppTable);
  fillRelativeEfficiency(rep.rows, kEqualTimeTable);
  return rep;
}

TEST(Report, EfficiencyIsRelativeToExactOfTheSameTableAndSpp) {
  Report rep = sampleReport();
  EXPECT_DOUBLE_EQ(rep.rows[0].efficiency, 1.0);
  EXPECT_DOUBLE_EQ(rep.rows[1].efficiency, 2.0);  // same MSE in half the time
  EXPECT_DOUBLE_EQ(rep.rows[3].efficiency, 1.0);  // 2× MSE in half the time, vs exact at 16 spp
  EXPECT_DOUBLE_EQ(rep.rows[5].efficiency, 2.0);  // equal time, half the MSE
}

TEST(Report, JsonHasTheContractKeys) {
  Report rep = sampleReport();
  nlohmann::json j = nlohmann::json::parse(reportToJson(rep).dump());
  EXPECT_DOUBLE_EQ(j.at("relmse_epsilon").get<double>(), 1e-2);
  ASSERT_EQ(j.at("rows").size(), rep.rows.size());
  for (const auto& r : j.at("rows"))
    for (const char* key : {"estimator", "spp", "seconds", "mse", "relmse", "efficiency", "rays"})
      EXPECT_TRUE(r.contains(key)) << key;
  EXPECT_EQ(j["rows"][1]["estimator"], "roulette");
  EXPECT_DOUBLE_EQ(j["rows"][1]["efficiency"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(j["rows"][1]["rays"]["proxy"].get<double>(), 100.0);
  EXPECT_DOUBLE_EQ(j["rows"][1]["rays_per_pixel"]["original"].get<double>(), 5.0);
}

TEST(Report, TypedRowFieldsKeepTheirJsonKeys) {
  ReportRow r = row("equal-time", "roulette", 30, 2.0, 5e-4);
  r.spp_max = 33;
  r.shading_seconds = 0.25;
  r.visibility_seconds = 1.5;
  r.time_budget = 2.0;
  r.proxy_class = "outside";
  r.mse_per_seed = {4e-4, 6e-4};
  LearnedSummary learned;
  learned.regions = 12;
  learned.regions_roulette = 5;
  learned.costs.proxy[1] = 7;
  r.learned = learned;
  nlohmann::json j = rowToJson(r);
  EXPECT_EQ(j.at("spp_max"), 33);
  EXPECT_DOUBLE_EQ(j.at("shading_seconds").get<double>(), 0.25);
  EXPECT_DOUBLE_EQ(j.at("visibility_seconds").get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(j.at("time_budget").get<double>(), 2.0);
  EXPECT_EQ(j.at("proxy_class"), "outside");
  EXPECT_EQ(j.at("mse_per_seed").size(), 2u);
  EXPECT_EQ(j.at("learned").at("regions"), 12);
  EXPECT_EQ(j.at("learned").at("regions_roulette"), 5);
  EXPECT_DOUBLE_EQ(j.at("learned").at("cost_proxy").at(1).get<double>(), 7.0);
  // An equal-spp row has no budget and a non-roulette row learned nothing: no such keys.
  nlohmann::json plain = rowToJson(row("equal-spp", "exact", 4, 1.0, 4e-3));
  EXPECT_FALSE(plain.contains("time_budget"));
  EXPECT_FALSE(plain.contains("learned"));
}

TEST(Report, CsvHasHeaderAndOneLinePerRow) {
  Report rep = sampleReport();
  std::istringstream in(reportToCsv(rep.rows));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("table,estimator,spp,seconds,mse,", 0), 0u) << line;
  size_t columns = std::count(line.begin(), line.end(), ',');
  int lines = 0;
  while (std::getline(in, line)) {
    ++lines;
    EXPECT_EQ(size_t(std::count(line.begin(), line.end(), ',')), columns) << line;
  }
  EXPECT_EQ(lines, int(rep.rows.size()));
}

TEST(Report, MarkdownTableFiltersByTable) {
  Report rep = sampleReport();
  std::string t = markdownTable(rep.rows, kEqualTimeTable);
  EXPECT_NE(t.find("| culling |"), std::string::npos);
  EXPECT_EQ(t.find("| roulette |"), std::string::npos);
  EXPECT_NE(t.find("2.00×"), std::string::npos);
  std::string md = reportToMarkdown(rep);
  EXPECT_NE(md.find("ε = 0.01"), std::string::npos);
  EXPECT_NE(md.find("## Equal time"), std::string::npos);
  EXPECT_NE(md.find("## Equal samples"), std::string::npos);
}

size_t countOccurrences(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

TEST(Report, HtmlHasOnePolylinePerEstimatorAndEscapesText) {
  Report rep = sampleReport();
  HtmlReportLayout layout;
  LogLogPlot plot;
  plot.title = "MSE vs time";
  for (const char* est : {"exact", "culling", "roulette"}) {
    PlotSeries s{est, {}};
    for (const ReportRow& r : rep.rows)
      if (r.estimator == est) s.points.push_back({r.seconds, r.mse, ""});
    plot.series.push_back(s);
  }
  layout.plots.push_back(plot);
  layout.galleries.push_back({"Images", "", {{"exact_16.png", "exact", "MSE 1e-3", {}}}, {}});
  std::string html = reportToHtml(rep, layout);
  EXPECT_EQ(countOccurrences(html, "<svg"), 1u);
  EXPECT_EQ(countOccurrences(html, "<polyline"), 3u);
  for (const char* est : {"exact", "culling", "roulette"})
    EXPECT_NE(html.find(std::string("data-series=\"") + est + "\""), std::string::npos);
  EXPECT_NE(html.find("&lt;test&gt; &amp; co"), std::string::npos);
  EXPECT_EQ(html.find("<test>"), std::string::npos);
  EXPECT_NE(html.find("<img src=\"exact_16.png\""), std::string::npos);
  EXPECT_NE(html.find("</html>"), std::string::npos);
}

TEST(Report, HtmlHeadingIsTheSceneNameAndTheMarkdownToo) {
  Report rep = sampleReport();
  rep.scene_name = "dragon-plane";
  std::string html = reportToHtml(rep, {});
  EXPECT_NE(html.find("<h1>dragon-plane</h1>"), std::string::npos);
  EXPECT_NE(html.find("<title>dragon-plane · render-compare</title>"), std::string::npos);
  EXPECT_EQ(reportToMarkdown(rep).rfind("# dragon-plane\n", 0), 0u);
  EXPECT_EQ(reportToJson(rep).at("scene_name"), "dragon-plane");
  rep.scene_name.clear();  // no name: the title
  EXPECT_NE(reportToHtml(rep, {}).find("<h1>render-compare: &lt;test&gt; &amp; co</h1>"),
            std::string::npos);
}

TEST(Report, HtmlKeepsNumbersWholeAndTablesInAScrollBox) {
  Report rep = sampleReport();
  rep.notes.push_back("variance 1.06e-05 = 50% of 2.09e-05 & more");
  std::string html = reportToHtml(rep, {});
  EXPECT_NE(html.find("<span class=\"num\">1.06e-05</span> = <span class=\"num\">50%</span>"),
            std::string::npos);
  EXPECT_NE(html.find("&amp; more"), std::string::npos);
  EXPECT_EQ(countOccurrences(html, "<div class=\"scroll\"><table class=\"rows\">"), 2u);
  EXPECT_NE(html.find(".num, td { white-space: nowrap; }"), std::string::npos);
  EXPECT_NE(html.find("max-width: 100%"), std::string::npos);
}

TEST(Report, HtmlMetaHasReadableLabelsLinksAndRecordTables) {
  Report rep = sampleReport();
  rep.meta["reference_spp"] = 1024;
  rep.meta["reference_file"] = "reference-ab12.exr";
  rep.meta["uses_proxies"] = true;
  rep.meta["warnings"] = nlohmann::json::array();
  rep.meta["proxy_classes"] = nlohmann::json::array(
      {{{"mesh", "box"}, {"class", "outside"}}, {{"mesh", "bunny"}, {"class", "general"}}});
  HtmlReportLayout layout;
  layout.files.push_back({"Reference", {{"reference-ab12.exr", "reference-ab12.exr"}}});
  std::string html = reportToHtml(rep, layout);
  EXPECT_NE(html.find("<b>reference: samples per pixel</b>"), std::string::npos);
  EXPECT_EQ(html.find("reference_spp"), std::string::npos);
  EXPECT_NE(html.find("<b>scene has proxies</b>yes"), std::string::npos);
  EXPECT_NE(html.find("<b>warnings</b>none"), std::string::npos);
  // A meta value naming a written file links it; the file list links it too.
  EXPECT_EQ(countOccurrences(html, "<a href=\"reference-ab12.exr\">"), 2u);
  EXPECT_NE(html.find("<h3>proxies</h3>"), std::string::npos);
  EXPECT_NE(html.find("<td>bunny</td><td>general</td>"), std::string::npos);
}

TEST(Report, HtmlHeatMapGalleryHasAColourBarWithItsRangeUnderEachImage) {
  Report rep = sampleReport();
  HtmlReportLayout layout;
  HtmlGallery g{"Errors", "", {}, HtmlColorBar{"colorbar.png", {2e-5, 3e-2, true}, "rays/px"}};
  g.images.push_back({"a_error.png", "a", "1 spp · MSE 1.0e-03", {{"a.exr", "EXR"}}});
  g.images.push_back({"b_error.png", "b", "", {}});
  layout.galleries.push_back(g);
  std::string html = reportToHtml(rep, layout);
  EXPECT_EQ(countOccurrences(html, "<img src=\"colorbar.png\""), 2u);
  EXPECT_EQ(countOccurrences(html, "<span class=\"num\">2.0e-05</span>"), 2u);
  EXPECT_EQ(countOccurrences(html, "<span class=\"num\">3.0e-02</span>"), 2u);
  EXPECT_NE(html.find("rays/px, log scale"), std::string::npos);
  EXPECT_NE(html.find("<span class=\"num\">1 spp</span> · <span class=\"num\">MSE 1.0e-03</span>"),
            std::string::npos);
  EXPECT_NE(html.find("<a href=\"a.exr\">EXR</a>"), std::string::npos);
}

}  // namespace
}  // namespace proxyvis
