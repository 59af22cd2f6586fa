#pragma once
// One rank's share of a scene rendered data-parallel (docs/data_parallel.md):
//   - distributed objects: every placed mesh or instance whose mesh has an outside proxy. Each is
//     owned by one rank (spatial domains balanced by the originals' bytes: domain_partition.h),
//     and only its owner opens its original file;
//   - replicated objects: meshes without an outside proxy (a ground quad, a terrain), loaded by
//     every rank;
//   - the proxies of every mesh that forwarding, the partition and the build decision use, on
//     every rank, with their proved classes;
//   - replicated instance boxes (each distributed object's world box, measured by its owner on
//     its original and shared once) and domain boxes (the union of a rank's instance boxes).
// Object ids are the single-process renderer's (RenderScene: placed meshes, then instances, in
// file order), and the Embree scenes use the same flat or instanced build as it would, so that
// a primary hit or a shadow segment gets the same answer here as there, bit for bit.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "distributed/box_index.h"
#include "distributed/mpi_comm.h"
#include "render/camera.h"
#include "render/light_sampler.h"
#include "render/render_scene.h"
#include "scene/scene_desc.h"
#include "trace/trace_scene.h"

namespace proxyvis {

// Which remote ranks a shadow segment that is unblocked here must be sent to.
enum class Forwarding {
  kDomainBounds,   // every rank whose domain box the segment enters
  kInstanceBoxes,  // every rank owning an object whose world box the segment enters
  kProxies         // every rank owning an object whose outside proxy the segment crosses,
                   // unless an inside proxy (of any object) blocks it: then none
};
const char* forwardingName(Forwarding f);  // "domain-bounds", "instance-boxes", "proxies"
// Throws Error naming the flag for anything else.
Forwarding parseForwarding(const std::string& name);

struct DistributedSceneOptions {
  // The single-process renderer's options for the same flags: the proxy each mesh would trace
  // and the BVH build follow from them (scene_assembly.h), as in loadRenderScene, so that both
  // renderers build the same Embree scenes. proxy_kind also names the proxies forwarding relies
  // on: empty for the outside and inside ones, "outside" for the outside ones alone; any other
  // kind is refused (an inside proxy alone cannot say which rank to ask, a general one proves
  // nothing).
  RenderSceneOptions scene;
  // Build what Forwarding::kProxies needs: the outside and inside proxies in Embree, each one's
  // class proved for its file (recorded sha256 equal to the file's) and the lights outside them.
  // The box policies only use proxies to place objects; with them a proxy_kind is refused.
  bool proxies = true;
};

// What a shadow segment needs after the local trace.
struct Route {
  bool blocked_by_inside = false;  // an inside proxy blocks it: V = 0 without a forward
  std::vector<uint16_t> ranks;     // remote ranks to ask, nearest entry first
};

class DistributedScene {
 public:
  // Collective: every rank calls it. Throws Error (on rank 0 with "rank R: " and the first
  // failing rank's message; ReportedOnAnotherRank elsewhere) for a file a rank cannot read,
  // a proxy whose class does not hold, a light inside a proxy's bounds, a proxy kind it cannot
  // forward by.
  static std::unique_ptr<DistributedScene> load(const SceneDesc& desc,
                                                const DistributedSceneOptions& options,
                                                const MpiComm& comm);
  ~DistributedScene();

  const SceneDesc& desc() const { return desc_; }
  const Camera& camera() const { return camera_; }
  const LightSampler& lights() const { return lights_; }
  float epsilon() const { return epsilon_; }
  int rank() const { return rank_; }
  int ranks() const { return ranks_; }
  const std::vector<RenderObject>& objects() const { return objects_; }
  // Per object: the owning rank, or -1 for a replicated object.
  const std::vector<int>& owners() const { return owners_; }
  bool flat() const { return build_.flat; }
  const BuildChoice& buildChoice() const { return build_; }
  bool hasProxyForwarding() const { return outside_ != nullptr; }

  // This rank's originals: its own distributed objects, and the replicated ones (null if none).
  const TraceScene* own() const { return own_.get(); }
  const TraceScene* replicated() const { return replicated_.get(); }
  // True if this rank's originals (own and replicated) block the segment.
  bool locallyOccluded(const Segment& s) const;
  // True if this rank's own distributed originals block it: the answer to a forwarded segment.
  bool ownOccluded(const Segment& s) const;
  // The closest hit among this rank's originals.
  Hit intersectLocal(const Segment& ray) const;
  // Remote ranks for a segment left unblocked by the local trace, under `policy` (kProxies only
  // if hasProxyForwarding()). `scratch` is reused.
  void route(Forwarding policy, const Segment& s, std::vector<LabelEntry>& scratch,
             Route& out) const;

  // Facts for reports.
  struct Facts {
    uint64_t own_objects = 0, replicated_objects = 0, distributed_objects = 0;
    uint64_t own_triangles = 0, replicated_triangles = 0;  // this rank's originals
    uint64_t proxy_triangles = 0;                          // every proxy this rank loaded
    std::vector<std::filesystem::path> originals_opened;   // by this rank
  };
  const Facts& facts() const { return facts_; }

 private:
  friend class DistributedSceneLoader;  // load()'s steps (distributed_scene.cpp)
  explicit DistributedScene(const SceneDesc& desc);
  // route()'s kProxies part (distributed_scene.cpp says how).
  bool routeByProxies(const Segment& s, std::vector<LabelEntry>& scratch, Route& out) const;

  SceneDesc desc_;
  Camera camera_;
  LightSampler lights_;
  int rank_ = 0, ranks_ = 1;
  std::vector<RenderObject> objects_;
  std::vector<int> owners_;
  BuildChoice build_;
  std::unique_ptr<TraceDevice> device_;
  std::unique_ptr<TraceScene> own_, replicated_, outside_, inside_;
  std::unique_ptr<BoxIndex> domain_boxes_, instance_boxes_;  // labelled by rank
  float epsilon_ = 1e-4f;
  Facts facts_;
};

}  // namespace proxyvis
