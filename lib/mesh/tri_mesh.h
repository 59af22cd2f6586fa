#pragma once
// The one triangle-mesh type of proxyvis: an indexed triangle list with float positions (what the
// file formats store and Embree traces). Polygons are triangulated on load; no other attributes.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "util/vec3.h"

namespace proxyvis {

using Triangle = std::array<uint32_t, 3>;

struct TriMesh {
  std::vector<Vec3f> vertices;
  std::vector<Triangle> triangles;
  // Where it came from (file path or a generator's name), used in messages.
  std::string source;

  size_t numVertices() const { return vertices.size(); }
  size_t numTriangles() const { return triangles.size(); }
  bool empty() const { return triangles.empty(); }

  // Box of the vertices that triangles reference.
  Bounds3f bounds() const {
    Bounds3f b;
    for (const Triangle& t : triangles)
      for (uint32_t i : t) b.extend(vertices[i]);
    return b;
  }
  float diagonal() const { return bounds().diagonal(); }

  // Signed volume by the divergence theorem; positive for a closed outward-oriented mesh.
  // Meaningless for an open mesh.
  double signedVolume() const {
    double v = 0;
    for (const Triangle& t : triangles) {
      Vec3d a(vertices[t[0]]), b(vertices[t[1]]), c(vertices[t[2]]);
      v += dot(a, cross(b, c));
    }
    return v / 6.0;
  }
};

}  // namespace proxyvis
