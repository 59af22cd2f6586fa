#include "proxies/check/proxy_check_settings.h"

#include <fmt/core.h>

#include <utility>

#include "util/error.h"
#include "util/proxy_class.h"

namespace proxyvis {

namespace {

const std::pair<std::string_view, const char*> kHelp[] = {
    {"--rays",
     "Number of segments to classify (per proxy). The scene distribution counts only "
     "segments that cross the box of original or proxy and draws until it has N, or "
     "gives up with a warning after 1000 N attempts"},
    {"--distribution",
     "sphere: random lines through a sphere around both meshes; scene: camera hits "
     "to light samples"},
    {"--expect",
     "Exit 1 if the evidence contradicts this class (outside: no HM' and exact "
     "'contains'; inside: no MH' and exact 'contained'; general: never)"},
    {"--precision",
     "Mesh pair: the readings of the original's file the exact check runs on: float "
     "(as proxyvis reads it), double (its decimals as the nearest doubles, as a CAD "
     "tool reads them), or both (default; the class holds only when both agree). "
     "Binary formats store floats: both readings are the same"},
};

}  // namespace

const char* proxyCheckHelp(std::string_view flag) {
  for (const auto& [name, text] : kHelp)
    if (name == flag) return text;
  PV_CHECK_MSG(false, std::string(flag));
  return "";
}

PairCheckOptions pairCheckOptions(const ProxyCheckSettings& s) {
  if (s.rays < 1 || s.rays > kMaxCheckRays)
    throw Error("", fmt::format("--rays must be in [1, {}], got {}", kMaxCheckRays, s.rays));
  if (s.distribution != "sphere" && s.distribution != "scene")
    throw Error("", fmt::format("unknown --distribution '{}'", s.distribution),
                "use sphere or scene");
  if (s.precision != "float" && s.precision != "double" && s.precision != "both")
    throw Error("", fmt::format("unknown --precision '{}'", s.precision),
                "use float, double or both");
  PairCheckOptions p;
  p.rays = s.rays;
  p.seed = s.seed;
  p.quiet = s.quiet;
  if (!s.expect.empty()) {
    p.expect = parseProxyClass(s.expect);
    if (!p.expect)
      throw Error("", fmt::format("unknown --expect '{}'", s.expect),
                  "use outside, inside or general");
  }
  p.max_error_segments = s.max_error_segments;
  return p;
}

void requireSphereDistribution(const ProxyCheckSettings& s) {
  if (s.distribution != "sphere")
    throw Error("", "--distribution scene needs a scene", "a mesh pair has no camera or lights",
                "run proxy-check SCENE.json --distribution scene");
}

PairCheckReport checkMeshPair(const TriMesh& original, const std::vector<Vec3d>* original_double,
                              const TriMesh& proxy, const ProxyCheckSettings& s) {
  requireSphereDistribution(s);
  PairCheckOptions options = pairCheckOptions(s);
  if (needsDoubleReading(s)) {
    PV_CHECK_MSG(original_double, "precision " + s.precision + " needs the double reading");
    if (original_double->size() != original.numVertices())
      throw Error(original.source, "the double reading does not match the mesh",
                  fmt::format("{} positions for {} vertices", original_double->size(),
                              original.numVertices()));
    options.original_double = original_double;
    options.double_only = s.precision == "double";
  }
  return checkPair(original, proxy, options);
}

}  // namespace proxyvis
