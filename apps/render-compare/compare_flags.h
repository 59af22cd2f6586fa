#pragma once
// render-compare's command line: the study's flags (study/compare_options.h) as CLI11 options, and
// the flags a plan keeps (plan.json "args") so that a unit or the merge parses the same study.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "study/compare_options.h"

namespace proxyvis {

void addCompareOptions(CLI::App& app, CompareOptions& options);

// The flags as given, without --plan, with the scene, --out and --json absolute, so
// that a unit run from another folder sees the same study.
// `app` is the parsed command line (its --plan, --help and --version are left out).
std::vector<std::string> studyArgs(const CLI::App& app, const CompareOptions& options);

// Parses `args` as render-compare's flags into `options` (resolved); throws Error naming `file`.
void parseStudyArgs(const std::vector<std::string>& args, CompareOptions& options,
                    const std::filesystem::path& file);

}  // namespace proxyvis
