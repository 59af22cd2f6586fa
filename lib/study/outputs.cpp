#include "study/outputs.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "image/color_map.h"
#include "image/image_io.h"
#include "render/image_metadata.h"
#include "util/parallel_in_order.h"

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

namespace {

// The files of one cell, in the order writeReportImages reports a failure.
enum CellFile { kRadianceExr, kRadiancePng, kAovExr, kErrorPng, kCostPng, kCellFiles };

void writeCellFile(const CellImages& images, CellFile file, const SceneDesc& scene,
                   const fs::path& dir, float exposure, const HeatMapRange& error_range,
                   const HeatMapRange& cost_range) {
  const RenderResult& r = images.cell->first;
  const ReportRow& row = images.cell->row;
  RenderMetadata meta{"render-compare", row.estimator,           r.spp,
                      r.seconds,        images.cell->first_seed, {{"proxyvis:table", row.table}}};
  auto attributes = [&](const std::string& content) {
    RenderMetadata m = meta;
    m.extra.push_back({"proxyvis:content", content});
    return renderAttributes(scene, m);
  };
  const int w = r.radiance.width, h = r.radiance.height;
  switch (file) {
    case kRadianceExr: {
      ImageWriteOptions exr;
      exr.attributes = attributes("radiance (linear RGB), first seed");
      // Lossless either way: a noisy render's half floats barely compress, and zip took 4x the
      // CPU of rle for files only a quarter smaller (docs/slurm.md, "Measured"). The AOVs keep
      // zip: their counts repeat, and rle would make them 18x larger.
      exr.exr_compression = "rle";
      writeImage(r.radiance, dir / (images.stem + ".exr"), exr);
      break;
    }
    case kRadiancePng: {
      ImageWriteOptions png;
      png.exposure = exposure;
      png.attributes = attributes("radiance, tone-mapped: x exposure, clamped, sRGB");
      png.attributes.push_back({"proxyvis:exposure", exposure});
      writeImage(r.radiance, dir / (images.stem + ".png"), png);
      break;
    }
    case kAovExr: {  // the cost heat-map's data, 32-bit
      ImageWriteOptions aov_options;
      aov_options.full_float = true;
      aov_options.channel_names = kAovChannelNames;
      aov_options.attributes =
          attributes("AOVs: mean estimated visibility; proxy, original and probe rays per pixel");
      writeImage(aovImage(r), dir / (images.stem + "_aov.exr"), aov_options);
      break;
    }
    case kErrorPng: {
      ImageWriteOptions heat;
      heat.attributes = attributes("squared error per pixel against the reference, log heat-map");
      writeImage(heatMapImage(images.cell->error_map, w, h, error_range),
                 dir / (images.stem + "_error.png"), heat);
      break;
    }
    case kCostPng: {
      ImageWriteOptions heat;
      heat.attributes = attributes("rays per pixel (proxy + original + 2 x probe), log heat-map");
      writeImage(heatMapImage(raysPerPixel(r.cost), w, h, cost_range),
                 dir / (images.stem + "_cost.png"), heat);
      break;
    }
    case kCellFiles:
      break;
  }
}

}  // namespace

void writeReportImages(const std::vector<TableImages>& tables, const SceneDesc& scene,
                       const fs::path& dir, float exposure) {
  // One task per file, over every table at once (no table waits for the last file of the one
  // before): each file is encoded on its own (PNG compression is single-threaded), and its bytes
  // do not depend on which thread writes it or when.
  std::vector<std::pair<const TableImages*, size_t>> files;  // (table, file index in it)
  for (const TableImages& t : tables)
    for (size_t i = 0; i < t.cells.size() * kCellFiles; ++i) files.push_back({&t, i});
  parallelInOrder(files.size(), [&](size_t f) {
    const auto [t, i] = files[f];
    writeCellFile(t->cells[i / kCellFiles], CellFile(i % kCellFiles), scene, dir, exposure,
                  t->error_range, t->cost_range);
  });
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
