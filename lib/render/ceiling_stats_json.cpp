// CeilingMeasurement as JSON (ceiling_stats.h), read back through util/json_field.h.
#include <array>
#include <nlohmann/json.hpp>

#include "render/ceiling_stats.h"
#include "util/json_field.h"

namespace proxyvis {

namespace {

// A region's numbers after its light, in the order of its JSON array.
template <class Stats>
auto regionNumbers(Stats& r) {
  return std::array{&r.segments,
                    &r.blocked,
                    &r.mh,
                    &r.hm,
                    &r.visibility_var,
                    &r.var_fv,
                    &r.f2_mh,
                    &r.f2_hm,
                    &r.cost_proxy[0],
                    &r.cost_proxy[1],
                    &r.cost_original[0],
                    &r.cost_original[1]};
}

}  // namespace

void to_json(nlohmann::json& j, const CeilingMeasurement& m) {
  nlohmann::json regions = nlohmann::json::array();
  for (const CeilingRegionStats& r : m.regions) {
    nlohmann::json a = nlohmann::json::array({r.light});
    for (const double* v : regionNumbers(r)) a.push_back(*v);
    regions.push_back(std::move(a));
  }
  j = {{"num_lights", m.num_lights},       {"passes", m.passes},
       {"measurement_seconds", m.seconds}, {"ticks_per_ns", m.ticks_per_ns},
       {"cpu_per_wall", m.cpu_per_wall},   {"segments", m.segments},
       {"regions", std::move(regions)}};
}

void from_json(const nlohmann::json& j, CeilingMeasurement& m) {
  const JsonField f(j);
  m.num_lights = f["num_lights"].asUint32();
  m.passes = f["passes"].asInt();
  m.seconds = f["measurement_seconds"].asDouble();
  m.ticks_per_ns = f["ticks_per_ns"].asDouble();
  m.cpu_per_wall = f["cpu_per_wall"].asDouble();
  m.segments = f["segments"].asUint64();
  const JsonField regions = f["regions"];
  m.regions.clear();
  for (size_t i = 0, n = regions.arraySize(); i < n; ++i) {
    const JsonField a = regions[i];
    CeilingRegionStats r;
    const auto numbers = regionNumbers(r);
    if (a.arraySize() != numbers.size() + 1) a.fail("expected 13 numbers: a ceiling region");
    r.light = a[size_t(0)].asUint32();
    for (size_t k = 0; k < numbers.size(); ++k) *numbers[k] = a[k + 1].asDouble();
    m.regions.push_back(r);
  }
}

}  // namespace proxyvis
