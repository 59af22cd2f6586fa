#pragma once
// A self-contained HTML page for a render-compare report: settings, the tables, inline SVG
// log-log plots, image galleries with colour bars under the heat-maps, and links to every file
// the run wrote. Images and files are referenced by relative path, so the page works from the
// output directory and can be copied with it. The page fits an 800 px wide window: tables scroll
// inside their own box, images shrink, numbers never break inside.
#include <optional>
#include <string>
#include <vector>

#include "metrics/heat_map.h"
#include "metrics/log_plot.h"
#include "metrics/report.h"

namespace proxyvis {

struct HtmlLink {
  std::string href;  // relative to the HTML file
  std::string text;
};

// The scale of a heat-map gallery, drawn under each of its images.
struct HtmlColorBar {
  std::string src;     // image of the colour map, t = 0 at the left, 1 at the right
  HeatMapRange range;  // the values at the two ends
  std::string unit;    // e.g. "rays/px"
};

struct HtmlImage {
  std::string src;              // relative to the HTML file
  std::string caption;          // e.g. the estimator
  std::string detail;           // e.g. "16 spp · 0.8 s · MSE 1.2e-04" (" · " may wrap)
  std::vector<HtmlLink> links;  // e.g. the EXR the PNG was made from
};

struct HtmlGallery {
  std::string title;
  std::string description;  // plain text
  std::vector<HtmlImage> images;
  std::optional<HtmlColorBar> color_bar;  // heat-map galleries
};

// One line of the page's file list: "label: link · link ...".
struct HtmlFileGroup {
  std::string label;
  std::vector<HtmlLink> links;
};

struct HtmlReportLayout {
  std::vector<LogLogPlot> plots;
  std::vector<HtmlGallery> galleries;
  std::vector<HtmlFileGroup> files;  // everything the run wrote; a meta value naming one links it
};

// The whole page. Every text is HTML-escaped; numbers as in the Markdown tables. The heading is
// the scene's name (Report::scene_name), or the report's title when the name is empty.
std::string reportToHtml(const Report& report, const HtmlReportLayout& layout);

}  // namespace proxyvis
