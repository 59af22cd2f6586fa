#include "outputs.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "render/image_io.h"
#include "render/image_metadata.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

// Inverse of the sRGB transfer curve (IEC 61966-2-1), for colours that are already display-
// encoded but go through writeImage's linear-to-sRGB PNG path.
float srgbToLinear(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

std::string rangeText(const HeatMapRange& r) {
  return fmt::format("log scale, {:.1e} (dark) to {:.1e} (bright)", r.lo, r.hi);
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
  Image image{width, height, 3, heatMapRgb(values, range)};
  for (float& v : image.pixels) v = srgbToLinear(v);
  return image;
}

void writeCellImages(const CellImages& images, const SceneDesc& scene, const fs::path& dir,
                     float exposure, const HeatMapRange& error_range,
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
  ImageWriteOptions exr;
  exr.attributes = attributes("radiance (linear RGB), first seed");
  writeImage(r.radiance, dir / (images.stem + ".exr"), exr);
  ImageWriteOptions png;
  png.exposure = exposure;
  png.attributes = attributes("radiance, tone-mapped: x exposure, clamped, sRGB");
  png.attributes.push_back({"proxyvis:exposure", exposure});
  writeImage(r.radiance, dir / (images.stem + ".png"), png);
  const int w = r.radiance.width, h = r.radiance.height;
  // AOVs (the cost heat-map's data), 32-bit.
  ImageWriteOptions aov_options;
  aov_options.full_float = true;
  aov_options.channel_names = kAovChannelNames;
  aov_options.attributes =
      attributes("AOVs: mean estimated visibility; proxy, original and probe rays per pixel");
  writeImage(aovImage(r), dir / (images.stem + "_aov.exr"), aov_options);
  ImageWriteOptions heat;
  heat.attributes = attributes("squared error per pixel against the reference, log heat-map");
  writeImage(heatMapImage(images.cell->error_map, w, h, error_range),
             dir / (images.stem + "_error.png"), heat);
  heat.attributes = attributes("rays per pixel (proxy + original + 2 x probe), log heat-map");
  writeImage(heatMapImage(raysPerPixel(r.cost), w, h, cost_range),
             dir / (images.stem + "_cost.png"), heat);
}

std::vector<HtmlGallery> cellGalleries(const std::string& title, const std::string& reference_png,
                                       const std::vector<CellImages>& cells,
                                       const HeatMapRange& error_range,
                                       const HeatMapRange& cost_range) {
  HtmlGallery renders{title + ": images",
                      "Tone-mapped PNG (linear EXR beside it), first seed.",
                      {{reference_png, "reference", "exact, converged"}}};
  HtmlGallery errors{title + ": squared error per pixel",
                     "Mean over RGB of (I − I_ref)², " + rangeText(error_range) +
                         ", the same scale for every estimator.",
                     {}};
  HtmlGallery costs{title + ": rays per pixel",
                    "proxy + original + 2 × probe rays per pixel, " + rangeText(cost_range) + ".",
                    {}};
  for (const CellImages& c : cells) {
    const ReportRow& row = c.cell->row;
    std::string detail =
        fmt::format("{:.0f} spp · {:.2f} s · MSE {:.2e}", row.spp, row.seconds, row.mse);
    renders.images.push_back({c.stem + ".png", row.estimator, detail});
    errors.images.push_back({c.stem + "_error.png", row.estimator, detail});
    double px = row.pixels > 0 ? row.pixels : 1;
    costs.images.push_back(
        {c.stem + "_cost.png", row.estimator,
         fmt::format("{:.1f} proxy · {:.1f} orig · {:.1f} probe /px", row.rays.proxy / px,
                     row.rays.original / px, row.rays.probe / px)});
  }
  return {renders, errors, costs};
}

LogLogPlot mseTimePlot(const std::vector<ReportRow>& rows) {
  LogLogPlot plot;
  plot.title = "MSE against render time (log-log; lower left is better)";
  plot.x_label = "time per render (s)";
  plot.y_label = "MSE";
  for (const ReportRow& r : rows) {
    auto it = std::find_if(plot.series.begin(), plot.series.end(),
                           [&](const PlotSeries& s) { return s.name == r.estimator; });
    if (it == plot.series.end()) {
      plot.series.push_back({r.estimator, {}});
      it = plot.series.end() - 1;
    }
    it->points.push_back({r.seconds, r.mse, fmt::format("{} {:.0f} spp", r.table, r.spp)});
  }
  return plot;
}

}  // namespace proxyvis
