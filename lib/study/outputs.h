#pragma once
// Everything render-compare writes besides the tables: the rendered images (EXR + PNG), the
// error and cost heat-maps (PNG), and the galleries and plot of the HTML report.
#include <filesystem>
#include <string>
#include <vector>

#include "image/image_io.h"  // autoExposure: the same for every image so they compare
#include "metrics/heat_map.h"
#include "metrics/html_report.h"
#include "study/reference.h"
#include "study/runs.h"

namespace proxyvis {

// Rays per pixel weighted by what they cost in traversals: proxy + original + 2 × probe (a probe
// is traced against both).
std::vector<float> raysPerPixel(const Image& cost);

// One log range covering several maps, so heat-maps of different estimators compare.
HeatMapRange sharedLogRange(const std::vector<const std::vector<float>*>& maps);

// The images of each cell of the report's tables, written as `stem`.exr / .png / _aov.exr /
// _error.png / _cost.png in `dir`, each with the render's metadata (render/image_metadata.h); the
// heat-maps of a table share its ranges; the AOV channels are layers "visibility.Y" and
// "rays.proxy", "rays.original", "rays.probe". The files are written in parallel; a failure
// names the first file (table by table, cell by cell, in that order) that failed.
struct CellImages {
  std::string stem;
  const CellResult* cell = nullptr;
};
struct TableImages {
  std::vector<CellImages> cells;
  HeatMapRange error_range, cost_range;
};
void writeReportImages(const std::vector<TableImages>& tables, const SceneDesc& scene,
                       const std::filesystem::path& dir, float exposure);

// A heat-map as an image for writeImage's PNG path (OIIO's colour maps are linear values that its
// sRGB curve turns into the map's published colours).
Image heatMapImage(const std::vector<float>& values, int width, int height,
                   const HeatMapRange& range);

// The colour bar image under every heat-map of the HTML report (the heat-maps' colour map, low
// values at the left), written once as `kColorBarFile` in `dir`.
inline constexpr const char* kColorBarFile = "colorbar.png";
void writeColorBar(const std::filesystem::path& dir);

// Galleries for one table: the images beside the reference, the error and the cost heat-maps
// (each with the colour bar of its range), every image linked to the files it was made from.
std::vector<HtmlGallery> cellGalleries(const std::string& title, const std::string& reference_png,
                                       const std::string& reference_exr,
                                       const std::vector<CellImages>& cells,
                                       const HeatMapRange& error_range,
                                       const HeatMapRange& cost_range);

// The report's list of every file the run writes: the tables, the reference, each cell's images.
std::vector<HtmlFileGroup> runFileGroups(const std::string& reference_png,
                                         const std::string& reference_exr,
                                         const std::vector<CellImages>& cells);

// MSE against time, one series per estimator (every row of every table).
LogLogPlot mseTimePlot(const std::vector<ReportRow>& rows);

}  // namespace proxyvis
