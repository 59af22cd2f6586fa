#pragma once
// Least-squares fit of y = a*x1 + b*x2 + c (the film-scale memory model: bytes = a * prototype
// triangles + b * instances + c), by the 3x3 normal equations.
#include <optional>
#include <vector>

namespace proxyvis::bench {

struct LinearFit2 {
  double a = 0, b = 0, c = 0;
  double max_relative_residual = 0;  // max |y - fit| / y over the points
};

// Empty when the points do not determine the three coefficients (fewer than 3, or x1/x2
// collinear over them).
std::optional<LinearFit2> fitLinear2(const std::vector<double>& x1, const std::vector<double>& x2,
                                     const std::vector<double>& y);

}  // namespace proxyvis::bench
