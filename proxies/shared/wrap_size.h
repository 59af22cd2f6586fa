#pragma once
// How large an alpha wrap (outer or inner) may get: an estimate checked before the wrap starts,
// and the bound its budget visitor (cgal/wrap_budget.h) enforces while it runs.
#include "mesh/tri_mesh.h"

namespace proxyvis {

// The most faces a wrap may be estimated to have (estimateWrapFaces): beyond it the wrap needs
// more memory and time than a proxy is worth. The estimate is about 6 times what is built: on
// the bunny, alpha 1/100 is estimated at 89 k faces and builds 13.9 k; alpha 1/250 at 555 k and
// builds 78 k (39 s, 130 MB for the whole run). The wrap itself stops after a quarter of this
// many Steiner points (about half as many faces), in case the estimate is ever too low.
inline constexpr double kMaxEstimatedWrapFaces = 4e6;

// An upper estimate of the faces of an alpha wrap (outer or inner) of `input` with alpha and
// offset as fractions of the diagonal: the surface the wrap can have (the input's area plus the
// box grown by the offset) covered by triangles of edge ~alpha. Cheap; used to refuse a wrap
// that would not finish before it starts.
double estimateWrapFaces(const TriMesh& input, double alpha, double offset);

// Throws Error naming the input when estimateWrapFaces exceeds kMaxEstimatedWrapFaces.
void requireWrapSize(const TriMesh& input, double alpha, double offset, const char* what);

}  // namespace proxyvis
