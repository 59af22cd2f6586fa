#pragma once
// An alpha_wrap_3 visitor that stops a running wrap when its time budget is
// spent or it inserts far more points than its estimate allowed. CGAL 5.5's wrapper has no
// go_further() hook; the visitor throws instead, from between two facet steps (the wrapper's
// state is then discarded by its destructors and nothing has been written to the output mesh).
// Pulls in CGAL; include it only from .cpp files.
#include <CGAL/alpha_wrap_3.h>

#include <cstddef>

#include "proxies/shared/time_budget.h"
#include "util/error.h"

namespace proxyvis::cgal {

class WrapBudgetVisitor : public CGAL::Alpha_wraps_3::internal::Wrapping_default_visitor {
 public:
  WrapBudgetVisitor(const TimeBudget* budget, double max_points, std::string source)
      : budget_(budget), max_points_(max_points), source_(std::move(source)) {}

  template <typename Wrapper, typename Gate>
  void before_facet_treatment(const Wrapper&, const Gate&) {
    if (++facets_ % 1024 == 0) checkBudget(budget_, "the alpha wrap");
  }

  template <typename Wrapper, typename VertexHandle>
  void after_Steiner_point_insertion(const Wrapper&, VertexHandle) {
    if (double(++points_) > max_points_)
      throw Error(source_, "stopped: the alpha wrap grew beyond its size estimate",
                  "the wrap would need more memory than a proxy is worth",
                  "use a larger --alpha or a smaller --offset");
  }

 private:
  const TimeBudget* budget_;
  double max_points_;
  std::string source_;
  size_t facets_ = 0, points_ = 0;
};

}  // namespace proxyvis::cgal
