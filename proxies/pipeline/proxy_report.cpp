#include "proxies/pipeline/proxy_report.h"

#include "proxies/pipeline/report_fields.h"

namespace proxyvis {

using json = nlohmann::json;

namespace {

// Sets j[key] when `v` holds a value.
template <typename T>
void putOptional(json& j, const char* key, const std::optional<T>& v) {
  if (v) j[key] = *v;
}

json inputJson(const ProxyInputFacts& in) {
  return {{"path", in.path},         {"faces", in.faces},
          {"closed", in.closed},     {"watertight", in.watertight},
          {"manifold", in.manifold}, {"boundary_edges", in.boundary_edges}};
}

ProxyInputFacts readInput(const Field& f) {
  return {f["path"].asString(),     readCount(f["faces"]),  f["closed"].asBool(),
          f["watertight"].asBool(), f["manifold"].asBool(), readCount(f["boundary_edges"])};
}

json parametersJson(const ProxyParameters& p) {
  json j = {{"max_faces", p.max_faces},
            {"fill_holes", p.fill_holes},
            {"seed", p.seed},
            {"budget", p.budget}};
  putOptional(j, "max_seconds", p.max_seconds);
  putOptional(j, "hull_epsilon", p.hull_epsilon);
  putOptional(j, "alpha", p.alpha);
  putOptional(j, "offset", p.offset);
  putOptional(j, "erosion", p.erosion);
  putOptional(j, "voxel", p.voxel);
  putOptional(j, "ratio", p.ratio);
  putOptional(j, "max_faces_from_ratio", p.max_faces_from_ratio);
  putOptional(j, "min_faces", p.min_faces);
  putOptional(j, "max_faces_auto", p.max_faces_auto);
  return j;
}

ProxyParameters readParameters(const Field& f) {
  ProxyParameters p;
  p.max_faces = readCount(f["max_faces"]);
  p.fill_holes = f["fill_holes"].asBool();
  p.seed = readCount(f["seed"]);
  p.budget = f["budget"].asString();
  p.max_seconds = optionalDouble(f, "max_seconds");
  p.hull_epsilon = optionalDouble(f, "hull_epsilon");
  p.alpha = optionalDouble(f, "alpha");
  p.offset = optionalDouble(f, "offset");
  p.erosion = optionalDouble(f, "erosion");
  p.voxel = optionalDouble(f, "voxel");
  p.ratio = optionalDouble(f, "ratio");
  p.max_faces_from_ratio = optionalCount(f, "max_faces_from_ratio");
  p.min_faces = optionalCount(f, "min_faces");
  p.max_faces_auto = optionalCount(f, "max_faces_auto");
  return p;
}

json attemptJson(const BudgetAttempt& a) {
  return {{"source", a.source},
          {"max_move_edges", a.max_move_edges},
          {"faces", a.faces},
          {"closed", a.closed},
          {"manifold", a.manifold},
          {"self_intersecting_pairs", a.self_intersecting_pairs},
          {"containment", a.containment}};
}

BudgetAttempt readAttempt(const Field& f) {
  return {f["source"].asString(),     readDouble(f["max_move_edges"]),
          readCount(f["faces"]),      f["closed"].asBool(),
          f["manifold"].asBool(),     readCount(f["self_intersecting_pairs"]),
          f["containment"].asString()};
}

json ladderJson(const LadderEntry& e) {
  if (e.skipped) return {{"skipped", *e.skipped}};
  json j = {{"source", e.source}, {"faces", e.faces}, {"verified", e.verified}};
  putOptional(j, "volume_ratio", e.volume_ratio);
  return j;
}

LadderEntry readLadderEntry(const Field& f) {
  LadderEntry e;
  e.skipped = optionalString(f, "skipped");
  if (e.skipped) return e;
  e.source = f["source"].asString();
  e.faces = readCount(f["faces"]);
  e.verified = f["verified"].asBool();
  e.volume_ratio = optionalDouble(f, "volume_ratio");
  return e;
}

json checksJson(const ProxyChecks& c) {
  json j = {{"closed", c.closed},
            {"manifold", c.manifold},
            {"self_intersecting_pairs", c.self_intersecting_pairs}};
  putOptional(j, "containment", c.containment);
  putOptional(j, "containment_detail", c.containment_detail);
  putOptional(j, "containment_against", c.containment_against);
  return j;
}

ProxyChecks readChecks(const Field& f) {
  ProxyChecks c;
  c.closed = f["closed"].asBool();
  c.manifold = f["manifold"].asBool();
  c.self_intersecting_pairs = readCount(f["self_intersecting_pairs"]);
  c.containment = optionalString(f, "containment");
  c.containment_detail = optionalString(f, "containment_detail");
  c.containment_against = optionalString(f, "containment_against");
  return c;
}

ProxyClass readClass(const Field& f) {
  const std::optional<ProxyClass> c = parseProxyClass(f.asString());
  if (!c) f.fail("expected outside, inside or general");
  return *c;
}

HausdorffDistances readHausdorff(const Field& f) {
  return {readDouble(f["original_to_proxy"]), readDouble(f["proxy_to_original"]),
          readDouble(f["diagonal"])};
}

template <typename T, typename Read>
std::vector<T> readArray(const Field& parent, const char* key, Read read) {
  std::vector<T> out;
  if (!parent.has(key)) return out;
  const Field array = parent[key];
  for (size_t i = 0, n = array.arraySize(); i < n; ++i) out.push_back(read(array[i]));
  return out;
}

// The keys of what the pipeline found, without those proxy-gen adds.
void putResults(json& j, const ProxyReport& r) {
  putOptional(j, "holes_filled", r.holes_filled);
  putOptional(j, "seeds", r.seeds);
  putOptional(j, "voxels", r.voxels);
  if (!r.budget_attempts.empty())
    for (const BudgetAttempt& a : r.budget_attempts) j["budget_attempts"].push_back(attemptJson(a));
  if (!r.budget_ladder.empty())
    for (const LadderEntry& e : r.budget_ladder) j["budget_ladder"].push_back(ladderJson(e));
  putOptional(j, "budget_fallback", r.budget_fallback);
  putOptional(j, "budget_reached", r.budget_reached);
  putOptional(j, "class_reason", r.class_reason);
  if (r.written_check)
    j["written_check"] = {{"containment", r.written_check->containment},
                          {"detail", r.written_check->detail}};
}

}  // namespace

void addLoadSeconds(ProxyReport& report, double load_seconds) {
  report.seconds["load"] = load_seconds;
  report.seconds["total"] += load_seconds;
}

void to_json(json& j, const ProxyReport& r) {
  json seconds = json::object();
  for (const auto& [stage, s] : r.seconds) seconds[stage] = s;
  j = {{"input", inputJson(r.input)},
       {"kind", proxyClassName(r.kind)},
       {"method", r.method},
       {"parameters", parametersJson(r.parameters)},
       {"seconds", seconds},
       {"faces_before_budget", r.faces_before_budget},
       {"checks", checksJson(r.checks)},
       {"faces", r.faces},
       {"verified", r.verified},
       {"class", r.written_class ? json(proxyClassName(*r.written_class)) : json(nullptr)},
       {"volume_ratio", r.volume_ratio ? json(*r.volume_ratio) : json(nullptr)},
       {"hausdorff_proxy_to_original", r.hausdorff_proxy_to_original},
       {"hausdorff_original_to_proxy", r.hausdorff_original_to_proxy},
       {"hausdorff", hausdorffJson(r.hausdorff)}};
  putResults(j, r);
  putOptional(j, "output", r.output);
  putOptional(j, "output_sha256", r.output_sha256);
  putOptional(j, "report_html", r.report_html);
}

ProxyReport readProxyReport(const Field& f) {
  ProxyReport r;
  r.input = readInput(f["input"]);
  r.kind = readClass(f["kind"]);
  r.method = f["method"].asString();
  r.parameters = readParameters(f["parameters"]);
  const Field seconds = f["seconds"];
  if (!seconds.value().is_object())
    seconds.fail(std::string("expected an object, found ") + seconds.value().type_name());
  for (const auto& [stage, unused] : seconds.value().items())
    r.seconds[stage] = readDouble(seconds[stage.c_str()]);
  r.holes_filled = optionalCount(f, "holes_filled");
  r.seeds = optionalCount(f, "seeds");
  r.voxels = optionalCount(f, "voxels");
  r.faces_before_budget = readCount(f["faces_before_budget"]);
  r.budget_attempts = readArray<BudgetAttempt>(f, "budget_attempts", readAttempt);
  r.budget_ladder = readArray<LadderEntry>(f, "budget_ladder", readLadderEntry);
  r.budget_fallback = optionalString(f, "budget_fallback");
  r.budget_reached = optionalBool(f, "budget_reached");
  r.checks = readChecks(f["checks"]);
  r.faces = readCount(f["faces"]);
  r.verified = f["verified"].asBool();
  if (!f["class"].value().is_null()) r.written_class = readClass(f["class"]);
  r.class_reason = optionalString(f, "class_reason");
  r.volume_ratio = readDoubleOrNull(f["volume_ratio"]);
  r.hausdorff_proxy_to_original = readDouble(f["hausdorff_proxy_to_original"]);
  r.hausdorff_original_to_proxy = readDouble(f["hausdorff_original_to_proxy"]);
  r.hausdorff = readHausdorff(f["hausdorff"]);
  if (f.has("written_check"))
    r.written_check = WrittenCheck{f["written_check"]["containment"].asString(),
                                   f["written_check"]["detail"].asString()};
  r.output = optionalString(f, "output");
  r.output_sha256 = optionalString(f, "output_sha256");
  r.report_html = optionalString(f, "report_html");
  return r;
}

void from_json(const json& j, ProxyReport& r) {
  r = readWithoutFile(j, readProxyReport);
}

void to_json(json& j, const SceneMeshReport& r) {
  j = r.proxy ? json(*r.proxy) : json::object();
  putOptional(j, "name", r.name);
  putOptional(j, "cache", r.cache);
  putOptional(j, "skipped", r.skipped);
  putOptional(j, "faces", r.faces);
  putOptional(j, "error", r.error);
}

SceneMeshReport readSceneMeshReport(const Field& f) {
  SceneMeshReport r;
  r.name = optionalString(f, "name");
  r.cache = optionalString(f, "cache");
  r.skipped = optionalString(f, "skipped");
  r.error = optionalString(f, "error");
  if (r.skipped || r.error)
    r.faces = optionalCount(f, "faces");
  else
    r.proxy = readProxyReport(f);
  return r;
}

void from_json(const json& j, SceneMeshReport& r) {
  r = readWithoutFile(j, readSceneMeshReport);
}

}  // namespace proxyvis
