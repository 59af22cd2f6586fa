// General simplifiers without CGAL: OpenMesh's Decimater (M. Garland, P. Heckbert, "Surface
// simplification using quadric error metrics", SIGGRAPH 1997) and meshoptimizer (A. Kapoulkine).
#include <meshoptimizer.h>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/ModHausdorffT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <OpenMesh/Tools/Decimater/Observer.hh>
#include <cstdlib>
#include <mutex>

#include <algorithm>
#include <cmath>
#include <optional>

#include "proxies/general/general_proxy.h"
#include "proxies/general/openmesh_faces.h"
#include "proxies/general/qem_decimater.h"
#include "proxies/shared/input_geometry.h"
#include "util/error.h"

namespace proxyvis {
namespace {

using OmMesh = QemMesh;

TriMesh compact(const std::vector<Vec3f>& vertices, const std::vector<uint32_t>& indices,
                const std::string& source) {
  TriMesh out;
  out.source = source;
  std::vector<uint32_t> remap(vertices.size(), UINT32_MAX);
  for (size_t i = 0; i + 2 < indices.size(); i += 3) {
    Triangle t{};
    for (int k = 0; k < 3; ++k) {
      uint32_t& r = remap[indices[i + k]];
      if (r == UINT32_MAX) {
        r = uint32_t(out.vertices.size());
        out.vertices.push_back(vertices[indices[i + k]]);
      }
      t[k] = r;
    }
    out.triangles.push_back(t);
  }
  return out;
}

// Lets OpenMesh's decimater stop between collapses when the time budget is spent.
class BudgetObserver : public OpenMesh::Decimater::Observer {
 public:
  explicit BudgetObserver(const TimeBudget& budget) : Observer(256), budget_(budget) {}
  void notify(size_t) override {}
  bool abort() const override { return budget_.expired(); }

 private:
  const TimeBudget& budget_;
};

std::vector<uint32_t> flatIndices(const TriMesh& mesh) {
  std::vector<uint32_t> idx;
  idx.reserve(mesh.triangles.size() * 3);
  for (const Triangle& t : mesh.triangles) idx.insert(idx.end(), t.begin(), t.end());
  return idx;
}

}  // namespace

size_t generalTargetFaces(const TriMesh& input, const GeneralOptions& options) {
  if (options.max_faces > 0) return std::max<size_t>(options.max_faces, 4);
  if (!(options.ratio > 0) || options.ratio > 1)
    throw Error("", "--ratio must be in (0, 1]", "it is the fraction of faces kept");
  return std::max<size_t>(4, size_t(std::llround(options.ratio * double(input.numTriangles()))));
}

TriMesh weldVertices(const TriMesh& input) {
  // meshopt_generateVertexRemap merges vertices whose bytes are equal: exactly equal positions.
  std::vector<uint32_t> idx = flatIndices(input);
  std::vector<uint32_t> remap(input.vertices.size());
  const size_t unique =
      meshopt_generateVertexRemap(remap.data(), idx.data(), idx.size(), input.vertices.data(),
                                  input.vertices.size(), sizeof(Vec3f));
  std::vector<Vec3f> welded(unique);
  meshopt_remapVertexBuffer(welded.data(), input.vertices.data(), input.vertices.size(),
                            sizeof(Vec3f), remap.data());
  for (uint32_t& i : idx) i = remap[i];
  return compact(welded, idx, input.source);
}

TriMesh simplifyQem(const TriMesh& input, const GeneralOptions& options, QemStats* stats) {
  requireProxyGeometry(input, GeometryNeed::kSurface, "a qem proxy");
  const TriMesh welded = weldVertices(input);
  OmMesh om;
  std::vector<OmMesh::VertexHandle> vh;
  vh.reserve(welded.vertices.size());
  for (const Vec3f& v : welded.vertices) vh.push_back(om.add_vertex(OmMesh::Point(v.x, v.y, v.z)));
  // A triangle whose corners welded into fewer than three vertices has no edge to collapse, and
  // OpenMesh asserts on it: skipped. Faces at non-manifold edges and vertices go on copies of
  // their vertices (OpenMesh would drop them with a warning on stderr).
  addFacesSplittingComplex(om, vh, welded.triangles);
  if (om.n_faces() == 0)
    throw Error(input.source, "cannot build a qem proxy",
                "no triangle could be added to a half-edge mesh (all degenerate or non-manifold)",
                "use --method meshopt");

  // ModNormalFlipping compares face normals before and after a collapse.
  om.request_face_normals();
  om.update_face_normals();
  // Mixed: the first 80 % of the collapses by multiple choice (best of 10 random candidates,
  // Wu and Kobbelt 2002), the rest from the exact priority queue. On the dragon to 1 %: 0.7 s
  // against 1.5 s for the queue alone, with a smaller Hausdorff distance (0.016/0.021 against
  // 0.019/0.031 of the diagonal). QemDecimater makes OpenMesh's MixedDecimaterT choices with
  // fewer legality tests (qem_decimater.h).
  OpenMesh::Decimater::ModQuadricT<OmMesh>::Handle quadric;
  QemDecimater decimater(om, quadric);
  OpenMesh::Decimater::ModNormalFlippingT<OmMesh>::Handle normal_flipping;
  OpenMesh::Decimater::ModHausdorffT<OmMesh>::Handle hausdorff;
  decimater.add(quadric);
  decimater.add(normal_flipping);
  if (options.hausdorff > 0) {
    decimater.add(hausdorff);
    decimater.module(hausdorff).set_tolerance(float(options.hausdorff * input.diagonal()));
  }
  decimater.initialize();
  std::optional<BudgetObserver> observer;
  if (options.budget) {
    observer.emplace(*options.budget);
    decimater.set_observer(&*observer);
  }
  {
    static std::mutex rand_mutex;  // the multiple-choice sampling draws from std::rand
    std::lock_guard<std::mutex> lock(rand_mutex);
    std::srand(1);
    decimater.decimateToFaces(generalTargetFaces(input, options), 0.8f);
  }
  if (stats) *stats = {decimater.counts().collapses, decimater.counts().legality_tests};
  checkBudget(options.budget, "the qem decimation");
  om.garbage_collection();

  TriMesh out;
  out.source = "qem of " + input.source;
  for (auto v : om.vertices()) {
    const auto& p = om.point(v);
    out.vertices.emplace_back(p[0], p[1], p[2]);
  }
  for (auto f : om.faces()) {
    Triangle t{};
    int k = 0;
    for (auto v : om.fv_range(f)) t[k++] = uint32_t(v.idx());
    out.triangles.push_back(t);
  }
  return out;
}

TriMesh simplifyMeshopt(const TriMesh& input, const GeneralOptions& options) {
  requireProxyGeometry(input, GeometryNeed::kSurface, "a meshopt proxy");
  const TriMesh welded = weldVertices(input);
  const size_t target = generalTargetFaces(input, options);
  std::vector<uint32_t> idx = flatIndices(welded), out(idx.size());
  // Already within the budget (a mesh of fewer than 4 triangles): meshopt asserts on a target
  // above the index count.
  if (target * 3 >= idx.size()) return compact(welded.vertices, idx, "meshopt of " + input.source);
  // target_error 1 (relative to the mesh extent) lets the face budget alone decide.
  size_t n = meshopt_simplify(out.data(), idx.data(), idx.size(), &welded.vertices[0].x,
                              welded.vertices.size(), sizeof(Vec3f), target * 3, 1.0f);
  if (n > target * 3) {
    std::vector<uint32_t> sloppy(idx.size());
    n = meshopt_simplifySloppy(sloppy.data(), out.data(), n, &welded.vertices[0].x,
                               welded.vertices.size(), sizeof(Vec3f), target * 3, 1.0f, nullptr);
    out.swap(sloppy);
  }
  out.resize(n);
  return compact(welded.vertices, out, "meshopt of " + input.source);
}

}  // namespace proxyvis
