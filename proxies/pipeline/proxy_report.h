#pragma once
// proxy-gen's report of one proxy (docs/proxy_reports.md): what generateProxy found, and what
// proxy-gen adds when it writes the proxy. The same JSON goes to --json, the proxy cache, shard
// manifests and a glTF's proof; to_json writes it and from_json reads it back key by key through
// the path-tracking Field reader, so a wrong or missing key is an error that names it.
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "proxies/check/distance_report.h"
#include "util/proxy_class.h"

namespace proxyvis {

class JsonField;

// The input's facts ("input").
struct ProxyInputFacts {
  std::string path;
  uint64_t faces = 0;
  bool closed = false, watertight = false, manifold = false;
  uint64_t boundary_edges = 0;
  bool operator==(const ProxyInputFacts&) const = default;
};

// The settings the proxy was built with ("parameters"); a size is there only when the method
// read it, a budget key only when that budget applied.
struct ProxyParameters {
  uint64_t max_faces = 0;
  bool fill_holes = false;
  uint64_t seed = 0;
  std::optional<double> max_seconds;
  std::optional<double> hull_epsilon, alpha, offset, erosion, voxel, ratio;
  std::optional<uint64_t> parts;        // convex-parts: the most pieces asked for
  std::optional<double> parts_epsilon;  // convex-parts: the pieces' growth (of the diagonal)
  std::optional<uint64_t> max_faces_from_ratio, min_faces;  // outside/inside with --ratio
  std::optional<uint64_t> max_faces_auto;                   // the input's count, as a goal
  std::string budget;                                       // "hard" or "soft"
  std::optional<double> clearance;       // outside/inside: --clearance, in scene units
  std::optional<double> clearance_ulps;  // or its ulps (given, or the default)
  bool operator==(const ProxyParameters&) const = default;
};

// One reduction of the built proxy to the budget ("budget_attempts").
struct BudgetAttempt {
  std::string source;
  double max_move_edges = 0;
  uint64_t faces = 0;
  bool closed = false, manifold = false;
  uint64_t self_intersecting_pairs = 0;
  std::string containment;  // a verdict, or "n/a" for general proxies
  bool operator==(const BudgetAttempt&) const = default;
};

// One candidate of the budget ladder ("budget_ladder"): checked, or skipped with the reason.
struct LadderEntry {
  std::optional<std::string> skipped;  // when set, the only key
  std::string source;
  uint64_t faces = 0;
  bool verified = false;
  std::optional<double> volume_ratio;
  bool operator==(const LadderEntry&) const = default;
};

// The checks of the chosen proxy ("checks").
struct ProxyChecks {
  bool closed = false, manifold = false;
  uint64_t self_intersecting_pairs = 0;
  std::optional<std::string> containment, containment_detail;  // outside/inside
  std::optional<std::string> containment_against;  // "the hole-filled input" for --fill-holes
  // Outside/inside: the clearance the proof holds with (scene units) and the surfaces' measured
  // separation (at least the clearance; measured up to twice it, so 2 x clearance means "at
  // least that").
  std::optional<double> clearance, separation;
  // Outside/inside with the input read in double too: the exact check's verdict on that reading.
  std::optional<std::string> containment_double;
  bool operator==(const ProxyChecks&) const = default;
};

// The exact check of a proxy again after an encoder moved its vertices ("written_check").
struct WrittenCheck {
  std::string containment, detail;
  bool operator==(const WrittenCheck&) const = default;
};

struct ProxyReport {
  ProxyInputFacts input;
  ProxyClass kind = ProxyClass::kOutside;
  std::string method;
  ProxyParameters parameters;
  std::map<std::string, double> seconds;  // per stage (StageTimer) and "total"
  std::optional<uint64_t> holes_filled;   // --fill-holes
  std::optional<uint64_t> seeds;          // inside wrap
  std::optional<uint64_t> voxels;         // erode
  std::optional<uint64_t> parts;          // convex parts: the pieces united
  uint64_t faces_before_budget = 0;
  std::vector<BudgetAttempt> budget_attempts;  // empty: no key
  std::vector<LadderEntry> budget_ladder;      // empty: no key
  std::optional<std::string> budget_fallback;
  std::optional<bool> budget_reached;  // with a face budget
  ProxyChecks checks;
  uint64_t faces = 0;
  bool verified = false;
  std::optional<ProxyClass> written_class;  // "class": null when not verified (written_class.h)
  std::optional<std::string> class_reason;
  std::optional<double> volume_ratio;  // null when the input or the proxy bounds no volume
  // Fractions of the input's diagonal, and the same distances in scene units ("hausdorff").
  double hausdorff_proxy_to_original = 0, hausdorff_original_to_proxy = 0;
  HausdorffDistances hausdorff;
  std::optional<WrittenCheck> written_check;
  // Added by proxy-gen when it writes the proxy.
  std::optional<std::string> output, output_sha256, report_html;
  bool operator==(const ProxyReport&) const = default;
};

// A mesh of a scene run (the report's "meshes", a proxy cache entry, a shard manifest): its
// proxy's report with the scene's keys, or why it has none ({"skipped", "faces"}), or its
// failure ({"name", "error"}).
struct SceneMeshReport {
  std::optional<ProxyReport> proxy;  // its keys at the top level
  std::optional<std::string> name;   // the scene's mesh name (not in a cache entry)
  std::optional<std::string> cache;  // "cached", "generated" or "off"
  std::optional<std::string> skipped;
  std::optional<uint64_t> faces;  // with skipped, once loaded: the input's face count
  std::optional<std::string> error;
  bool operator==(const SceneMeshReport&) const = default;
};

// Loading is proxy-gen's own stage: it goes into the report's seconds (and their total, which
// then covers everything but writing).
void addLoadSeconds(ProxyReport& report, double load_seconds);

void to_json(nlohmann::json& j, const ProxyReport& r);
void from_json(const nlohmann::json& j, ProxyReport& r);
void to_json(nlohmann::json& j, const SceneMeshReport& r);
void from_json(const nlohmann::json& j, SceneMeshReport& r);

// The readers behind from_json, for a file's value: errors name the file and the key's path.
ProxyReport readProxyReport(const JsonField& f);
SceneMeshReport readSceneMeshReport(const JsonField& f);

}  // namespace proxyvis
