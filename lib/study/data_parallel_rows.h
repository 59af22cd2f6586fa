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
  // The renders' figures over the seeds (addSeed), serialized by dataParallelRow as render's
  // are: shadow segments, forwards and routed segments summed over the seeds (forwards per
  // segment is their ratio), bytes and messages per render, seconds and the model means over
  // the seeds, the largest peak RSS, emulated if a render's exchange waited; the rest is the
  // first seed's.
  DataParallelStats stats;
  double mse = 0;  // mean over the seeds
  double efficiency = 0, modelled_efficiency = 0, relative = 0, modelled_relative = 0;

  // Adds one seed's render (the first one sets the figures that are not summed).
  void addSeed(const DataParallelStats& s, bool first);
  // After the last of `seeds` seeds: sums to means where the row gives means.
  void finishSeeds(int seeds);
  bool emulated() const { return stats.emulated; }
};

// "<estimator>_<forwarding>_<spp>spp[_emulated]": the row's images without extension.
std::string imageName(const Row& r);

// The rows as the report's table (report.md and report.html); `network` names the modelled
// fabric.
TextTable studyTable(const std::vector<Row>& rows, const std::string& network);

}  // namespace proxyvis::dp_study
