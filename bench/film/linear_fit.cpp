#include "linear_fit.h"

#include <algorithm>
#include <cmath>

namespace proxyvis::bench {

std::optional<LinearFit2> fitLinear2(const std::vector<double>& x1, const std::vector<double>& x2,
                                     const std::vector<double>& y) {
  const size_t n = y.size();
  if (n < 3 || x1.size() != n || x2.size() != n) return std::nullopt;
  // Scale the columns to about 1 so the normal equations stay well conditioned (x1 ~ 1e7).
  double s1 = 0, s2 = 0;
  for (size_t i = 0; i < n; ++i) {
    s1 = std::max(s1, std::abs(x1[i]));
    s2 = std::max(s2, std::abs(x2[i]));
  }
  if (s1 == 0 || s2 == 0) return std::nullopt;
  double m[3][4] = {};
  for (size_t i = 0; i < n; ++i) {
    const double row[3] = {x1[i] / s1, x2[i] / s2, 1.0};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) m[r][c] += row[r] * row[c];
      m[r][3] += row[r] * y[i];
    }
  }
  // Gauss-Jordan elimination with partial pivoting.
  for (int col = 0; col < 3; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 3; ++r)
      if (std::abs(m[r][col]) > std::abs(m[pivot][col])) pivot = r;
    if (std::abs(m[pivot][col]) < 1e-9 * double(n)) return std::nullopt;
    std::swap(m[pivot], m[col]);
    for (int r = 0; r < 3; ++r) {
      if (r == col) continue;
      const double f = m[r][col] / m[col][col];
      for (int c = col; c < 4; ++c) m[r][c] -= f * m[col][c];
    }
  }
  LinearFit2 fit;
  fit.a = m[0][3] / m[0][0] / s1;
  fit.b = m[1][3] / m[1][1] / s2;
  fit.c = m[2][3] / m[2][2];
  for (size_t i = 0; i < n; ++i) {
    const double predicted = fit.a * x1[i] + fit.b * x2[i] + fit.c;
    if (y[i] != 0)
      fit.max_relative_residual =
          std::max(fit.max_relative_residual, std::abs(y[i] - predicted) / std::abs(y[i]));
  }
  return fit;
}

}  // namespace proxyvis::bench
