#include "render/render_options.h"

#include <sstream>
#include <vector>

#include "util/app_main.h"
#include "util/error.h"

namespace proxyvis {

std::vector<std::string> splitCommaList(const std::string& list) {
  std::vector<std::string> items;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) items.push_back(item);
  return items;
}

void addRenderFlags(CLI::App& app, RenderFlags& f) {
  // The scene's own limit (scenes/FORMAT.md): an override may not bypass it.
  app.add_option("--width", f.width, "Override the scene's image width")
      ->check(integerIn(1, kMaxImageSide));
  app.add_option("--height", f.height, "Override the scene's image height")
      ->check(integerIn(1, kMaxImageSide));
  app.add_option("--proxy-kind", f.proxy_kind,
                 "Use each mesh's proxy of this kind (outside, inside, general; default: first)")
      ->check(CLI::IsMember({"outside", "inside", "general"}));
  app.add_option("--q-min", f.q_min, "Roulette floor where an error class is possible")
      ->check(numberIn(1e-6, 1.0))
      ->capture_default_str();
  app.add_option("--probes", f.probes, "Probe rays per shading point (paper-optimal, paper-cost)")
      ->check(integerIn(1, kMaxProbes))
      ->each([&f](const std::string&) { f.probes_given = true; })
      ->capture_default_str();
  app.add_option("--build", f.build,
                 "Instances as Embree instances, flattened into one BVH, or auto (flat when the "
                 "flattened scene has at most 4 M triangles and its estimated memory fits "
                 "--memory-budget)")
      ->check(CLI::IsMember({"auto", "flat", "instanced"}))
      ->capture_default_str();
  app.add_option("--memory-budget", f.memory_budget_gib,
                 "GiB the flattened BVHs may take under --build auto (default: the smaller of 4 "
                 "and half the physical or cgroup memory)")
      ->check(numberIn(0, 1 << 20));
  app.add_option("--roulette-costs", f.roulette_costs,
                 "Roulette's ray costs: 'measured' (per region, timing-dependent choices) or "
                 "'c_p0,c_p1,c_o0,c_o1,c_s' in ns (fixed: bit-reproducible)")
      ->capture_default_str();
}

void RenderFlags::resolve() {
  fixed_costs.reset();
  if (roulette_costs == "measured") return;
  std::vector<double> c;
  for (const std::string& item : splitCommaList(roulette_costs)) {
    const std::optional<double> v = parseNumber(item);
    if (!v || *v < 0) {
      c.clear();
      break;
    }
    c.push_back(*v);
  }
  if (c.size() != 5 || !(c[0] > 0 && c[1] > 0 && c[2] > 0 && c[3] > 0))
    throw Error({}, "--roulette-costs: '" + roulette_costs + "' is not 'measured' or five costs",
                "expected c_p|V'=0, c_p|V'=1, c_o|V'=0, c_o|V'=1 (> 0) and c_s (>= 0) in ns",
                "e.g. --roulette-costs 40,20,300,25,60 (bench_render prints measured ones)");
  ClassCosts costs;
  costs.proxy[0] = c[0];
  costs.proxy[1] = c[1];
  costs.original[0] = c[2];
  costs.original[1] = c[3];
  costs.per_sample = c[4];
  fixed_costs = costs;
}

void RenderFlags::applyTo(SceneDesc& scene) const {
  if (width > 0) scene.camera.width = width;
  if (height > 0) scene.camera.height = height;
}

RenderSceneOptions RenderFlags::sceneOptions(bool quiet) const {
  RenderSceneOptions o;
  o.proxy_kind = proxy_kind;
  o.quiet = quiet;
  o.instance_build = build == "flat"        ? InstanceBuild::kFlat
                     : build == "instanced" ? InstanceBuild::kInstanced
                                            : InstanceBuild::kAuto;
  o.memory_budget_bytes =
      memory_budget_gib < 0 ? -1.0 : memory_budget_gib * double(uint64_t(1) << 30);
  return o;
}

EstimatorSetup RenderFlags::estimatorSetup(EstimatorKind kind) const {
  EstimatorSetup setup;
  setup.kind = kind;
  setup.q_min = q_min;
  setup.probes_per_point = probes;
  setup.fixed_costs = fixed_costs;
  return setup;
}

}  // namespace proxyvis
