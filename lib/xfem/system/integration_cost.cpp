// SPDX-License-Identifier: MIT
#include "xfem/system/integration_cost.h"

#include <cmath>

namespace xfem {

double integration_points_estimate(const EnrichedMesh& em, const Problem& problem, int points, int refine,
                                   long* enriched_tets) {
  const bool conforming = problem.rule == Problem::Rule::Conforming;
  const double m = std::floor(std::cbrt(static_cast<double>(points))) + 1;  // m^3 > points
  const double n3 = problem.graded ? 64.0 : std::pow(problem.order, 3);  // graded: 4^3 on pieces off the front
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

}  // namespace xfem
