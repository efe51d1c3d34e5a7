// SPDX-License-Identifier: MIT
#include "xfem/post/cell_stress.h"

namespace xfem {

CellStress cell_stress(const MaterialLaw& law, const Eigen::Matrix3d& G) {
  CellStress c;
  const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + G;
  c.det_F = F.determinant();
  if (law.model == MaterialModel::Linear) {
    // Defined for any G, inverted or not: what the linear tools always showed.
    c.strain = 0.5 * (G + G.transpose());
    c.stress = law.lame.lambda * c.strain.trace() * Eigen::Matrix3d::Identity() + 2 * law.lame.mu * c.strain;
    return c;
  }
  c.strain = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
  StressAt s;
  // sigma = P F^T / J has no meaning for J <= 0 (and neo-Hookean no energy): 0, counted by the caller.
  if (c.inverted() || !stress_at(law, F, s)) return c;
  const Eigen::Matrix3d sigma = cauchy_stress(s.P, F);
  c.stress = 0.5 * (sigma + sigma.transpose());  // symmetric up to round-off; VTK stores 6 components
  return c;
}

}  // namespace xfem
