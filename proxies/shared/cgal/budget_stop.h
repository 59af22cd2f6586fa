#pragma once
// A stop predicate for CGAL's edge_collapse that stops at an edge count or
// as soon as a time budget is spent. edge_collapse then returns normally; the caller checks the
// budget afterwards and throws. Pulls in CGAL; include it only from .cpp files.
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>

#include <cstddef>

#include "proxies/shared/time_budget.h"

namespace proxyvis::cgal {

template <typename Mesh>
struct CountOrBudgetStop {
  CGAL::Surface_mesh_simplification::Count_stop_predicate<Mesh> count;
  const TimeBudget* budget = nullptr;

  template <typename F, typename Profile>
  bool operator()(const F& cost, const Profile& profile, std::size_t initial,
                  std::size_t current) const {
    return count(cost, profile, initial, current) || (budget && budget->expired());
  }
};

}  // namespace proxyvis::cgal
