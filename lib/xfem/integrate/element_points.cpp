// SPDX-License-Identifier: MIT
#include "xfem/integrate/element_points.h"

#include <cmath>
#include <vector>

#include "xfem/geometry/tet_shape.h"
#include "xfem/integrate/closed_form_stiffness.h"
#include "xfem/integrate/straight_front_rule.h"

namespace xfem {

void element_points(const EnrichedMesh& em, const CutElementSplits& splits, int t, int order,
                    FaceIntegralCache* face_cache, ElementPoints& out) {
  const int n = em.size(t);
  const long base = em.offsets[t];
  if (em.plain(t)) {
    const TetShape shape = tet_shape(em.mesh, t);
    out.weight.setConstant(1, std::abs(shape.volume));
    out.gradient.resize(1, 3 * n);
    for (int c = 0; c < n; ++c)
      for (int a = 0; a < 3; ++a) out.gradient(0, 3 * c + a) = shape.grad(em.local[base + c], a);
    return;
  }
  PointRule rule;
  conforming_rule(em, splits, t, order, rule);
  const int straight_points = straight_front_angle_points(order);
  Eigen::MatrixXd gradients(rule.size(), 3 * n);
  std::vector<TipCoordinates> tips;
  sampled_gradients(em, t, rule, order, face_cache, std::vector<int>(), gradients, tips, 0, nullptr, straight_points);
  const bool branch = em.branch(t);
  const int q = rule.size();
  out.correction.resize(0, 0);
  if (branch) {
    out.weight = Eigen::Map<const Eigen::VectorXd>(rule.weights.data(), q);
    out.gradient = std::move(gradients);
    ClosedFormWorkspace work;
    if (straight_front_rule(em, splits, t, straight_points, work.straight))
      out.correction = closed_form_moments(em, splits, t, PointRule(), order, face_cache, 0, work, &work.straight,
                                           straight_points) -
                       out.gradient.transpose() * out.weight.asDiagonal() * out.gradient;
    return;
  }
  // Sign enrichment only: one point per distinct gradient row (one per side or region).
  std::vector<int> first;       // the distinct rows, by their first point
  std::vector<double> weights;  // their summed weights
  for (int p = 0; p < q; ++p) {
    std::size_t k = 0;
    while (k < first.size() && gradients.row(first[k]) != gradients.row(p)) ++k;
    if (k == first.size()) {
      first.push_back(p);
      weights.push_back(0.0);
    }
    weights[k] += rule.weights[p];
  }
  out.weight = Eigen::Map<const Eigen::VectorXd>(weights.data(), static_cast<long>(weights.size()));
  out.gradient.resize(static_cast<long>(first.size()), 3 * n);
  for (std::size_t k = 0; k < first.size(); ++k) out.gradient.row(static_cast<long>(k)) = gradients.row(first[k]);
}

}  // namespace xfem
