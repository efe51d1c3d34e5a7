// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>

#include "xfem/integrate/material_law.h"

namespace xfem {

/// What deformed.vtu shows of one cell (docs/FORMATS.md "deformed.vtu"), from the displacement
/// gradient G = grad u at its centroid, F = I + G.
struct CellStress {
  /// Linear: the small strain sym(G). Other models: the Green-Lagrange strain (F^T F - I) / 2,
  /// zero under any rigid rotation, dimensionless.
  Eigen::Matrix3d strain = Eigen::Matrix3d::Zero();
  /// Linear: Hooke's sigma = lambda tr(eps) I + 2 mu eps. Other models: the Cauchy stress
  /// P F^T / det F of the model's first Piola stress P (material_law.h), made exactly symmetric;
  /// 0 for an inverted cell (det F <= 0), where it is undefined. Pa.
  Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();
  double det_F = 1.0;  ///< J = det F; <= 0 (or not finite): the cell is turned inside out
  bool inverted() const { return !(det_F > 0); }
};

/// The cell's strain and stress under `law` for displacement gradient G (row i, column j:
/// du_i/dx_j). The Linear law's stress is the expression xfem-visualize always wrote, bit for bit.
CellStress cell_stress(const MaterialLaw& law, const Eigen::Matrix3d& G);

}  // namespace xfem
