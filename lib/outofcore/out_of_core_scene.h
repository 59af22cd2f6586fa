#pragma once
// A scene whose originals stay on disk (docs/out_of_core.md): what the out-of-core renderer keeps
// resident (camera, lights, the objects, one world box per object, the outside and inside
// proxies with their proved classes) and how it loads one mesh's original when a batch needs it.
//
// Object ids, the proxy choice and the flat or instanced build are the single-process
// renderer's (scene_assembly.h), and a mesh's original is built with addRenderObjects for that
// mesh's objects alone, as the data-parallel renderer builds a rank's share: every primary hit
// and shadow segment gets the same answer as in the in-core scene, bit for bit.
//
// Loading scans every original once: it reads and builds each mesh alone to measure what its
// built scene takes (the unit of the geometry budget), its bounds (the objects' boxes, the ray
// offset) and its triangles, keeping none of them.
#include <cstdint>
#include <memory>
#include <vector>

#include "distributed/box_index.h"
#include "outofcore/geometry_cache.h"
#include "render/camera.h"
#include "render/light_sampler.h"
#include "render/render_scene.h"
#include "render/scene_assembly.h"
#include "scene/scene_desc.h"
#include "trace/trace_scene.h"

namespace proxyvis {

struct OutOfCoreSceneOptions {
  // The single-process renderer's options (proxy kind, build, trace options): the same scene.
  RenderSceneOptions scene;
  // Load the outside and inside proxies the proxy policies rely on, their classes proved for
  // their files (the recorded sha256), the lights outside them.
  bool proxies = true;
};

// What loading a mesh (reading, decoding and building it) takes at its peak, over its built
// bytes: the decoded triangles and Embree's build scratch beside the scene being built. Measured
// as the RSS growth of loads (render --json's rss_growth.load_over_built, the heap's freed memory
// handed back before each load) of the unique park's dragon copies (100 k triangles, 8.7-9.0 MiB
// built): 1.31-2.11 over 40 loads of the 16-sculpture park at budgets of 40-100 % on 1 and 2
// threads; up to 2.49 in renders of the 100-sculpture park at 10-50 %. The largest, rounded up.
inline constexpr double kLoadPeakOverBuilt = 2.5;

struct OutOfCoreMesh {
  bool used = false;
  uint64_t triangles = 0;        // the original's
  uint64_t built_bytes = 0;      // its objects' built Embree scene (the budget's unit)
  uint64_t load_peak_bytes = 0;  // kLoadPeakOverBuilt x built_bytes: what its load needs
  uint64_t file_bytes = 0;
  int outside = -1, inside = -1;  // the proxies the proxy policies use (-1: none)
};

class OutOfCoreScene {
 public:
  // Throws Error for an unreadable original or proxy, a proxy class not proved for its file,
  // a light inside a proxy's bounds.
  static std::unique_ptr<OutOfCoreScene> load(const SceneDesc& desc,
                                              const OutOfCoreSceneOptions& options);
  ~OutOfCoreScene();

  const SceneDesc& desc() const { return desc_; }
  const Camera& camera() const { return camera_; }
  const LightSampler& lights() const { return lights_; }
  float epsilon() const { return epsilon_; }
  const std::vector<RenderObject>& objects() const { return objects_; }
  const std::vector<OutOfCoreMesh>& meshes() const { return meshes_; }
  const BuildChoice& buildChoice() const { return build_; }
  // The originals' built bytes together: what the in-core renderer's scene of them takes once
  // built.
  uint64_t builtBytes() const;
  // Per mesh, one figure of its scan (e.g. &OutOfCoreMesh::built_bytes).
  std::vector<uint64_t> perMesh(uint64_t OutOfCoreMesh::*figure) const {
    std::vector<uint64_t> out;
    for (const OutOfCoreMesh& m : meshes_) out.push_back(m.*figure);
    return out;
  }
  // What holding every original takes: each built, and the largest load's scratch (its
  // load_peak_bytes over its built bytes) while the last one loads. A budget's share ("25%") is
  // of this, so that 100 % loads every mesh once.
  uint64_t inCoreBytes() const;
  double scanSeconds() const { return scan_seconds_; }

  // Reads, decodes and builds mesh `mesh`'s original for its objects (world space as in the
  // in-core scene). Throws Error naming the file if it cannot be read any more.
  // `cold`: the file's cached pages are dropped first (util/page_cache.h), so it is read from
  // the disk.
  GeometryLoad loadOriginal(uint32_t mesh, bool cold = false) const;
  // Builds mesh `mesh`'s objects from its original, already read (the scan's second half).
  GeometryLoad buildOriginal(uint32_t mesh, const TriMesh& original) const;

  // One box per object (its original's world box, grown by epsilon()), labelled by its mesh.
  const BoxIndex& objectBoxes() const { return *boxes_; }
  // Every object's outside / inside proxy (null when no object has one, or without proxies);
  // the outside ones traced robustly. User ids are object ids.
  const TraceScene* outsideProxies() const { return outside_.get(); }
  const TraceScene* insideProxies() const { return inside_.get(); }
  uint64_t proxyBytes() const { return proxy_bytes_; }

 private:
  friend class OutOfCoreSceneLoader;
  explicit OutOfCoreScene(const SceneDesc& desc);

  SceneDesc desc_;
  Camera camera_;
  LightSampler lights_;
  float epsilon_ = 1e-4f;
  std::vector<RenderObject> objects_;
  std::vector<OutOfCoreMesh> meshes_;
  BuildChoice build_;
  RenderSceneOptions scene_options_;
  std::unique_ptr<TraceDevice> device_;
  std::unique_ptr<BoxIndex> boxes_;
  std::unique_ptr<TraceScene> outside_, inside_;
  uint64_t proxy_bytes_ = 0;
  double scan_seconds_ = 0;
};

}  // namespace proxyvis
