// SPDX-License-Identifier: MIT
#include "xfem/fracture/front_cost.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "xfem/core/error.h"

namespace xfem {

FrontCost front_cost(const EnrichedMesh& em, const std::vector<FrontPolyline>& chains,
                     const std::vector<std::vector<double>>& node_rho, double R, double spacing, int order) {
  const TetMesh& mesh = em.mesh;
  const double n3 = std::pow(order, 3);
  const double near_levels = std::min(8, (order - 2) * (order - 2)), far_levels = std::min(8, std::max(0, 2 * (order - 3)));
  double h = 0.0;  // the longest edge: how far the interpolated q reaches beyond its nodes
  FrontCost cost;
  for (int t = 0; t < em.tets(); ++t) {
    bool near = false, cut = !em.cut_class.empty() && em.cut_class[t] != 0;
    for (const CutLayer& c : em.cuts) cut = cut || c.cut_class[t] != 0;
    for (int i = 0; i < 4; ++i) {
      const int n = mesh.tets(t, i);
      for (const auto& rho : node_rho) near = near || rho[n] < R;
      for (int j = i + 1; j < 4; ++j) h = std::max(h, (mesh.points.row(n) - mesh.points.row(mesh.tets(t, j))).norm());
    }
    if (near) cost.integration_points += n3 * (cut ? 16 * (near_levels + 1) : 1 + far_levels / 2);
  }
  const double d = spacing > 0 ? spacing : R;
  // In double: a spacing of 1e-12 m must give a large number, not an overflowed int.
  for (const FrontPolyline& ch : chains) cost.points += std::max(1.0, std::round(ch.length / d)) + (ch.closed ? 0 : 1);
  cost.trace_points = cost.points * 2 * std::max(128.0, 64.0 * (2 * d + 4 * h) / d);
  cost.evaluations = cost.integration_points * std::min(cost.points, 2 * (d + 2 * h) / d);
  return cost;
}

void check_front_cost(const FrontCost& c, bool allowed) {
  if (allowed) return;
  if (c.points <= kMaxFrontPoints && c.trace_points <= kMaxFrontTracePoints &&
      c.integration_points <= kMaxFrontIntegrationPoints && c.evaluations <= kMaxFrontEvaluations)
    return;
  throw Error("about " + short_number(c.points) + " front points, " + short_number(c.trace_points) +
              " evaluations of the weight along the front, " + short_number(c.integration_points) +
              " integration points and " + short_number(c.evaluations) + " integrand evaluations requested (limits " +
              short_number(kMaxFrontPoints) + ", " + short_number(kMaxFrontTracePoints) + ", " +
              short_number(kMaxFrontIntegrationPoints) + ", " + short_number(kMaxFrontEvaluations) +
              "; a larger --spacing or --radius, a lower --order, or --allow-large)");
}

}  // namespace xfem
