#include "estimate/selection.h"

#include <cmath>
#include <limits>

#include "util/error.h"

namespace proxyvis {

namespace {

// a / p with the conventions of selectionVariance: 0/0 = 0, a/0 = inf.
double termOver(double a, double p) {
  if (a <= 0) return 0.0;
  return p > 0 ? a / p : std::numeric_limits<double>::infinity();
}

}  // namespace

double selectionVariance(const ClassProbabilities& c, const SelectionProbabilities& p) {
  const double v = c.vAvg();
  const double a0 = (1 - v) * (1 - c.fHit()) + v * c.fMiss();  // P(HM') + P(MM')
  const double a_plus = v * (1 - c.fMiss());                   // P(MH')
  const double a_minus = (1 - v) * (1 - c.fHit());             // P(HM')
  return termOver(a0, p.p0) + termOver(a_plus, p.p_plus) + termOver(a_minus, p.p_minus) - v * v;
}

double selectionVarianceSlideMisprint(const ClassProbabilities& c,
                                      const SelectionProbabilities& p) {
  const double v = c.vAvg();
  const double a0 = (1 - v) * (1 - c.fHit()) + v * c.fMiss();
  const double a_plus = v * (1 - c.fMiss());
  const double a_minus = (1 - v) * (1 - c.fHit());
  return termOver(a0, p.p0) + termOver(a_plus, p.p_plus) + termOver(a_minus, p.p_plus) - v * v;
}

SelectionRays selectionRays(const ClassProbabilities& c, const SelectionProbabilities& p) {
  return {1.0, p.p_plus * c.proxyBlocked() + p.p_minus * c.proxyVisible()};
}

SelectionProbabilities equalProbabilities(ProxyClass c) {
  switch (c) {
    case ProxyClass::kOutside:
      return {0.5, 0.5, 0.0};
    case ProxyClass::kInside:
      return {0.5, 0.0, 0.5};
    case ProxyClass::kGeneral:
      break;
  }
  return {1.0 / 3, 1.0 / 3, 1.0 / 3};
}

SelectionProbabilities optimalProbabilities(const ClassProbabilities& c, ProxyClass cls) {
  const double s0 = std::sqrt(c.proxyVisible());
  const double s_plus = cls == ProxyClass::kInside ? 0.0 : std::sqrt(c.mh);
  const double s_minus = cls == ProxyClass::kOutside ? 0.0 : std::sqrt(c.hm);
  const double sum = s0 + s_plus + s_minus;
  if (!(sum > 0)) return {1.0, 0.0, 0.0};
  return {s0 / sum, s_plus / sum, s_minus / sum};
}

SelectionProbabilities costHeuristicProbabilities(const SelectionProbabilities& optimal,
                                                  double error) {
  PV_CHECK(error >= 0 && error <= 1);
  const double f = std::pow(error, 0.25);
  SelectionProbabilities p{0, f * optimal.p_plus, f * optimal.p_minus};
  p.p0 = 1 - p.p_plus - p.p_minus;
  return p;
}

}  // namespace proxyvis
