#pragma once
// What every proxyvis app shares: the standard flags (--version, --seed, --threads, --quiet,
// --json) and the mapping from errors to exit codes (0 ok, 1 check failed, 2 bad input or usage,
// 3 cannot write output).
#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace proxyvis {

// Number checks whose messages read well ("--alpha: must be > 0, got -1"); CLI11's own ones
// print the range up to the largest double.
// The whole of `text` as a finite number; nullopt for anything else ("1x", "", "nan").
std::optional<double> parseNumber(const std::string& text);
CLI::Validator positiveNumber();
CLI::Validator nonNegativeNumber();
// A number in [lo, hi]; the message names the range ("--alpha: must be in [0.001, 1], got 5").
CLI::Validator numberIn(double lo, double hi);
// An integer written as decimal digits only (no sign, exponent or fraction) in [lo, hi]. CLI11
// alone turns "-1" into 2^64-1 and saturates 2^64 for unsigned options; this runs before it.
CLI::Validator integerIn(uint64_t lo, uint64_t hi);

// The output compression flags of the programs that write meshes: --compress none|draco|meshopt
// (glTF outputs) and --draco-bits N (Draco quantization; `bits_note` says what the program does
// with it). mesh/io/mesh_io.h's parseGltfCompression reads `compress`.
void addCompressionOptions(CLI::App& app, std::string& compress, int& draco_bits,
                           const std::string& bits_note);

// --mesh NAME and --node NAME: what to take of a glTF input (mesh/io/mesh_io.h's GltfPick).
void addGltfPickOptions(CLI::App& app, std::string& mesh, std::string& node);

struct CommonOptions {
  uint64_t seed = 0;
  int threads = 0;  // 0 = all hardware threads
  bool quiet = false;
  std::string json_path;  // empty = no JSON; "-" = stdout
};

// Adds the standard flags to `app` and the exit-code table to its footer.
void addCommonOptions(CLI::App& app, CommonOptions& options);

// True if --json writes to stdout ("-", /dev/stdout): then stdout carries only the JSON.
bool jsonOnStdout(const CommonOptions& options);

// The human-readable report: to stdout, or to stderr (unless --quiet) when the JSON owns stdout.
void printHumanReport(const CommonOptions& options, const std::string& text);

// Parses argv and runs `body` under a TBB arena limited to options.threads. Exceptions become
// one line on stderr ("<app>: error: <message>") and the documented exit code. A terminating
// signal (SIGINT, SIGTERM, SIGHUP) removes the run's temporary files before the process dies. CLI11
// parse errors exit through app.exit(), with usage errors mapped to exit code 2.
int runApp(CLI::App& app, int argc, char** argv, const CommonOptions& options,
           const std::function<int()>& body);

}  // namespace proxyvis
