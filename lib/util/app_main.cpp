#include "util/app_main.h"

#include <charconv>
#include <cmath>
#include <string>

#include <fmt/core.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <new>
#include <optional>

#include "util/error.h"
#include "util/output_path.h"
#include "util/progress.h"
#include "util/temp_files.h"

namespace proxyvis {

void addCommonOptions(CLI::App& app, CommonOptions& options) {
  app.set_version_flag("--version", std::string("proxyvis ") + PROXYVIS_VERSION);
  app.add_option("--seed", options.seed,
                 "Random seed; the same seed gives the same result at any thread count")
      ->check(integerIn(0, std::numeric_limits<uint64_t>::max()))
      ->capture_default_str();
  app.add_option("--threads", options.threads, "Worker threads (0 = all cores)")
      ->check(integerIn(0, 4096))
      ->capture_default_str();
  app.add_flag("-q,--quiet", options.quiet, "No progress bars");
  app.add_option("--json", options.json_path,
                 "Write the report as JSON to this file ('-' = stdout)");
  app.footer(
      "Exit codes: 0 success, 1 a check failed, 2 bad input or usage, 3 output cannot be "
      "written.\nOutputs are written to a temporary file and renamed at the end: nothing partial "
      "is left on failure.");
}

std::optional<double> parseNumber(const std::string& text) {
  double v = 0;
  size_t used = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used != text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

namespace {
CLI::Validator numberCheck(bool allow_zero) {
  return CLI::Validator(
      [allow_zero](std::string& text) -> std::string {
        const std::optional<double> parsed = parseNumber(text);
        if (!parsed) return "expected a number, got '" + text + "'";
        const double v = *parsed;
        if (allow_zero ? v < 0 : v <= 0)
          return std::string(allow_zero ? "must be >= 0" : "must be > 0") + ", got " + text;
        return {};
      },
      allow_zero ? "NONNEGATIVE" : "POSITIVE");
}
}  // namespace

CLI::Validator numberIn(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        const std::optional<double> parsed = parseNumber(text);
        if (!parsed) return "expected a number, got '" + text + "'";
        if (*parsed < lo || *parsed > hi)
          return fmt::format("must be in [{}, {}], got {}", lo, hi, text);
        return {};
      },
      fmt::format("[{}, {}]", lo, hi));
}

CLI::Validator integerIn(uint64_t lo, uint64_t hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        uint64_t v = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, v);
        const bool digits_only =
            !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        if (!digits_only || ptr != end)
          return fmt::format("expected a whole number in [{}, {}], got '{}'", lo, hi, text);
        if (ec == std::errc::result_out_of_range || v < lo || v > hi)
          return fmt::format("must be in [{}, {}], got {}", lo, hi, text);
        return {};
      },
      fmt::format("INT in [{}, {}]", lo, hi));
}

void addGltfPickOptions(CLI::App& app, std::string& mesh, std::string& node) {
  CLI::Option* m = app.add_option(
      "--mesh", mesh, "glTF input: take only the mesh with this name, in its own coordinates");
  CLI::Option* n = app.add_option(
      "--node", node,
      "glTF input: take only the node with this name and its children, in world coordinates "
      "(default: the whole default scene)");
  m->excludes(n);
}

void addCompressionOptions(CLI::App& app, std::string& compress, int& draco_bits,
                           const std::string& bits_note) {
  app.add_option("--compress", compress,
                 "glTF output: none, draco (KHR_draco_mesh_compression) or meshopt "
                 "(EXT_meshopt_compression, exact)")
      ->check(CLI::IsMember({"none", "draco", "meshopt"}))
      ->capture_default_str();
  app.add_option(
         "--draco-bits", draco_bits,
         "Draco output (.drc, or --compress draco): position quantization bits " + bits_note)
      ->check(integerIn(0, 30))
      ->capture_default_str();
}

CLI::Validator positiveNumber() {
  return numberCheck(false);
}
CLI::Validator nonNegativeNumber() {
  return numberCheck(true);
}

namespace {

// This process's rank when a launcher (mpirun, srun) started it among others, else 0.
int launcherRank() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK", "SLURM_PROCID"})
    if (const char* value = std::getenv(name))
      if (const std::optional<double> rank = parseNumber(value); rank && *rank >= 1) return 1;
  return 0;
}

}  // namespace

int runApp(CLI::App& app, int argc, char** argv, const CommonOptions& options,
           const std::function<int()>& body) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // One line, like every other error: program, what is wrong, what to do. Under an MPI or
    // Slurm launcher every task parses the same command line, so only the first says it.
    if (launcherRank() > 0) return kExitBadInput;
    std::fprintf(stderr, "%s: error: %s (run %s --help for usage)\n", app.get_name().c_str(),
                 printableText(e.what()).c_str(), app.get_name().c_str());
    return kExitBadInput;
  }
  Progress::setGloballyQuiet(options.quiet);
  removeTemporariesOnTerminatingSignals();
  const std::string name = app.get_name();
  try {
    int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return body();
  } catch (const std::exception& e) {
    const ErrorReport report = errorReport(e);
    std::fprintf(stderr, "%s: error: %s\n", name.c_str(), report.message.c_str());
    return report.exit_code;
  }
}

bool jsonOnStdout(const CommonOptions& options) {
  if (options.json_path.empty()) return false;
  try {
    const OutputTarget target = resolveOutputTarget(options.json_path);
    return target.kind == OutputTarget::Kind::kStream && target.fd == 1;
  } catch (const Error&) {
    return false;
  }
}

void printHumanReport(const CommonOptions& options, const std::string& text) {
  if (!jsonOnStdout(options)) {
    std::fputs(text.c_str(), stdout);
  } else if (!options.quiet) {
    std::fputs(text.c_str(), stderr);
  }
}

}  // namespace proxyvis
