#pragma once
// A self-contained HTML page for a render-compare report: settings, the tables, inline SVG
// log-log plots and image galleries (images are referenced by relative path, so the page works
// from the output directory and can be copied with it).
#include <string>
#include <vector>

#include "metrics/log_plot.h"
#include "metrics/report.h"

namespace proxyvis {

struct HtmlImage {
  std::string src;      // relative to the HTML file
  std::string caption;  // e.g. the estimator
  std::string detail;   // e.g. "MSE 1.2e-4 · 0.8 s"
};

struct HtmlGallery {
  std::string title;
  std::string description;  // plain text
  std::vector<HtmlImage> images;
};

struct HtmlReportLayout {
  std::vector<LogLogPlot> plots;
  std::vector<HtmlGallery> galleries;
};

// The whole page. Every text is HTML-escaped; numbers as in the Markdown tables.
std::string reportToHtml(const Report& report, const HtmlReportLayout& layout);

}  // namespace proxyvis
