#pragma once
// Private to proxies/general: OpenMesh's mixed decimation (MixedDecimaterT: multiple choice, then
// a priority queue) with the same choices, made with far fewer legality tests.
//
// OpenMesh tests every candidate collapse for legality (is_collapse_ok: one-ring intersection,
// boundary rules, and the binary modules such as normal flipping) before it compares costs: ten
// tests per multiple-choice collapse, one per outgoing half-edge for every vertex the queue
// updates. These tests were 40 % of a QEM run. Only the quadric is a cost; the other modules
// only say legal or not. So the candidates can be ordered by their quadric cost first and tested
// in that order until one is legal: the first legal one is the one OpenMesh picks (the cheapest
// legal candidate, the earliest among equal costs), from the same random samples, so the result
// is the same mesh (tests/proxies/general/qem_decimater_test.cpp compares them).
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/BaseDecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <OpenMesh/Tools/Utils/HeapT.hh>

#include <cstddef>
#include <memory>
#include <vector>

namespace proxyvis {

using QemMesh = OpenMesh::TriMesh_ArrayKernelT<>;

// Counts of the work done, for tests and benchmarks.
struct QemDecimaterCounts {
  size_t collapses = 0;
  size_t legality_tests = 0;  // BaseDecimaterT::is_collapse_legal calls
  size_t cost_evaluations = 0;
};

class QemDecimater : public OpenMesh::Decimater::BaseDecimaterT<QemMesh> {
 public:
  using Base = OpenMesh::Decimater::BaseDecimaterT<QemMesh>;
  using QuadricHandle = OpenMesh::Decimater::ModQuadricT<QemMesh>::Handle;

  // `quadric` must be added to this decimater (add(quadric)) before initialize(); it is the
  // only non-binary module.
  QemDecimater(QemMesh& mesh, QuadricHandle& quadric);
  ~QemDecimater() override;

  // As MixedDecimaterT::decimate_to_faces(0, faces, mc_factor): the first mc_factor of the
  // collapses by multiple choice (best of samples() random half-edges, drawn with std::rand),
  // then the rest from the exact priority queue. Returns the number of collapses.
  size_t decimateToFaces(size_t faces, float mc_factor);

  size_t samples() const { return samples_; }
  const QemDecimaterCounts& counts() const { return counts_; }

 private:
  using VertexHandle = QemMesh::VertexHandle;
  using HalfedgeHandle = QemMesh::HalfedgeHandle;

  class HeapInterface {
   public:
    HeapInterface(QemMesh& mesh, OpenMesh::VPropHandleT<float> prio,
                  OpenMesh::VPropHandleT<int> pos)
        : mesh_(mesh), prio_(prio), pos_(pos) {}
    bool less(VertexHandle a, VertexHandle b) {
      return mesh_.property(prio_, a) < mesh_.property(prio_, b);
    }
    bool greater(VertexHandle a, VertexHandle b) {
      return mesh_.property(prio_, a) > mesh_.property(prio_, b);
    }
    int get_heap_position(VertexHandle v) { return mesh_.property(pos_, v); }
    void set_heap_position(VertexHandle v, int p) { mesh_.property(pos_, v) = p; }

   private:
    QemMesh& mesh_;
    OpenMesh::VPropHandleT<float> prio_;
    OpenMesh::VPropHandleT<int> pos_;
  };
  using Heap = OpenMesh::Utils::HeapT<VertexHandle, HeapInterface>;

  struct Candidate {
    HalfedgeHandle halfedge;
    float cost;
  };

  // The cheapest legal candidate of `candidates` (ordered by cost, stably), or none. `cost` is
  // then its full priority.
  bool pickLegal(std::vector<Candidate>& candidates, Candidate& picked);
  float quadricCost(const CollapseInfo& ci);
  bool legal(const CollapseInfo& ci);
  void collapse(CollapseInfo& ci);

  size_t multipleChoice(size_t target_vertices, size_t target_faces);
  size_t queue(size_t target_faces);
  void heapVertex(VertexHandle v);

  QemMesh& mesh_;
  QuadricHandle& quadric_;
  size_t samples_ = 10;
  QemDecimaterCounts counts_;
  std::vector<Candidate> candidates_;
  std::unique_ptr<Heap> heap_;
  OpenMesh::VPropHandleT<HalfedgeHandle> collapse_target_;
  OpenMesh::VPropHandleT<float> priority_;
  OpenMesh::VPropHandleT<int> heap_position_;
};

}  // namespace proxyvis
