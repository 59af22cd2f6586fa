#include "outputs.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "metrics/color_map.h"
#include "render/image_io.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

// Units of the heat-maps' colour bars.
constexpr const char* kErrorUnit = "radiance²";
constexpr const char* kCostUnit = "rays/px";

std::string cellLabel(const ReportRow& row) {
  return row.table == kEqualTimeTable ? row.estimator + ", equal time"
                                      : fmt::format("{}, {:.0f} spp", row.estimator, row.spp);
}

}  // namespace

float autoExposure(const Image& reference) {
  std::vector<float> brightest;
  for (size_t p = 0; p + 2 < reference.pixels.size(); p += 3)
    brightest.push_back(
        std::max({reference.pixels[p], reference.pixels[p + 1], reference.pixels[p + 2]}));
  if (brightest.empty()) return 1;
  size_t k = size_t(0.99 * double(brightest.size() - 1));
  std::nth_element(brightest.begin(), brightest.begin() + k, brightest.end());
  return brightest[k] > 0 ? 1.0f / brightest[k] : 1.0f;
}

std::vector<float> raysPerPixel(const Image& cost) {
  std::vector<float> out(size_t(cost.width) * cost.height, 0.0f);
  if (cost.channels < 3) return out;
  for (size_t p = 0; p < out.size(); ++p)
    out[p] = cost.pixels[3 * p] + cost.pixels[3 * p + 1] + 2 * cost.pixels[3 * p + 2];
  return out;
}

HeatMapRange sharedLogRange(const std::vector<const std::vector<float>*>& maps) {
  std::vector<float> all;
  for (const auto* m : maps) all.insert(all.end(), m->begin(), m->end());
  return robustLogRange(all);
}

Image heatMapImage(const std::vector<float>& values, int width, int height,
                   const HeatMapRange& range) {
  return Image{width, height, 3, heatMapRgb(values, range)};
}

void writeCellImages(const CellImages& images, const fs::path& dir, float exposure,
                     const HeatMapRange& error_range, const HeatMapRange& cost_range) {
  const RenderResult& r = images.cell->first;
  writeImage(r.radiance, dir / (images.stem + ".exr"));
  writeImage(r.radiance, dir / (images.stem + ".png"), {exposure, false, {}});
  const int w = r.radiance.width, h = r.radiance.height;
  // AOVs: mean visibility and the rays per pixel by kind (the cost heat-map's data), 32-bit.
  Image aov{w, h, 4, std::vector<float>(size_t(w) * h * 4)};
  for (size_t i = 0; i < size_t(w) * h; ++i) {
    aov.pixels[i * 4] = r.visibility.pixels[i];
    for (int c = 0; c < 3; ++c) aov.pixels[i * 4 + 1 + c] = r.cost.pixels[i * 3 + c];
  }
  writeImage(aov, dir / (images.stem + "_aov.exr"),
             {1.0f, true, {"visibility", "rays_proxy", "rays_original", "rays_probe"}});
  writeImage(heatMapImage(images.cell->error_map, w, h, error_range),
             dir / (images.stem + "_error.png"));
  writeImage(heatMapImage(raysPerPixel(r.cost), w, h, cost_range),
             dir / (images.stem + "_cost.png"));
}

void writeColorBar(const fs::path& dir) {
  constexpr int kWidth = 256, kHeight = 8;
  writeImage(Image{kWidth, kHeight, 3, colorBarRgb(kWidth, kHeight)}, dir / kColorBarFile);
}

std::vector<HtmlGallery> cellGalleries(const std::string& title, const std::string& reference_png,
                                       const std::string& reference_exr,
                                       const std::vector<CellImages>& cells,
                                       const HeatMapRange& error_range,
                                       const HeatMapRange& cost_range) {
  HtmlGallery renders{title + ": images",
                      "Tone-mapped PNG of the first seed; the linked EXR holds the linear "
                      "radiance, the AOV EXR the visibility and rays per pixel.",
                      {{reference_png, "reference", "exact · converged", {{reference_exr, "EXR"}}}},
                      std::nullopt};
  HtmlGallery errors{title + ": squared error per pixel",
                     "Mean over RGB of (I − I_ref)², first seed; one colour scale for every "
                     "estimator of the table, its range under each map.",
                     {},
                     HtmlColorBar{kColorBarFile, error_range, kErrorUnit}};
  HtmlGallery costs{title + ": rays per pixel",
                    "proxy + original + 2 × probe rays per pixel, first seed; one colour scale "
                    "for every estimator of the table.",
                    {},
                    HtmlColorBar{kColorBarFile, cost_range, kCostUnit}};
  for (const CellImages& c : cells) {
    const ReportRow& row = c.cell->row;
    std::string detail =
        fmt::format("{:.0f} spp · {:.2f} s · MSE {:.2e}", row.spp, row.seconds, row.mse);
    renders.images.push_back({c.stem + ".png",
                              row.estimator,
                              detail,
                              {{c.stem + ".exr", "EXR"}, {c.stem + "_aov.exr", "AOV EXR"}}});
    errors.images.push_back({c.stem + "_error.png", row.estimator, detail, {}});
    double px = row.pixels > 0 ? row.pixels : 1;
    costs.images.push_back(
        {c.stem + "_cost.png",
         row.estimator,
         fmt::format("{:.1f} proxy · {:.1f} original · {:.1f} probe rays/px", row.rays.proxy / px,
                     row.rays.original / px, row.rays.probe / px),
         {{c.stem + "_aov.exr", "AOV EXR"}}});
  }
  return {renders, errors, costs};
}

std::vector<HtmlFileGroup> runFileGroups(const std::string& reference_png,
                                         const std::string& reference_exr,
                                         const std::vector<CellImages>& cells) {
  std::vector<HtmlFileGroup> groups = {
      {"Tables",
       {{"report.json", "report.json"}, {"report.csv", "report.csv"}, {"report.md", "report.md"}}},
      {"Reference",
       {{reference_exr, reference_exr},
        {fs::path(reference_exr).replace_extension(".json").string(), "its settings (JSON)"},
        {reference_png, "PNG"}}},
      {"Colour bar of the heat-maps", {{kColorBarFile, kColorBarFile}}}};
  for (const CellImages& c : cells)
    groups.push_back({cellLabel(c.cell->row),
                      {{c.stem + ".exr", "EXR"},
                       {c.stem + "_aov.exr", "AOV EXR"},
                       {c.stem + ".png", "PNG"},
                       {c.stem + "_error.png", "error map"},
                       {c.stem + "_cost.png", "cost map"}}});
  return groups;
}

LogLogPlot mseTimePlot(const std::vector<ReportRow>& rows) {
  LogLogPlot plot;
  plot.title = "MSE against render time (lower left is better; bars: ± standard error over seeds)";
  plot.x_label = "wall time per render (s, log scale)";
  plot.y_label = "MSE (linear radiance², log scale)";
  for (const ReportRow& r : rows) {
    auto it = std::find_if(plot.series.begin(), plot.series.end(),
                           [&](const PlotSeries& s) { return s.name == r.estimator; });
    if (it == plot.series.end()) {
      plot.series.push_back({r.estimator, {}});
      it = plot.series.end() - 1;
    }
    std::string label = r.table == kEqualTimeTable
                            ? fmt::format("equal time, {:.0f} spp reached", r.spp)
                            : fmt::format("{:.0f} spp", r.spp);
    it->points.push_back({r.seconds, r.mse, label, r.mse_stderr});
  }
  return plot;
}

}  // namespace proxyvis
