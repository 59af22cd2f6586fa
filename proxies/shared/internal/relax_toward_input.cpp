// Each vertex tries a few steps along two directions: down the volume gradient (the fastest
// volume decrease) and toward the nearest input point; the step lengths are fractions of the
// distance to the input, the first admissible one is kept. A step is admissible when no face
// of the star flips, the input test allows the new star, and no new face crosses a face of the
// mesh that shares no corner with it (a linear scan over face boxes: the meshes are small).
#include "proxies/shared/internal/relax_toward_input.h"

#include <CGAL/intersections.h>

#include <array>
#include <vector>

#include "mesh/cgal_bridge.h"

namespace proxyvis::cgal {
namespace {

using Tri = std::array<Vec3d, 3>;

struct Box {
  Vec3d lo, hi;
  bool overlaps(const Box& o) const {
    return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y && lo.z <= o.hi.z &&
           o.lo.z <= hi.z;
  }
};

Box boxOf(const Tri& t) {
  return {min(min(t[0], t[1]), t[2]), max(max(t[0], t[1]), t[2])};
}

Point3 toPoint(const Vec3d& v) {
  return {v.x, v.y, v.z};
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
    for (const Vec3d& d : dirs) {
      for (double s : {0.9, 0.5, 0.25, 0.1}) {
        const Vec3d x = roundToFloat(p + d * (dist * s));
        const double gain = -dot(x - p, gradient);
        if (!(gain > best_gain)) continue;
        if (admissible(v, x)) {
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

  bool admissible(uint32_t v, const Vec3d& x) const {
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
    if (!bound_.allows(old_star, new_star)) return false;
    for (size_t i = 0; i < star.size(); ++i) {
      const Tri& t = new_star[i];
      const Box box = boxOf(t);
      const Triangle& corners = mesh_.triangles[star[i]];
      const Kernel::Triangle_3 moved(toPoint(t[0]), toPoint(t[1]), toPoint(t[2]));
      for (size_t f = 0; f < mesh_.triangles.size(); ++f) {
        if (!box.overlaps(boxes_[f])) continue;
        const Triangle& g = mesh_.triangles[f];
        bool shares = false;
        for (uint32_t a : g) shares |= a == corners[0] || a == corners[1] || a == corners[2];
        if (shares) continue;  // the star itself and its neighbours
        const Tri o = tri(f);
        if (CGAL::do_intersect(moved,
                               Kernel::Triangle_3(toPoint(o[0]), toPoint(o[1]), toPoint(o[2]))))
          return false;
      }
    }
    return true;
  }

  TriMesh& mesh_;
  const InputBound& bound_;
  std::vector<std::vector<uint32_t>> faces_of_;
  std::vector<Box> boxes_;
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
    if (!(gained > 1e-3 * volume)) break;
  }
  return moved;
}

}  // namespace proxyvis::cgal
