#pragma once
// Sample moments for comparing a measured variance with a closed form. The standard error of the
// sample variance s^2 of N i.i.d. values is sqrt((mu4 - sigma^4) / N) to first order (Cramer
// 1946, §27.4), with mu4 the fourth central moment, both measured.
#include <cmath>
#include <vector>

namespace proxyvis::test {

struct Moments {
  double mean = 0, variance = 0, variance_se = 0;
  size_t n = 0;
};

inline Moments moments(const std::vector<double>& x) {
  Moments m;
  m.n = x.size();
  for (double v : x) m.mean += v;
  m.mean /= double(m.n);
  double m2 = 0, m4 = 0;
  for (double v : x) {
    const double d = (v - m.mean) * (v - m.mean);
    m2 += d;
    m4 += d * d;
  }
  m.variance = m2 / double(m.n - 1);
  const double mu4 = m4 / double(m.n);
  m.variance_se = std::sqrt(std::max(0.0, mu4 - m.variance * m.variance) / double(m.n));
  return m;
}

}  // namespace proxyvis::test
