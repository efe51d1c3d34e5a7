// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>

#include "xfem/core/mesh.h"

namespace xfem {

/// The linear shape functions N_0..N_3 of one tetrahedron (paper 3.4): N_m is the barycentric
/// coordinate of node m, so N_m(P_n) = delta_mn; the gradients are constant over the tet.
struct TetShape {
  Eigen::Matrix<double, 4, 3> grad;  ///< row m: grad N_m, 1/metre
  Eigen::Vector3d centroid;          ///< metres; N_m(centroid) = 1/4
  double volume = 0.0;               ///< m^3, positive for a positively oriented tet

  /// N_0..N_3 at x (any x: outside the tet some are negative).
  Eigen::Vector4d values(const Eigen::Vector3d& x) const {
    return Eigen::Vector4d::Constant(0.25) + grad * (x - centroid);
  }
};

/// Shape functions of the tet (p0, p1, p2, p3). Throws xfem::Error if it has zero volume
/// (the readers reject such tets, so this only guards hand-built data).
TetShape tet_shape(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                   const Eigen::Vector3d& p3);
TetShape tet_shape(const TetMesh& mesh, int tet);

/// The point with barycentric coordinates `lambda` (sum 1) in tet `tet`: sum lambda_m P_m.
Eigen::Vector3d tet_point(const TetMesh& mesh, int tet, const Eigen::Vector4d& lambda);

}  // namespace xfem
