// SPDX-License-Identifier: MIT
#include "xfem/system/deformed_volume_at_points.h"

namespace xfem {

PointVolume deformed_volume_at_points(const EnrichedMesh& em, const BodyIntegration& body, const Eigen::VectorXd& u) {
  PointVolume v;
  Eigen::VectorXd ue;
  for (int t = 0; t < em.tets(); ++t) {
    const ElementPoints& points = body.tets[static_cast<std::size_t>(t)];
    const long base = em.offsets[t];
    ue.resize(3 * em.size(t));
    for (int c = 0; c < em.size(t); ++c) ue.segment<3>(3 * c) = u.segment<3>(3 * em.dofs[base + c]);
    PointVolume::Part& kind = em.plain(t) ? v.plain : em.branch(t) ? v.branch : v.sign;
    const double tet_volume = points.weight.sum();
    double before = 0.0, after = 0.0, largest = 0.0;
    bool any = false;
    for (int p = 0; p < points.size(); ++p) {
      const double J = deformation_gradient(points, p, ue).determinant();
      before += points.weight[p];
      after += points.weight[p] * J;
      // The points next to a front (element_forces.h) carry no volume worth naming as "largest".
      if (points.weight[p] >= next_to_front_weight * tet_volume && (!any || J > largest)) largest = J, any = true;
    }
    for (PointVolume::Part* part : {&kind, &v.body}) {
      ++part->tets;
      part->before += before;
      part->after += after;
      if (any && (part->max_J_tet < 0 || largest > part->max_J)) {
        part->max_J = largest;
        part->max_J_tet = t;
      }
    }
  }
  for (PointVolume::Part* part : {&v.body, &v.plain, &v.sign, &v.branch})
    if (part->max_J_tet >= 0)
      for (int k = 0; k < 4; ++k)
        part->max_J_at += em.mesh.points.row(em.mesh.tets(part->max_J_tet, k)).transpose() / 4.0;
  return v;
}

}  // namespace xfem
