// The two loops follow OpenMesh 9's McDecimaterT::decimate_to_faces and
// DecimaterT::decimate_to_faces step by step (same samples, counters, stopping rules and heap);
// only the order of the legality tests differs (qem_decimater.h says why that keeps the result).
#include "proxies/general/qem_decimater.h"

#include <algorithm>
#include <cfloat>
#include <cstdlib>

namespace proxyvis {

namespace {
// What a module's collapse_priority returns for a forbidden collapse (-1).
constexpr float kIllegal = float(int(OpenMesh::Decimater::ModBaseT<QemMesh>::ILLEGAL_COLLAPSE));
}  // namespace

QemDecimater::QemDecimater(QemMesh& mesh, QuadricHandle& quadric)
    : Base(mesh), mesh_(mesh), quadric_(quadric) {
  // What McDecimaterT and DecimaterT request: the multiple-choice loop skips deleted half-edges.
  mesh_.request_halfedge_status();
  mesh_.add_property(collapse_target_);
  mesh_.add_property(priority_);
  mesh_.add_property(heap_position_);
}

QemDecimater::~QemDecimater() {
  mesh_.remove_property(collapse_target_);
  mesh_.remove_property(priority_);
  mesh_.remove_property(heap_position_);
  mesh_.release_halfedge_status();
}

float QemDecimater::quadricCost(const CollapseInfo& ci) {
  ++counts_.cost_evaluations;
  return module(quadric_).collapse_priority(ci);
}

bool QemDecimater::legal(const CollapseInfo& ci) {
  ++counts_.legality_tests;
  return is_collapse_legal(ci);
}

bool QemDecimater::pickLegal(std::vector<Candidate>& candidates, Candidate& picked) {
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.cost < b.cost; });
  for (const Candidate& c : candidates) {
    CollapseInfo ci(mesh_, c.halfedge);
    if (!legal(ci)) continue;
    // The binary modules (normal flipping, Hausdorff) and the quadric again: the priority
    // OpenMesh would have compared, equal to c.cost when legal.
    const float priority = collapse_priority(ci);
    if (priority == kIllegal) continue;
    picked = {c.halfedge, priority};
    return true;
  }
  return false;
}

void QemDecimater::collapse(CollapseInfo& ci) {
  preprocess_collapse(ci);
  mesh_.collapse(ci.v0v1);
  ++counts_.collapses;
  if (mesh_.has_face_normals())
    for (QemMesh::VertexFaceIter f = mesh_.vf_iter(ci.v1); f.is_valid(); ++f)
      if (!mesh_.status(*f).deleted()) mesh_.set_normal(*f, mesh_.calc_face_normal(*f));
  postprocess_collapse(ci);
}

size_t QemDecimater::multipleChoice(size_t target_vertices, size_t target_faces) {
  size_t nv = mesh_.n_vertices(), nf = mesh_.n_faces(), n_collapses = 0;
  unsigned no_collapses = 0;
  bool unchanged = false;
  while (target_vertices < nv && target_faces < nf) {
    if (no_collapses > 20) break;  // OpenMesh: "no collapses performed in over 20 iterations"
    candidates_.clear();
    for (size_t i = 0; i < samples_; ++i) {
      const HalfedgeHandle h(
          int((double(std::rand()) / double(RAND_MAX)) * double(mesh_.n_halfedges() - 1)));
      if (mesh_.status(h).deleted()) continue;
      const float cost = quadricCost(CollapseInfo(mesh_, h));
      // McDecimaterT keeps energy != ILLEGAL_COLLAPSE and energy < FLT_MAX.
      if (cost != kIllegal && double(cost) < double(FLT_MAX)) candidates_.push_back({h, cost});
    }
    Candidate best;
    if (!pickLegal(candidates_, best)) {
      no_collapses = unchanged ? no_collapses + 1 : 1;
      unchanged = true;
      continue;
    }
    CollapseInfo ci(mesh_, best.halfedge);
    --nv;
    nf -= (mesh_.is_boundary(ci.v0v1) || mesh_.is_boundary(ci.v1v0)) ? 1 : 2;
    collapse(ci);
    ++n_collapses;
    no_collapses = 0;
    unchanged = false;
    if (!notify_observer(n_collapses)) break;
  }
  return n_collapses;
}

void QemDecimater::heapVertex(VertexHandle v) {
  candidates_.clear();
  // The iterators DecimaterT uses, in its order (ties go to the first).
  for (QemMesh::VertexOHalfedgeIter h(mesh_, v); h.is_valid(); ++h) {
    const float cost = quadricCost(CollapseInfo(mesh_, *h));
    // DecimaterT keeps prio >= 0 and prio < FLT_MAX.
    if (cost >= 0.0f && cost < FLT_MAX) candidates_.push_back({*h, cost});
  }
  Candidate best;
  if (pickLegal(candidates_, best) && best.cost >= 0.0f) {
    mesh_.property(collapse_target_, v) = best.halfedge;
    mesh_.property(priority_, v) = best.cost;
    if (heap_->is_stored(v))
      heap_->update(v);
    else
      heap_->insert(v);
  } else {
    if (heap_->is_stored(v)) heap_->remove(v);
    mesh_.property(collapse_target_, v) = HalfedgeHandle();
    mesh_.property(priority_, v) = -1;
  }
}

size_t QemDecimater::queue(size_t target_faces) {
  if (target_faces >= mesh_.n_faces()) return 0;
  size_t nf = mesh_.n_faces(), n_collapses = 0;
  heap_ = std::make_unique<Heap>(HeapInterface(mesh_, priority_, heap_position_));
  heap_->reserve(mesh_.n_vertices());
  for (VertexHandle v : mesh_.vertices()) {
    heap_->reset_heap_position(v);
    if (!mesh_.status(v).deleted()) heapVertex(v);
  }
  std::vector<VertexHandle> support;
  while (!heap_->empty() && target_faces < nf) {
    const VertexHandle vp = heap_->front();
    const HalfedgeHandle v0v1 = mesh_.property(collapse_target_, vp);
    heap_->pop_front();
    CollapseInfo ci(mesh_, v0v1);
    if (!legal(ci)) continue;  // as DecimaterT: the target may have gone stale
    support.clear();
    for (QemMesh::VertexVertexIter s = mesh_.vv_iter(ci.v0); s.is_valid(); ++s)
      support.push_back(*s);
    ++n_collapses;
    nf -= (mesh_.is_boundary(ci.v0v1) || mesh_.is_boundary(ci.v1v0)) ? 1 : 2;
    collapse(ci);
    for (VertexHandle s : support) heapVertex(s);
    if (!notify_observer(n_collapses)) break;
  }
  heap_.reset();
  return n_collapses;
}

size_t QemDecimater::decimateToFaces(size_t faces, float mc_factor) {
  if (!is_initialized() || mc_factor > 1.0f) return 0;
  size_t collapses = 0;
  if (mc_factor > 0.0f) {
    // MixedDecimaterT's split, in its own arithmetic (float).
    const size_t mesh_faces = mesh_.n_faces(), mesh_vertices = mesh_.n_vertices();
    const size_t vertices_mc = static_cast<size_t>(mesh_vertices - mc_factor * mesh_vertices);
    // A budget at or above the mesh's faces asks for no collapse (mesh_faces - faces would wrap
    // around, and its float product overflow size_t: undefined).
    const size_t faces_mc =
        faces >= mesh_faces ? mesh_faces
                            : static_cast<size_t>(mesh_faces - mc_factor * (mesh_faces - faces));
    collapses += multipleChoice(vertices_mc, faces_mc);
  }
  mesh_.garbage_collection();
  if (observer() && observer()->abort()) return collapses;
  if (mc_factor < 1.0f) collapses += queue(faces);
  return collapses;
}

}  // namespace proxyvis
