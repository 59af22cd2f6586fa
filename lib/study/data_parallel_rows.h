#pragma once
// One row of the data-parallel study (render-compare --data-parallel): what a render measured and
// modelled, its image's file name, and the study's table in Markdown and HTML (report.md and
// report.html show the same columns).
#include <cstdint>
#include <string>
#include <vector>

#include "distributed/data_parallel_render.h"
#include "study/study_page.h"

namespace proxyvis::dp_study {

struct Row {
  int spp = 0;
  std::string estimator;
  Forwarding forwarding{};
  bool emulated = false;  // the run's exchange waited for the emulated fabric
  double mse = 0, seconds = 0;
  ModelledTime modelled;                // means over seeds
  DataParallelStats stats;              // of the first seed; counts summed over seeds below
  uint64_t segments = 0, forwards = 0;  // summed over seeds
  uint64_t bytes = 0, messages = 0;     // per render (mean over seeds)
  uint64_t peak_rss = 0;
  double efficiency = 0, modelled_efficiency = 0, relative = 0, modelled_relative = 0;
};

// "<estimator>_<forwarding>_<spp>spp[_emulated]": the row's images without extension.
std::string imageName(const Row& r);

// The rows as the report's table (report.md and report.html); `network` names the modelled
// fabric.
TextTable studyTable(const std::vector<Row>& rows, const std::string& network);

}  // namespace proxyvis::dp_study
