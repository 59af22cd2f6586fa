// MeshReport as JSON and as a human-readable summary (mesh-info, proxy-gen reports).
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "mesh/validation.h"

namespace proxyvis {

nlohmann::json toJson(const MeshReport& r) {
  nlohmann::json j = {
      {"vertices", r.vertices},
      {"faces", r.faces},
      {"unreferenced_vertices", r.unreferenced_vertices},
      {"nonfinite_vertices", r.nonfinite_vertices},
      {"degenerate_faces", r.degenerate_faces},
      {"duplicate_faces", r.duplicate_faces},
      {"components", r.components},
      {"boundary_edges", r.boundary_edges},
      {"non_manifold_edges", r.non_manifold_edges},
      {"non_manifold_vertices", r.non_manifold_vertices},
      {"odd_edges", r.odd_edges},
      {"closed", r.closed},
      {"watertight", r.watertight},
      {"manifold", r.manifold},
  };
  if (r.bounds.empty())
    j["bounds"] = nullptr;
  else
    j["bounds"] = {{"min", {r.bounds.lo.x, r.bounds.lo.y, r.bounds.lo.z}},
                   {"max", {r.bounds.hi.x, r.bounds.hi.y, r.bounds.hi.z}}};
  j["genus"] = r.genus ? nlohmann::json(*r.genus) : nlohmann::json(nullptr);
  j["volume"] = r.volume ? nlohmann::json(*r.volume) : nlohmann::json(nullptr);
  j["self_intersecting_pairs"] = r.self_intersecting_pairs
                                     ? nlohmann::json(*r.self_intersecting_pairs)
                                     : nlohmann::json(nullptr);
  return j;
}

std::string formatReport(const MeshReport& r, const std::string& title) {
  std::string s = title + "\n";
  auto line = [&](const char* key, const std::string& value) {
    s += fmt::format("  {:<24} {}\n", key, value);
  };
  line("vertices", fmt::format("{} ({} unreferenced)", r.vertices, r.unreferenced_vertices));
  line("triangles", std::to_string(r.faces));
  if (r.bounds.empty())
    line("bounding box", "empty");
  else
    line("bounding box",
         fmt::format("[{:g}, {:g}, {:g}] .. [{:g}, {:g}, {:g}]", r.bounds.lo.x, r.bounds.lo.y,
                     r.bounds.lo.z, r.bounds.hi.x, r.bounds.hi.y, r.bounds.hi.z));
  line("NaN/inf vertices", std::to_string(r.nonfinite_vertices));
  line("degenerate triangles", std::to_string(r.degenerate_faces));
  line("duplicate triangles", std::to_string(r.duplicate_faces));
  line("components", std::to_string(r.components));
  line("boundary edges", std::to_string(r.boundary_edges));
  line("non-manifold edges", std::to_string(r.non_manifold_edges));
  line("non-manifold vertices", std::to_string(r.non_manifold_vertices));
  line("odd edges", fmt::format("{} (3, 5, ... faces)", r.odd_edges));
  line("closed", r.closed ? "yes" : "no");
  line("watertight",
       r.watertight ? "yes (bounds a volume by ray parity)" : "no (a boundary or odd edge)");
  line("manifold", r.manifold ? "yes" : "no");
  line("genus", r.genus ? std::to_string(*r.genus) : "- (not a closed manifold)");
  line("volume", r.volume ? fmt::format("{:.6g}", *r.volume) : "- (not closed)");
  line("self-intersecting pairs",
       r.self_intersecting_pairs ? std::to_string(*r.self_intersecting_pairs) : "not checked");
  return s;
}

}  // namespace proxyvis
