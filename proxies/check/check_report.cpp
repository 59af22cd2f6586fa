#include "proxies/check/check_report.h"

#include <fmt/core.h>

#include <nlohmann/json.hpp>
#include <optional>

#include "proxies/check/distance_report.h"
#include "util/atomic_write.h"
#include "util/error.h"
#include "util/output_set.h"

namespace proxyvis {

namespace {

std::string rateLine(const char* name, const RateEstimate& e, const char* meaning) {
  if (e.n == 0)
    return fmt::format("  {:<16} {:>12}  {:<26} {}\n", name, "n/a", "(no segments)", meaning);
  return fmt::format("  {:<16} {:>12.6f}  [{:.6f}, {:.6f}]   {}\n", name, e.value, e.ci.lo, e.ci.hi,
                     meaning);
}

// Why an open mesh has no volume: "closed" here is the exact check's ray-parity test.
constexpr const char* kOpenMeshNote =
    "open: some edge has an odd number of faces (a boundary), so the surface bounds no volume";

std::string meshLine(const char* role, const MeshSummary& m) {
  const std::string volume =
      m.closed ? fmt::format("volume {:.6g}", m.volume) : std::string("no volume (open)");
  return fmt::format("  {:<9} {:>9} faces {:>9} vertices  {:<6}  {:<18}  {}\n", role, m.faces,
                     m.vertices, m.closed ? "closed" : "open", volume, m.source);
}

// The volume ratio proxy/original, or why there is none.
std::optional<double> volumeRatio(const PairCheckReport& r) {
  if (r.original.closed && r.proxy.closed && r.original.volume > 0)
    return r.proxy.volume / r.original.volume;
  return std::nullopt;
}
std::string noVolumeRatioReason(const PairCheckReport& r) {
  if (!r.original.closed && !r.proxy.closed) return "both meshes are open: neither bounds a volume";
  if (!r.original.closed) return "the original is open: it bounds no volume";
  if (!r.proxy.closed) return "the proxy is open: it bounds no volume";
  return "the original's volume is zero";
}

HausdorffDistances distances(const PairCheckReport& r) {
  return {r.distance_original_to_proxy, r.distance_proxy_to_original, r.original_diagonal};
}

nlohmann::json rateJson(const RateEstimate& e) {
  nlohmann::json j = {{"k", e.k}, {"n", e.n}, {"lo", rateLower(e)}, {"hi", rateUpper(e)}};
  j["value"] = e.n == 0 ? nlohmann::json(nullptr) : nlohmann::json(e.value);
  return j;
}

nlohmann::json valueOrNull(const RateEstimate& e) {
  return e.n == 0 ? nlohmann::json(nullptr) : nlohmann::json(e.value);
}

nlohmann::json meshJson(const MeshSummary& m) {
  nlohmann::json j = {
      {"file", m.source}, {"faces", m.faces}, {"vertices", m.vertices}, {"closed", m.closed}};
  j["volume"] = m.closed ? nlohmann::json(m.volume) : nlohmann::json(nullptr);
  if (!m.closed) j["volume_note"] = kOpenMeshNote;
  return j;
}

}  // namespace

double rateLower(const RateEstimate& e) {
  return e.n == 0 ? 0.0 : e.ci.lo;
}

double rateUpper(const RateEstimate& e) {
  return e.n == 0 ? 1.0 : e.ci.hi;
}

nlohmann::json countsJson(const ClassCounts& c) {
  return {{"HH", c.hh}, {"HM", c.hm}, {"MH", c.mh}, {"MM", c.mm}};
}

std::optional<MissedClassBound> missedClassBound(const PairCheckReport& r) {
  switch (r.sampled_class) {
    case SampledClass::kOutside:
      return MissedClassBound{"HM'", r.stats.hm.ci.hi};
    case SampledClass::kInside:
      return MissedClassBound{"MH'", r.stats.mh.ci.hi};
    case SampledClass::kEquivalent:
      return MissedClassBound{"HM'+MH'", r.stats.error.ci.hi};
    case SampledClass::kGeneral:
      return std::nullopt;
  }
  return std::nullopt;
}

std::string formatHumanReport(const PairCheckReport& r) {
  const ClassCounts& c = r.sampled.counts;
  const ClassStats& s = r.stats;
  std::string out;
  if (!r.label.empty()) out += fmt::format("== {} ==\n", r.label);
  out += "Meshes\n";
  out += meshLine("original", r.original);
  out += meshLine("proxy", r.proxy);
  if (const std::optional<double> ratio = volumeRatio(r))
    out += fmt::format("  volume ratio proxy/original {:.4f}\n", *ratio);
  else
    out += fmt::format("  volume ratio proxy/original: none ({})\n", noVolumeRatioReason(r));
  out += fmt::format("  Hausdorff distance (sampled, a lower bound): {}\n",
                     hausdorffText(distances(r)));
  out += fmt::format(
      "\nSegments: {} ({} distribution, seed {}{})\n", c.total(), r.distribution, r.seed,
      r.sampled.skipped
          ? fmt::format(", {} attempts: {} gave no segment", r.sampled.attempts, r.sampled.skipped)
          : "");
  if (r.shortfall) out += fmt::format("  WARNING: {}\n", *r.shortfall);
  out += fmt::format("  {}\n", r.distribution_note);
  out += fmt::format("  {:<6} {:>12} {:>10}  {:<24}  {}\n", "class", "count", "fraction",
                     "95 % interval", "meaning");
  auto row = [&](const char* name, uint64_t k, const RateEstimate& e, const char* meaning) {
    out += fmt::format("  {:<6} {:>12} {:>10.6f}  [{:.6f}, {:.6f}]  {}\n", name, k, e.value,
                       e.ci.lo, e.ci.hi, meaning);
  };
  row("HH'", c.hh, s.hh, "both block");
  row("HM'", c.hm, s.hm, "original blocks, proxy misses (error)");
  row("MH'", c.mh, s.mh, "original misses, proxy blocks (error)");
  row("MM'", c.mm, s.mm, "both miss");
  out += "\nDerived (value, 95 % Wilson interval)\n";
  out += rateLine("V_avg", s.v_avg, "P(V = 1)");
  out += rateLine("f_hit", s.f_hit, "HH' / (HH' + HM')");
  out += rateLine("f_miss", s.f_miss, "MM' / (MH' + MM')");
  out += rateLine("P(err|V'=0)", s.error_given_v0, "MH' / (HH' + MH')");
  out += rateLine("P(err|V'=1)", s.error_given_v1, "HM' / (HM' + MM')");
  out += rateLine("P(H'|M)", s.wasted_forward,
                  "MH' / (MH' + MM'): hits the proxy, misses the original (outside: a wasted "
                  "forward)");
  out += rateLine("P(M'|H)", s.missed_block,
                  "HM' / (HH' + HM'): misses the proxy, hits the original (inside: a block "
                  "missed)");
  out += fmt::format(
      "  cost ratio c_p/c_o {:.3f}  (proxy {:.1f} ns, original {:.1f} ns per segment; "
      "{:.2f} M classified segments/s)\n",
      r.sampled.costRatio(),
      1e9 * r.sampled.seconds_proxy / double(std::max<uint64_t>(1, c.total())),
      1e9 * r.sampled.seconds_original / double(std::max<uint64_t>(1, c.total())),
      double(c.total()) / std::max(1e-9, r.sampled.seconds) / 1e6);
  out += "\nVerdicts\n";
  out += fmt::format("  sampled class  {}", sampledClassName(r.sampled_class));
  if (r.sampled_class == SampledClass::kEquivalent) out += " on these rays";
  if (auto b = missedClassBound(r))
    out += fmt::format("  (no {} seen; its rate is below {:.3g} at 95 %)", b->name, b->upper);
  out += "\n";
  out += fmt::format("  exact          {}  ({:.2f} s, {} reading{}): {}\n",
                     containmentName(r.exact.verdict), r.exact_seconds,
                     r.precision == "double" ? "double" : "float",
                     r.precision == "float" ? " only" : "", r.exact.detail);
  if (r.exact_double)
    out += fmt::format("  exact, double  {}: {}\n", containmentName(r.exact_double->verdict),
                       r.exact_double->detail);
  if (r.precision_mismatch)
    out += fmt::format("  !!! READINGS DISAGREE: {} !!!\n", *r.precision_mismatch);
  if (r.exact_placed)
    out += fmt::format("  exact, placed  {} (the placed float copies the renderer traces): {}\n",
                       containmentName(r.exact_placed->verdict), r.exact_placed->detail);
  if (r.placed_mismatch)
    out += fmt::format("  !!! PLACED COPIES DISAGREE: {} !!!\n", *r.placed_mismatch);
  if (r.mismatch) out += fmt::format("  !!! MISMATCH: {} !!!\n", *r.mismatch);
  if (r.expected)
    out += fmt::format("  expected       {}: {}\n", proxyClassName(*r.expected),
                       r.contradiction ? "CONTRADICTED (" + *r.contradiction + ")" : "consistent");
  return out;
}

nlohmann::json toJson(const PairCheckReport& r) {
  const ClassCounts& c = r.sampled.counts;
  const ClassStats& s = r.stats;
  nlohmann::json j;
  if (!r.label.empty()) j["label"] = r.label;
  j["counts"] = countsJson(c);
  j["V_avg"] = valueOrNull(s.v_avg);
  j["f_hit"] = valueOrNull(s.f_hit);
  j["f_miss"] = valueOrNull(s.f_miss);
  j["P_error_given_V0"] = valueOrNull(s.error_given_v0);
  j["P_error_given_V1"] = valueOrNull(s.error_given_v1);
  j["P_hit_proxy_given_miss_original"] = valueOrNull(s.wasted_forward);
  j["P_miss_proxy_given_hit_original"] = valueOrNull(s.missed_block);
  j["intervals"] = {{"level", 0.95},
                    {"method", "wilson"},
                    {"HH", rateJson(s.hh)},
                    {"HM", rateJson(s.hm)},
                    {"MH", rateJson(s.mh)},
                    {"MM", rateJson(s.mm)},
                    {"V_avg", rateJson(s.v_avg)},
                    {"f_hit", rateJson(s.f_hit)},
                    {"f_miss", rateJson(s.f_miss)},
                    {"P_error_given_V0", rateJson(s.error_given_v0)},
                    {"P_error_given_V1", rateJson(s.error_given_v1)},
                    {"P_hit_proxy_given_miss_original", rateJson(s.wasted_forward)},
                    {"P_miss_proxy_given_hit_original", rateJson(s.missed_block)},
                    {"error", rateJson(s.error)}};
  j["sampled_class"] = sampledClassName(r.sampled_class);
  if (auto b = missedClassBound(r))
    j["missed_class_upper_bound"] = {{"class", b->name}, {"rate", b->upper}};
  j["exact"] = containmentName(r.exact.verdict);
  j["exact_detail"] = r.exact.detail;
  j["exact_seconds"] = r.exact_seconds;
  j["intersecting_face_pairs"] = r.exact.intersecting_face_pairs;
  j["precision"] = r.precision;
  if (r.exact_double) {
    j["exact_double"] = containmentName(r.exact_double->verdict);
    j["exact_double_detail"] = r.exact_double->detail;
  }
  j["precision_mismatch"] =
      r.precision_mismatch ? nlohmann::json(*r.precision_mismatch) : nlohmann::json(nullptr);
  if (r.exact_placed) {
    j["exact_placed"] = containmentName(r.exact_placed->verdict);
    j["exact_placed_detail"] = r.exact_placed->detail;
    j["placed_mismatch"] =
        r.placed_mismatch ? nlohmann::json(*r.placed_mismatch) : nlohmann::json(nullptr);
  }
  j["mismatch"] = r.mismatch ? nlohmann::json(*r.mismatch) : nlohmann::json(nullptr);
  if (r.expected) {
    j["expect"] = proxyClassName(*r.expected);
    j["contradiction"] =
        r.contradiction ? nlohmann::json(*r.contradiction) : nlohmann::json(nullptr);
  }
  j["ok"] = !r.failed();
  j["cost_ratio"] = r.sampled.costRatio();
  j["seconds_proxy"] = r.sampled.seconds_proxy;
  j["seconds_original"] = r.sampled.seconds_original;
  j["seed"] = r.seed;
  j["rays"] = c.total();
  j["rays_requested"] = r.rays_requested;
  j["attempts"] = r.sampled.attempts;
  j["skipped"] = r.sampled.skipped;
  j["shortfall"] = r.shortfall ? nlohmann::json(*r.shortfall) : nlohmann::json(nullptr);
  j["distribution"] = r.distribution;
  j["seconds"] = r.seconds;
  j["original"] = meshJson(r.original);
  j["proxy"] = meshJson(r.proxy);
  const std::optional<double> ratio = volumeRatio(r);
  j["volume_ratio"] = ratio ? nlohmann::json(*ratio) : nlohmann::json(nullptr);
  if (!ratio) j["volume_ratio_note"] = noVolumeRatioReason(r);
  j["hausdorff"] = hausdorffJson(distances(r));
  return j;
}

bool SceneCheckReport::ok() const {
  for (const PairCheckReport* r : checks)
    if (r->failed()) return false;
  return true;
}

nlohmann::json toJson(const SceneCheckReport& s) {
  nlohmann::json checks = nlohmann::json::array();
  for (const PairCheckReport* r : s.checks) checks.push_back(toJson(*r));
  return {
      {"scene", s.scene}, {"seed", s.seed}, {"rays", s.rays}, {"checks", checks}, {"ok", s.ok()}};
}

void writeErrorSegmentsPly(const std::vector<ErrorSegment>& segments,
                           const std::filesystem::path& path) {
  std::string text =
      "ply\nformat ascii 1.0\ncomment proxy-check error segments: red = HM' (original blocks, "
      "proxy misses), blue = MH' (original misses, proxy blocks)\n";
  text += fmt::format(
      "element vertex {}\nproperty float x\nproperty float y\nproperty float z\n"
      "property uchar red\nproperty uchar green\nproperty uchar blue\n",
      2 * segments.size());
  text += fmt::format(
      "element edge {}\nproperty int vertex1\nproperty int vertex2\n"
      "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n",
      segments.size());
  auto color = [](const ErrorSegment& s) { return s.hm ? "255 0 0" : "0 0 255"; };
  for (const ErrorSegment& s : segments)
    for (const Vec3f& p : {s.a, s.b}) text += fmt::format("{} {} {} {}\n", p.x, p.y, p.z, color(s));
  for (size_t i = 0; i < segments.size(); ++i)
    text += fmt::format("{} {} {}\n", 2 * i, 2 * i + 1, color(segments[i]));
  // writeFileBytes reports the system's reason (no space, permission) for the path given.
  writeAtomically(
      path, [&](const std::filesystem::path& tmp) { writeFileBytes(tmp, text, path.string()); });
}

}  // namespace proxyvis
