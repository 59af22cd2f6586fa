#include "proxies/shared/wrap_size.h"

#include <fmt/core.h>

#include "util/error.h"

namespace proxyvis {

double estimateWrapFaces(const TriMesh& input, double alpha, double offset) {
  Bounds3d box;
  double area = 0;
  for (const Triangle& t : input.triangles) {
    const Vec3d a(input.vertices[t[0]]), b(input.vertices[t[1]]), c(input.vertices[t[2]]);
    box.extend(a);
    box.extend(b);
    box.extend(c);
    area += 0.5 * length(cross(b - a, c - a));
  }
  const double diag = box.diagonal();
  const Vec3d e = box.extent() + Vec3d(2, 2, 2) * (offset * diag);
  const double box_area = 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
  const double edge = alpha * diag;
  // An equilateral triangle of edge `edge` covers 0.433 edge^2; count both sides of the input.
  return (box_area + 2 * area) / (0.433 * edge * edge);
}

void requireWrapSize(const TriMesh& input, double alpha, double offset, const char* what) {
  const double faces = estimateWrapFaces(input, alpha, offset);
  if (!(faces <= kMaxEstimatedWrapFaces))
    throw Error(input.source,
                fmt::format("{} with alpha {:g} and offset {:g} would have about {:.3g} faces, "
                            "more than {:g}",
                            what, alpha, offset, faces, kMaxEstimatedWrapFaces),
                "it would take too much memory and time",
                "use a larger --alpha or a smaller --offset");
}

}  // namespace proxyvis
