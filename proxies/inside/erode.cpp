// Erosion proxy: solid voxelisation by ray parity, morphological erosion, and the boundary of
// the voxel set. Non-manifold voxel configurations are removed first, following the
// well-composed sets of L. J. Latecki, "3D well-composed pictures", Graphical Models and Image
// Processing 59(3), 1997: without the two critical configurations the voxel boundary is a
// 2-manifold. Only voxels are ever removed, so every step keeps the set inside.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "proxies/inside/inside_proxy.h"
#include "proxies/shared/input_geometry.h"
#include "util/error.h"

namespace proxyvis {
namespace {

struct Grid {
  int n[3] = {0, 0, 0};
  Vec3d origin;
  double h = 1;
  std::vector<uint8_t> in;
  size_t index(int i, int j, int k) const { return (size_t(k) * n[1] + j) * n[0] + i; }
  bool at(int i, int j, int k) const {
    if (i < 0 || j < 0 || k < 0 || i >= n[0] || j >= n[1] || k >= n[2]) return false;
    return in[index(i, j, k)] != 0;
  }
};

// Ray parity along +x through every (y, z) voxel-centre column. The columns are shifted by an
// irrational fraction of a voxel so that they do not pass exactly through grid-aligned edges;
// a column with an odd number of crossings (a ray grazing an edge) is left empty, which errs
// on the inside.
Grid voxelize(const TriMesh& mesh, double h, const TimeBudget* budget) {
  const Bounds3f b = mesh.bounds();
  Grid g;
  g.h = h;
  for (int a = 0; a < 3; ++a) {
    g.n[a] = int(std::ceil((b.hi[a] - b.lo[a]) / h)) + 2;
    g.origin[a] = b.lo[a] - h;
  }
  const double jitter = h * 1e-4 * std::sqrt(2.0);
  std::vector<std::vector<double>> hits(size_t(g.n[1]) * g.n[2]);
  for (const Triangle& t : mesh.triangles) {
    const Vec3d p[3] = {Vec3d(mesh.vertices[t[0]]), Vec3d(mesh.vertices[t[1]]),
                        Vec3d(mesh.vertices[t[2]])};
    const double ylo = std::min({p[0].y, p[1].y, p[2].y}), yhi = std::max({p[0].y, p[1].y, p[2].y});
    const double zlo = std::min({p[0].z, p[1].z, p[2].z}), zhi = std::max({p[0].z, p[1].z, p[2].z});
    const int j0 = std::max(0, int(std::floor((ylo - g.origin.y - jitter) / h - 0.5)));
    const int j1 = std::min(g.n[1] - 1, int(std::ceil((yhi - g.origin.y - jitter) / h - 0.5)));
    const int k0 = std::max(0, int(std::floor((zlo - g.origin.z - jitter * 1.7) / h - 0.5)));
    const int k1 =
        std::min(g.n[2] - 1, int(std::ceil((zhi - g.origin.z - jitter * 1.7) / h - 0.5)));
    // 2-D edge functions in the yz plane.
    const double area =
        (p[1].y - p[0].y) * (p[2].z - p[0].z) - (p[2].y - p[0].y) * (p[1].z - p[0].z);
    if (area == 0) continue;
    for (int k = k0; k <= k1; ++k) {
      const double z = g.origin.z + (k + 0.5) * h + jitter * 1.7;
      for (int j = j0; j <= j1; ++j) {
        const double y = g.origin.y + (j + 0.5) * h + jitter;
        double w[3];
        for (int e = 0; e < 3; ++e) {
          const Vec3d& a = p[(e + 1) % 3];
          const Vec3d& c = p[(e + 2) % 3];
          w[e] = ((c.y - a.y) * (z - a.z) - (c.z - a.z) * (y - a.y)) / area;
        }
        if (w[0] < 0 || w[1] < 0 || w[2] < 0) continue;
        hits[size_t(k) * g.n[1] + j].push_back(w[0] * p[0].x + w[1] * p[1].x + w[2] * p[2].x);
      }
    }
  }
  g.in.assign(size_t(g.n[0]) * g.n[1] * g.n[2], 0);
  checkBudget(budget, "the voxelisation");
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j) {
      std::vector<double>& xs = hits[size_t(k) * g.n[1] + j];
      if (xs.size() % 2 != 0) continue;
      std::sort(xs.begin(), xs.end());
      for (size_t s = 0; s + 1 < xs.size(); s += 2)
        for (int i = 0; i < g.n[0]; ++i) {
          const double x = g.origin.x + (i + 0.5) * h;
          if (x > xs[s] && x < xs[s + 1]) g.in[g.index(i, j, k)] = 1;
        }
    }
  return g;
}

// Erosion (keep = all) or dilation (keep = any) by a (2r+1)^3 cube, as three 1-D filters:
// erosion keeps a voxel if every voxel within L∞ distance r is inside.
void morph(Grid& g, int r, bool dilate, const TimeBudget* budget) {
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<uint8_t> out(g.in.size(), 0);
    for (int k = 0; k < g.n[2]; ++k) {
      checkBudget(budget, "the erosion");
      for (int j = 0; j < g.n[1]; ++j)
        for (int i = 0; i < g.n[0]; ++i) {
          bool keep = !dilate;
          for (int d = -r; d <= r && keep != dilate; ++d) {
            int c[3] = {i, j, k};
            c[axis] += d;
            keep = g.at(c[0], c[1], c[2]);
          }
          out[g.index(i, j, k)] = keep;
        }
    }
    g.in.swap(out);
  }
}

// Removes voxels until no 2x2x2 block holds a critical configuration: two face-diagonal voxels
// without the other two of their square (edge case), or two antipodal voxels alone / the six
// others without them (vertex case).
void makeWellComposed(Grid& g, const TimeBudget* budget) {
  bool changed = true;
  while (changed) {
    changed = false;
    for (int k = -1; k < g.n[2]; ++k) {
      checkBudget(budget, "the erosion");
      for (int j = -1; j < g.n[1]; ++j)
        for (int i = -1; i < g.n[0]; ++i) {
          auto v = [&](int c) { return g.at(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1)); };
          auto clear = [&](int c) {
            g.in[g.index(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1))] = 0;
            changed = true;
          };
          int count = 0;
          for (int c = 0; c < 8; ++c) count += v(c);
          if (count == 0 || count == 8) continue;
          // Edge case: in each of the six faces of the block (bit `axis` fixed to `side`).
          for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side) {
              int q[4], m = 0;
              for (int c = 0; c < 8; ++c)
                if (((c >> axis) & 1) == side) q[m++] = c;
              // q[0],q[3] and q[1],q[2] are the diagonals of the square.
              if (v(q[0]) && v(q[3]) && !v(q[1]) && !v(q[2]))
                clear(q[0]);
              else if (v(q[1]) && v(q[2]) && !v(q[0]) && !v(q[3]))
                clear(q[1]);
            }
          // Vertex case: antipodal pairs c and 7-c.
          for (int c = 0; c < 4; ++c) {
            int others = 0;
            for (int e = 0; e < 8; ++e)
              if (e != c && e != 7 - c) others += v(e);
            if (v(c) && v(7 - c) && others == 0)
              clear(c);
            else if (!v(c) && !v(7 - c) && others == 6) {
              for (int e = 0; e < 8; ++e)
                if (e != c && e != 7 - c && v(e)) clear(e);
            }
          }
        }
    }
  }
}

// The voxel faces between inside and outside voxels, as two triangles each, sharing grid
// corners; outward oriented.
TriMesh extractBoundary(const Grid& g, const std::string& source, const TimeBudget* budget) {
  TriMesh mesh;
  mesh.source = source;
  const int cn[3] = {g.n[0] + 1, g.n[1] + 1, g.n[2] + 1};
  std::vector<uint32_t> corner(size_t(cn[0]) * cn[1] * cn[2], UINT32_MAX);
  auto vertex = [&](int i, int j, int k) {
    uint32_t& id = corner[(size_t(k) * cn[1] + j) * cn[0] + i];
    if (id == UINT32_MAX) {
      id = uint32_t(mesh.vertices.size());
      mesh.vertices.emplace_back(float(g.origin.x + i * g.h), float(g.origin.y + j * g.h),
                                 float(g.origin.z + k * g.h));
    }
    return id;
  };
  for (int k = 0; k < g.n[2]; ++k) {
    checkBudget(budget, "the erosion's surface extraction");
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        if (!g.at(i, j, k)) continue;
        for (int axis = 0; axis < 3; ++axis)
          for (int dir = -1; dir <= 1; dir += 2) {
            int c[3] = {i, j, k};
            c[axis] += dir;
            if (g.at(c[0], c[1], c[2])) continue;
            // Face at the side `dir` of axis `axis`; u, v span it so that u × v points along dir.
            const int u = (axis + 1) % 3, w = (axis + 2) % 3;
            int base[3] = {i, j, k};
            if (dir > 0) base[axis] += 1;
            int q[4][3];
            for (int m = 0; m < 4; ++m) {
              std::copy(base, base + 3, q[m]);
              const int du = (m == 1 || m == 2) ? 1 : 0, dw = (m >= 2) ? 1 : 0;
              q[m][u] += du;
              q[m][w] += dw;
            }
            uint32_t id[4];
            for (int m = 0; m < 4; ++m) id[m] = vertex(q[m][0], q[m][1], q[m][2]);
            if (dir > 0) {
              mesh.triangles.push_back({id[0], id[1], id[2]});
              mesh.triangles.push_back({id[0], id[2], id[3]});
            } else {
              mesh.triangles.push_back({id[0], id[2], id[1]});
              mesh.triangles.push_back({id[0], id[3], id[2]});
            }
          }
      }
  }
  return mesh;
}

}  // namespace

double erodeVoxelForBudget(const TriMesh& input, size_t max_faces, double voxel, double erosion) {
  double area = 0;
  for (const Triangle& t : input.triangles) {
    const Vec3d a(input.vertices[t[0]]), b(input.vertices[t[1]]), c(input.vertices[t[2]]);
    area += 0.5 * length(cross(b - a, c - a));
  }
  const double diag = input.diagonal();
  if (!(diag > 0) || max_faces == 0) return voxel;
  double h = std::sqrt(2 * area / (kErodeFacesPerBudgetFace * double(max_faces))) / diag;
  if (h <= voxel) return voxel;
  // The erosion is rounded up to whole voxels: a voxel that divides it erodes no deeper than
  // asked (one of 0.0116 for 0.0133 would erode 2 voxels, 0.023, and keep 0.36 of the bunny's
  // volume at 2 % instead of 0.48).
  if (h < erosion) h = erosion / std::floor(erosion / h);
  return std::min(h, std::max(voxel, 1.0 / 30));
}

TriMesh makeErodeProxy(const TriMesh& input, const ErodeOptions& options, InsideStats* stats) {
  // At most ~1000^3 voxels and an erosion no deeper than the mesh is wide.
  if (!(options.voxel >= 1e-3 && options.voxel <= 1) ||
      !(options.erosion >= 0 && options.erosion <= 1))
    throw Error("", "the voxel size must be in [0.001, 1] and the erosion in [0, 1]",
                "both are fractions of the diagonal");
  requireProxyGeometry(input, GeometryNeed::kSolid, "an erosion proxy");
  const double diag = input.diagonal();
  const double h = options.voxel * diag;
  Grid g = voxelize(input, h, options.budget);
  const int r = std::max(1, int(std::ceil(options.erosion / options.voxel - 1e-9)));
  // Opening: erode by r + 1, dilate by 1. The result is a subset of the r-eroded set without
  // parts thinner than about 3 voxels, which the budgeted inward collapse would otherwise press
  // flat (its two sheets meeting = a self-intersection).
  morph(g, r + 1, false, options.budget);
  morph(g, 1, true, options.budget);
  makeWellComposed(g, options.budget);
  size_t voxels = 0;
  for (uint8_t v : g.in) voxels += v;
  if (stats) stats->voxels = voxels;
  if (voxels == 0)
    throw Error(input.source, fmt::format("nothing is left after eroding by {} voxels", r),
                "the mesh is thinner than the erosion", "lower --erosion or the voxel size");
  return extractBoundary(g, "eroded " + input.source, options.budget);
}

}  // namespace proxyvis
