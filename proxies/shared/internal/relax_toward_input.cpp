// Each vertex tries a few steps along two directions: down the volume gradient (the fastest
// volume decrease) and toward the nearest input point; the step lengths are fractions of the
// distance to the input, the first admissible one is kept. A step is admissible when no face
// of the star flips, the input test allows the new star, and no new face crosses a face of the
// mesh that shares no corner with it (a linear scan over face boxes: the meshes are small).
// Between vertex passes, edges are flipped where the flip removes volume under the same tests:
// at a few hundred faces the triangulation, not only the vertex positions, decides how closely
// thin parts (legs, horns, handles) are hugged, and edge collapses alone leave it as it fell.
#include "proxies/shared/internal/relax_toward_input.h"

#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <vector>

#include "mesh/cgal_bridge.h"
#include "proxies/shared/internal/face_crossing.h"
#include "util/vec3.h"

namespace proxyvis::cgal {
namespace {

using Tri = std::array<Vec3d, 3>;

Bounds3d boxOf(const Tri& t) {
  return {min(min(t[0], t[1]), t[2]), max(max(t[0], t[1]), t[2])};
}

class Relaxer {
 public:
  Relaxer(TriMesh& mesh, const InputBound& bound) : mesh_(mesh), bound_(bound) {
    faces_of_.resize(mesh.vertices.size());
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
      for (uint32_t v : mesh.triangles[f]) faces_of_[v].push_back(uint32_t(f));
      boxes_.push_back(boxOf(tri(f)));
    }
  }

  // Moves vertex v if an admissible step lowers the volume; returns the volume removed.
  double relax(uint32_t v) {
    const std::vector<uint32_t>& star = faces_of_[v];
    if (star.empty()) return 0;
    const Vec3d p(mesh_.vertices[v]);
    // The volume is Σ p·(b×c)/6 over the star faces (p, b, c): its gradient is Σ (b×c)/6.
    Vec3d gradient(0, 0, 0);
    for (uint32_t f : star) {
      const auto [b, c] = others(f, v);
      gradient += cross(b, c) / 6.0;
    }
    const Vec3d near = bound_.closestPoint(p);
    const double dist = length(near - p);
    const double glen = length(gradient);
    if (!(dist > 0) || !(glen > 0)) return 0;
    const Vec3d dirs[2] = {gradient * (-1.0 / glen), (near - p) / dist};
    double best_gain = 0;
    Vec3d best = p;
    size_t first_touch = 0;  // the new face that refused the last position
    for (const Vec3d& d : dirs) {
      for (double s : {0.9, 0.5, 0.25, 0.1}) {
        const Vec3d x = roundToFloat(p + d * (dist * s));
        const double gain = -dot(x - p, gradient);
        if (!(gain > best_gain)) continue;
        if (admissible(v, x, &first_touch)) {
          best_gain = gain;
          best = x;
          break;
        }
      }
    }
    if (best_gain > 0) {
      mesh_.vertices[v] = Vec3f(float(best.x), float(best.y), float(best.z));
      for (uint32_t f : star) boxes_[f] = boxOf(tri(f));
    }
    return best_gain;
  }

 private:
  Tri tri(size_t f) const {
    const Triangle& t = mesh_.triangles[f];
    return {Vec3d(mesh_.vertices[t[0]]), Vec3d(mesh_.vertices[t[1]]), Vec3d(mesh_.vertices[t[2]])};
  }
  // The two other corners of face f, in the face's order after v.
  std::array<Vec3d, 2> others(uint32_t f, uint32_t v) const {
    const Triangle& t = mesh_.triangles[f];
    const int k = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
    return {Vec3d(mesh_.vertices[t[(k + 1) % 3]]), Vec3d(mesh_.vertices[t[(k + 2) % 3]])};
  }

  bool admissible(uint32_t v, const Vec3d& x, size_t* first_touch) const {
    const std::vector<uint32_t>& star = faces_of_[v];
    std::vector<Tri> old_star, new_star;
    for (uint32_t f : star) {
      const auto [b, c] = others(f, v);
      const Vec3d p(mesh_.vertices[v]);
      const Vec3d n_old = cross(b - p, c - p), n_new = cross(b - x, c - x);
      const double len_old = length(n_old), len_new = length(n_new);
      if (!(len_new > 1e-12 * len_old) || dot(n_old, n_new) <= 0.2 * len_old * len_new)
        return false;
      old_star.push_back({p, b, c});
      new_star.push_back({x, b, c});
    }
    if (!bound_.allows(old_star, new_star, first_touch)) return false;
    // Corner ids in the order of new_star's points: (v, then the face's order after v).
    std::vector<Triangle> corners;
    for (uint32_t f : star) {
      const Triangle& t = mesh_.triangles[f];
      const int k = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
      corners.push_back({v, t[(k + 1) % 3], t[(k + 2) % 3]});
    }
    return crossesNothing(new_star, corners, star);
  }

  // No new face crosses another new one or a face of the mesh other than the `replaced` ones
  // (faces that share a corner are tested from that corner on: internal/face_crossing.h).
  bool crossesNothing(const std::vector<Tri>& new_faces, const std::vector<Triangle>& new_corners,
                      const std::vector<uint32_t>& replaced) const {
    std::vector<IdFace> faces;
    for (size_t i = 0; i < new_faces.size(); ++i)
      faces.push_back(
          {{toPoint(new_faces[i][0]), toPoint(new_faces[i][1]), toPoint(new_faces[i][2])},
           new_corners[i]});
    if (anyTwoCross(faces)) return false;
    for (size_t i = 0; i < faces.size(); ++i) {
      const Bounds3d box = boxOf(new_faces[i]);
      for (size_t f = 0; f < mesh_.triangles.size(); ++f) {
        if (!box.overlaps(boxes_[f])) continue;
        if (std::find(replaced.begin(), replaced.end(), uint32_t(f)) != replaced.end()) continue;
        const Tri o = tri(f);
        if (facesCross(faces[i],
                       {{toPoint(o[0]), toPoint(o[1]), toPoint(o[2])}, mesh_.triangles[f]}))
          return false;
      }
    }
    return true;
  }

 public:
  // Flips the edge from corner k to corner k+1 of face f: (a, b, c) and its neighbour (b, a, d)
  // become (c, a, d) and (d, b, c) when that removes volume, creates no edge that exists, folds
  // neither face and the input and self-intersection tests allow it. Returns the volume removed.
  double flip(uint32_t f, int k) {
    const Triangle tf = mesh_.triangles[f];
    const uint32_t a = tf[k], b = tf[(k + 1) % 3], c = tf[(k + 2) % 3];
    uint32_t g = kNone, d = kNone;
    for (uint32_t h : faces_of_[a]) {
      if (h == f) continue;
      const Triangle& th = mesh_.triangles[h];
      for (int j = 0; j < 3; ++j)
        if (th[j] == b && th[(j + 1) % 3] == a) g = h, d = th[(j + 2) % 3];
    }
    if (g == kNone || d == c) return 0;
    for (uint32_t h : faces_of_[c])
      for (uint32_t w : mesh_.triangles[h])
        if (w == d) return 0;  // edge (c, d) exists: the flip would make it non-manifold
    const Vec3d pa(mesh_.vertices[a]), pb(mesh_.vertices[b]), pc(mesh_.vertices[c]),
        pd(mesh_.vertices[d]);
    auto volume = [](const Vec3d& x, const Vec3d& y, const Vec3d& z) {
      return dot(x, cross(y, z)) / 6.0;
    };
    const double gain =
        volume(pa, pb, pc) + volume(pb, pa, pd) - volume(pc, pa, pd) - volume(pd, pb, pc);
    if (!(gain > 0)) return 0;
    const Vec3d n_old = cross(pb - pa, pc - pa) + cross(pa - pb, pd - pb);
    for (const Vec3d n : {cross(pa - pc, pd - pc), cross(pb - pd, pc - pd)}) {
      const double len = length(n), len_old = length(n_old);
      if (!(len > 1e-12 * len_old) || dot(n, n_old) <= 0.2 * len * len_old) return 0;
    }
    const std::vector<Tri> old_star{{pa, pb, pc}, {pb, pa, pd}};
    const std::vector<Tri> new_star{{pc, pa, pd}, {pd, pb, pc}};
    if (!bound_.allows(old_star, new_star)) return 0;
    // Both old faces and the new ones share corners; the rest of the mesh must not be crossed.
    if (!crossesNothing(new_star, {Triangle{c, a, d}, Triangle{d, b, c}}, {f, g})) return 0;
    mesh_.triangles[f] = {c, a, d};
    mesh_.triangles[g] = {d, b, c};
    auto drop = [&](uint32_t v, uint32_t face) {
      auto& list = faces_of_[v];
      list.erase(std::remove(list.begin(), list.end(), face), list.end());
    };
    drop(a, g);
    drop(b, f);
    faces_of_[c].push_back(g);
    faces_of_[d].push_back(f);
    boxes_[f] = boxOf(tri(f));
    boxes_[g] = boxOf(tri(g));
    return gain;
  }

 private:
  static constexpr uint32_t kNone = ~0u;

  TriMesh& mesh_;
  const InputBound& bound_;
  std::vector<std::vector<uint32_t>> faces_of_;
  std::vector<Bounds3d> boxes_;
};

}  // namespace

size_t relaxTowardInput(TriMesh& mesh, const InputBound& bound, int sweeps,
                        const TimeBudget* budget) {
  Relaxer relaxer(mesh, bound);
  size_t moved = 0;
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    const double volume = mesh.signedVolume();
    double gained = 0;
    for (uint32_t v = 0; v < mesh.vertices.size(); ++v) {
      if (budget && budget->expired()) return moved;
      const double g = relaxer.relax(v);
      if (g > 0) {
        gained += g;
        ++moved;
      }
    }
    for (uint32_t f = 0; f < mesh.triangles.size(); ++f) {
      if (budget && budget->expired()) return moved;
      for (int k = 0; k < 3; ++k) {
        const double g = relaxer.flip(f, k);
        if (g > 0) {
          gained += g;
          ++moved;
          break;  // face f has changed
        }
      }
    }
    if (!(gained > 1e-3 * volume)) break;
  }
  return moved;
}

}  // namespace proxyvis::cgal
