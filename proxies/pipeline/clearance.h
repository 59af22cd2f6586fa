#pragma once
// The clearance of outside and inside proxies (docs/clearance.md): the least distance a written
// proxy keeps from its input, so that its class still holds when either mesh's coordinates move
// a little. They do move: a text file's decimals round to float in proxyvis and to double in a
// CAD tool, and a placement's transform rounds the placed coordinates again. When both surfaces
// are at least `d` apart and no vertex of either moves by more than d/2, no point of either
// surface moves by more than d/2 (a triangle's points are convex combinations of its corners),
// so the surfaces never meet on the way and the class is kept.
#include <optional>
#include <vector>

#include "mesh/tri_mesh.h"
#include "util/affine3.h"
#include "util/proxy_class.h"

namespace proxyvis {

// The default clearance in ulps of float at the input's largest coordinate: a decimal rounds to
// float and to double at most half an ulp apart per coordinate (0.87 ulp per vertex, 1.73 for
// the two meshes together); the rest covers a placement that rounds each placed coordinate by
// up to about three ulps more (the renderer's own placement is verified where it happens).
inline constexpr double kDefaultClearanceUlps = 8;

// The spacing of floats at `magnitude` (ulp of the float binade holding it; the smallest normal
// spacing for 0).
double floatUlp(double magnitude);

// The largest absolute coordinate of the mesh's vertices.
double largestCoordinate(const TriMesh& mesh);

// The clearance in scene units: `distance` when given, else `ulps` (default
// kDefaultClearanceUlps) x floatUlp(largest coordinate of the input), or more where one of
// `placements` needs it (placementClearance).
double clearanceDistance(const TriMesh& input, std::optional<double> distance,
                         std::optional<double> ulps, const std::vector<Affine3f>& placements = {});

// The clearance, in the mesh's own units, that keeps a class on the float copies placed by
// `to_world` (Affine3f::apply, as the tracer places a mesh): `ulps` ulps of float at the largest
// magnitude the placement's arithmetic handles (each row's sum of |m_ij x_j| + |t_i| over the
// mesh's box: a float product and sum err by a few ulps of that), mapped back to the mesh's units
// by the transform's smallest singular value (the most it shrinks a distance). 0 for a singular
// transform (nothing can be kept; the renderer refuses it).
double placementClearance(const TriMesh& mesh, const Affine3f& to_world, double ulps);

// The proxy with every vertex moved away from the input by at least `distance` along its
// normal: outward for an outside proxy, inward for an inside one (the side follows from the
// sign of the proxy's volume, so either orientation works). Each vertex moves far enough that
// the planes of all its faces move by `distance` plus two ulps (what rounding to float may take
// back): along its normal where its faces are within 60 degrees of it, else by the least such
// move a small LP finds (at most 20 times the distance; a vertex with none stays).
TriMesh pushedAway(const TriMesh& proxy, ProxyClass kind, double distance);

}  // namespace proxyvis
