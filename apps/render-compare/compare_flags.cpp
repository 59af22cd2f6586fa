#include "compare_flags.h"

#include "util/error.h"

namespace proxyvis {

namespace fs = std::filesystem;

namespace {

std::string absoluteText(const std::string& path) {
  return fs::absolute(path).lexically_normal().string();
}

}  // namespace

void addCompareOptions(CLI::App& app, CompareOptions& o) {
  app.add_option("scene", o.scene, "Scene file (JSON, scenes/FORMAT.md)")->required();
  app.add_option("--out", o.out,
                 "Output folder (created if missing; each run replaces it as a whole)")
      ->required();
  app.add_option("--estimators", o.estimators, "Comma-separated estimators")->capture_default_str();
  app.add_option("--spp", o.spp,
                 "Comma-separated light samples per pixel for the equal-sample table")
      ->capture_default_str();
  app.add_option("--equal-time", o.equal_time,
                 "Seconds per render for the equal-time table (0 = no such table)")
      ->check(numberIn(0, kMaxRenderSeconds))
      ->capture_default_str();
  app.add_option("--reference-spp", o.reference_spp,
                 "Samples per pixel of the exact reference. 0 = automatic: 16 x the most samples "
                 "any compared render reached (equal-time renders included), at least 1024, "
                 "rounded up to a power of two. Either is rounded up to a multiple of its 16 "
                 "partial renders; a cached reference with at least as many samples is reused")
      ->check(integerIn(0, kMaxSpp))
      ->capture_default_str();
  app.add_option("--seeds", o.seeds,
                 "Independent renders per table cell (standard error over them)")
      ->check(integerIn(1, kMaxSeeds))
      ->capture_default_str();
  app.add_option("--repeats", o.repeats,
                 "Times the equal-time schedule is run (each with new seeds): seeds x repeats "
                 "runs per equal-time cell, and the efficiency's run-to-run spread over them")
      ->check(integerIn(1, kMaxRepeats))
      ->capture_default_str();
  addRenderFlags(app, o.render);
  addCommonOptions(app, o.common);
}

std::vector<std::string> studyArgs(const CLI::App& app, const CompareOptions& o) {
  std::vector<std::string> args;
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->count() == 0) continue;
    if (opt->get_positional()) {
      args.push_back(absoluteText(o.scene.string()));
      continue;
    }
    PV_CHECK_MSG(!opt->get_lnames().empty(), "every render-compare option has a long name");
    const std::string name = "--" + opt->get_lnames().front();
    if (name == "--plan" || name == "--help" || name == "--version") continue;
    // One "--name=value" per value given: flags read back their "true" this way too.
    for (const std::string& value : opt->results())
      args.push_back(
          name + "=" +
          (name == "--out" || (name == "--json" && value != "-") ? absoluteText(value) : value));
  }
  return args;
}
void parseStudyArgs(const std::vector<std::string>& args, CompareOptions& options,
                    const fs::path& file) {
  CLI::App app{"render-compare", "render-compare"};
  addCompareOptions(app, options);
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 parses from the back
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    throw Error(file.string(), "not a render-compare plan",
                std::string("its render-compare flags do not parse: ") + e.what(),
                "write it again with render-compare SCENE ... --plan DIR");
  }
  options.resolve();
}

}  // namespace proxyvis
