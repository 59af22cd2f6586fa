#include "proxies/pipeline/proxy_gen_settings.h"

#include <fmt/core.h>

#include <utility>

#include "mesh/io/double_reading.h"
#include "proxies/outside/outside_proxy.h"
#include "util/error.h"

namespace proxyvis {

ProxyGenOptions proxyGenOptions(const ProxyGenSettings& s, uint64_t seed) {
  ProxyGenOptions o;
  const std::optional<ProxyClass> kind = parseProxyClass(s.kind);
  if (!kind)
    throw Error("", fmt::format("unknown --kind '{}'", s.kind), "use outside, inside or general");
  if (s.budget != "hard" && s.budget != "soft")
    throw Error("", fmt::format("unknown --budget '{}'", s.budget), "use hard or soft");
  if (s.parts && (*s.parts < 1 || *s.parts > kMaxConvexParts))
    throw Error("", fmt::format("--parts must be in [1, {}], got {}", kMaxConvexParts, *s.parts));
  // proxy-gen's own lower limit (the pipeline's is kMaxSecondsRange.lo).
  if (!(s.max_seconds >= 0.1 && s.max_seconds <= kMaxSecondsRange.hi))
    throw Error("", fmt::format("--max-seconds must be in [0.1, {:g}], got {:g}",
                                kMaxSecondsRange.hi, s.max_seconds));
  o.kind = *kind;
  o.method = s.method;
  o.alpha = s.alpha;
  o.offset = s.offset;
  o.ratio = s.ratio;
  o.erosion = s.erosion;
  o.clearance = s.clearance;
  o.clearance_ulps = s.clearance_ulps;
  o.voxel = s.voxel;
  o.parts = s.parts;
  o.hard_budget = s.budget == "hard";
  o.max_faces = s.max_faces;
  o.min_faces = s.min_faces;
  o.fill_holes = s.fill_holes;
  o.seed = seed;
  o.max_seconds = s.max_seconds;
  return o;
}

namespace {

const std::pair<std::string_view, const char*> kHelp[] = {
    {"--kind", "outside | inside | general"},
    {"--method",
     "outside: wrap (default; the tightest: volume ratio 1.01-1.23 at --ratio 0.02 on the "
     "bundled closed meshes, 1.39 on a thin-legged cow), hull (convex: fastest, but 1.3-2.7), "
     "convex-parts (a "
     "proved union of convex pieces, as collision proxies are); "
     "inside: wrap (default; 0.76-0.98 of the volume at --ratio 0.02), erode (voxel erosion: "
     "0.76-0.95 at --ratio 0.02 on the bundled closed meshes); general: qem (default), "
     "cgal-sms, meshopt (no guarantee). See docs/proxy_tightness.md"},
    {"--parts",
     "convex-parts: the most convex pieces (default 16; with a face budget one per 12 "
     "faces, 2 to 32)"},
    {"--alpha",
     "wrap: alpha as a fraction of the diagonal (default 1/50; in a scene, 1/10 for an open "
     "mesh such as foliage, see docs/proxies.md)"},
    {"--offset",
     "wrap: offset as a fraction of the diagonal (default 1/600; in a scene, 1/100 for an "
     "open mesh)"},
    {"--max-faces",
     "Face budget (0 = none). Outside/inside proxies keep their guarantee while "
     "reducing; when the method's proxy cannot be reduced to it, coarser sizes, the "
     "convex hull (outside), a box (12 faces) and a tetrahedron (4 faces) are tried "
     "and the tightest verified one is kept. Without a budget an outside/inside proxy "
     "with more faces than the input is reduced to the input's count, as a goal"},
    {"--budget",
     "hard: a --max-faces/--ratio that no verified proxy meets ends the run with exit "
     "code 1 and nothing written; soft: write the smallest verified proxy anyway "
     "(\"budget_reached\": false in the JSON); see docs/budgets.md"},
    {"--max-seconds",
     "Time budget per mesh: a wrap, erosion or decimation still running after it is "
     "stopped and the mesh fails (exit code 2), nothing is written"},
    {"--ratio",
     "Faces kept as a fraction of the input: general (default 0.02); outside/inside "
     "a face budget relative to each mesh (for scenes), used when --max-faces is 0"},
    {"--min-faces",
     "With --ratio (outside/inside): the budget is at least this many faces, so that "
     "a scene's small meshes keep proxies about as tight as their wraps (ecosys: "
     "--ratio 0.03 --min-faces 64, docs/proxy_tightness.md)"},
    {"--erosion", "erode: erosion distance as a fraction of the diagonal (default 1/75)"},
    {"--voxel",
     "erode: voxel edge as a fraction of the diagonal (default 1/150; with a face "
     "budget, coarser: about 100 voxel faces per budget face)"},
    {"--clearance",
     "outside/inside: the least distance (scene units) the proxy keeps from the input, so its "
     "class holds when the input is read in double or placed by a transform; default: "
     "--clearance-ulps 8 (docs/clearance.md)"},
    {"--clearance-ulps",
     "outside/inside: the clearance in ulps of float at the input's largest "
     "coordinate (default 8: a float or double reading of a text file, and a "
     "placement that rounds each coordinate by a few ulps; 0 = none)"},
    {"--fill-holes",
     "inside: fill the holes of an open input first; the proxy is then written as class general "
     "(a ray through a hole can reach it), see docs/proxy_classes.md"},
};

}  // namespace

const char* proxyGenHelp(std::string_view flag) {
  for (const auto& [name, text] : kHelp)
    if (name == flag) return text;
  PV_CHECK_MSG(false, std::string(flag));
  return "";
}

void addDoublePositions(ProxyGenOptions& options, const TriMesh& input,
                        std::vector<Vec3d> positions, std::vector<Vec3d>& storage) {
  if (options.kind == ProxyClass::kGeneral || readsAsFloat(input, positions)) return;
  storage = std::move(positions);
  options.input_double = &storage;
}

}  // namespace proxyvis
