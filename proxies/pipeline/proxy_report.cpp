#include "proxies/pipeline/proxy_report.h"

#include "proxies/pipeline/json_visit.h"

namespace proxyvis {

using json = nlohmann::json;

// The keys of each part of the report (json_visit.h): one list for writing and reading.

template <typename V>
void fields(ProxyInputFacts& in, V& v) {
  v("path", in.path);
  v("faces", in.faces);
  v("closed", in.closed);
  v("watertight", in.watertight);
  v("manifold", in.manifold);
  v("boundary_edges", in.boundary_edges);
}

template <typename V>
void fields(ProxyParameters& p, V& v) {
  v("max_faces", p.max_faces);
  v("fill_holes", p.fill_holes);
  v("seed", p.seed);
  v("budget", p.budget);
  v("max_seconds", p.max_seconds);
  v("hull_epsilon", p.hull_epsilon);
  v("alpha", p.alpha);
  v("offset", p.offset);
  v("erosion", p.erosion);
  v("voxel", p.voxel);
  v("ratio", p.ratio);
  v("parts", p.parts);
  v("parts_epsilon", p.parts_epsilon);
  v("max_faces_from_ratio", p.max_faces_from_ratio);
  v("min_faces", p.min_faces);
  v("max_faces_auto", p.max_faces_auto);
  v("clearance", p.clearance);
  v("clearance_ulps", p.clearance_ulps);
}

template <typename V>
void fields(BudgetAttempt& a, V& v) {
  v("source", a.source);
  v("max_move_edges", a.max_move_edges);
  v("faces", a.faces);
  v("closed", a.closed);
  v("manifold", a.manifold);
  v("self_intersecting_pairs", a.self_intersecting_pairs);
  v("containment", a.containment);
}

template <typename V>
void fields(ProxyChecks& c, V& v) {
  v("closed", c.closed);
  v("manifold", c.manifold);
  v("self_intersecting_pairs", c.self_intersecting_pairs);
  v("containment", c.containment);
  v("containment_detail", c.containment_detail);
  v("containment_against", c.containment_against);
  v("clearance", c.clearance);
  v("separation", c.separation);
  v("containment_double", c.containment_double);
}

template <typename V>
void fields(WrittenCheck& w, V& v) {
  v("containment", w.containment);
  v("detail", w.detail);
}

template <typename V>
void fields(ProxyReport& r, V& v) {
  v("input", r.input);
  v("kind", r.kind);
  v("method", r.method);
  v("parameters", r.parameters);
  v("seconds", r.seconds);
  v("holes_filled", r.holes_filled);
  v("seeds", r.seeds);
  v("voxels", r.voxels);
  v("parts", r.parts);
  v("faces_before_budget", r.faces_before_budget);
  v.nonEmpty("budget_attempts", r.budget_attempts);
  v.nonEmpty("budget_ladder", r.budget_ladder);
  v("budget_fallback", r.budget_fallback);
  v("budget_reached", r.budget_reached);
  v("checks", r.checks);
  v("faces", r.faces);
  v("verified", r.verified);
  v.nullable("class", r.written_class);
  v("class_reason", r.class_reason);
  v.nullable("volume_ratio", r.volume_ratio);
  v("hausdorff_proxy_to_original", r.hausdorff_proxy_to_original);
  v("hausdorff_original_to_proxy", r.hausdorff_original_to_proxy);
  v("hausdorff", r.hausdorff);
  v("written_check", r.written_check);
  v("output", r.output);
  v("output_sha256", r.output_sha256);
  v("report_html", r.report_html);
}

// A ladder entry is either skipped (that key alone) or a checked candidate.
json toJsonValue(const LadderEntry& e) {
  if (e.skipped) return {{"skipped", *e.skipped}};
  json j = {{"source", e.source}, {"faces", e.faces}, {"verified", e.verified}};
  if (e.volume_ratio) j["volume_ratio"] = *e.volume_ratio;
  return j;
}

LadderEntry readAs(const Field& f, Tag<LadderEntry>) {
  LadderEntry e;
  FieldReader read{f};
  read("skipped", e.skipped);
  if (e.skipped) return e;
  read("source", e.source);
  read("faces", e.faces);
  read("verified", e.verified);
  read("volume_ratio", e.volume_ratio);
  return e;
}

// The distances with their unit (proxies/check/distance_report.h); the derived keys are not read.
json toJsonValue(const HausdorffDistances& h) {
  return hausdorffJson(h);
}

HausdorffDistances readAs(const Field& f, Tag<HausdorffDistances>) {
  return {f["original_to_proxy"].asDouble(), f["proxy_to_original"].asDouble(),
          f["diagonal"].asDouble()};
}

void addLoadSeconds(ProxyReport& report, double load_seconds) {
  report.seconds["load"] = load_seconds;
  report.seconds["total"] += load_seconds;
}

void to_json(json& j, const ProxyReport& r) {
  j = toJsonValue(r);
}

ProxyReport readProxyReport(const Field& f) {
  return readFields<ProxyReport>(f);
}

void from_json(const json& j, ProxyReport& r) {
  r = readWithoutFile(j, readProxyReport);
}

void to_json(json& j, const SceneMeshReport& r) {
  j = r.proxy ? toJsonValue(*r.proxy) : json::object();
  JsonWriter write{j};
  write("name", r.name);
  write("cache", r.cache);
  write("skipped", r.skipped);
  write("faces", r.faces);
  write("error", r.error);
}

SceneMeshReport readSceneMeshReport(const Field& f) {
  SceneMeshReport r;
  FieldReader read{f};
  read("name", r.name);
  read("cache", r.cache);
  read("skipped", r.skipped);
  read("error", r.error);
  if (r.skipped || r.error)
    read("faces", r.faces);
  else
    r.proxy = readProxyReport(f);
  return r;
}

void from_json(const json& j, SceneMeshReport& r) {
  r = readWithoutFile(j, readSceneMeshReport);
}

}  // namespace proxyvis
