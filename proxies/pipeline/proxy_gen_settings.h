#pragma once
// proxy-gen's settings of one proxy as its flags give them (--kind, --method, --max-faces, ...),
// with its defaults and its help texts, in one place for the two front ends that take them:
// apps/proxy-gen binds its flags to these fields, and the Python module's proxyvis.proxy() takes
// the same names and defaults (apps/python). proxyGenOptions() turns them into the pipeline's
// options.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "proxies/pipeline/proxy_pipeline.h"

namespace proxyvis {

struct ProxyGenSettings {
  std::string kind = "outside";  // --kind: outside, inside or general
  std::string method;            // --method; empty = the kind's default
  std::optional<double> alpha, offset, ratio, erosion, voxel, clearance, clearance_ulps;
  std::optional<size_t> parts;  // --parts (convex-parts)
  std::string budget = "hard";  // --budget: hard or soft
  size_t max_faces = 0;         // --max-faces; 0 = none
  size_t min_faces = 12;        // --min-faces
  double max_seconds = 600;     // --max-seconds
  bool fill_holes = false;      // --fill-holes
};

// The pipeline's options for `settings` and --seed. Throws Error for what proxy-gen's flags
// refuse (an unknown kind or budget, --parts or --max-seconds out of range); generateProxy checks
// the sizes and the method.
ProxyGenOptions proxyGenOptions(const ProxyGenSettings& settings, uint64_t seed);

// proxy-gen's help text of a setting's flag ("--method", "--max-faces", ...), as --help prints it.
// PV_CHECK fails for a flag that has none here.
const char* proxyGenHelp(std::string_view flag);

// For positions the caller holds in double (the Python module's float64 arrays) rather than a
// file: what addDoubleReading does for a text file's decimals. Unless the kind is general or
// `positions` are exactly `input`'s float vertices (then both readings are one), moves them into
// `storage` and points options.input_double at it, so that the class is proved in both readings.
void addDoublePositions(ProxyGenOptions& options, const TriMesh& input,
                        std::vector<Vec3d> positions, std::vector<Vec3d>& storage);

}  // namespace proxyvis
