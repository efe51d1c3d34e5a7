// SPDX-License-Identifier: MIT
#include "xfem/system/integration_cost.h"

#include <cmath>

#include "xfem/core/error.h"

namespace xfem {

double integration_points_estimate(const EnrichedMesh& em, const Problem& problem, int points, int refine,
                                   long* enriched_tets) {
  const bool conforming = problem.rule == Problem::Rule::Conforming;
  const double m = std::floor(std::cbrt(static_cast<double>(points))) + 1;  // m^3 > points
  // The pieces off the front take the most points: (order + 1)^3 (TetRuleLayout::of_order), graded and fast 4^3.
  const double n3 = problem.graded || problem.fast ? 64.0 : std::pow(problem.order + (problem.uniform ? 0 : 1), 3);
  double estimate = 0;
  *enriched_tets = 0;
  for (int t = 0; t < em.tets(); ++t) {
    if (em.size(t) == 4) continue;
    ++*enriched_tets;
    const bool cut = em.cut_class[t] != 0;
    // Conforming: a cut tet splits into about 24 sub-tets of n^3 points. Oversampling: m^3
    // points, and refinement splits the ~m^2 sub-tets the cut crosses into 8, `refine` times.
    estimate += conforming ? (cut ? 24 : 1) * n3 : m * m * m + (cut ? m * m * std::pow(8.0, refine) : 0.0);
  }
  return estimate;
}

double check_integration_cost(const EnrichedMesh& em, const Problem& problem, int points, int refine, bool allow_large,
                              const std::string& input) {
  long enriched_tets = 0;
  const double estimate = integration_points_estimate(em, problem, points, refine, &enriched_tets);
  if (estimate > 2e8 && !allow_large)
    throw Error(input + ": about " + short_number(estimate) + " integration points in " + std::to_string(enriched_tets) +
                " enriched tets (limit 2e8: lower --points/--refine/--order, or give --allow-large)");
  return estimate;
}

}  // namespace xfem
