// SPDX-License-Identifier: MIT
#include "xfem/integrate/element_forces.h"

#include <Eigen/Eigenvalues>
#include <array>

namespace xfem {

Eigen::Matrix3d deformation_gradient(const ElementPoints& points, int p, const Eigen::VectorXd& ue) {
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  const int n = static_cast<int>(ue.size() / 3);
  for (int c = 0; c < n; ++c)
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 3; ++J) F(i, J) += ue[3 * c + i] * points.gradient(p, 3 * c + J);
  return F;
}

bool element_forces(const ElementPoints& points, const MaterialLaw& law, const Eigen::VectorXd& ue, bool tangent,
                    ElementForces& out, Tangent kind) {
  const int n = static_cast<int>(ue.size() / 3);
  out.energy = 0.0;
  out.min_J = std::numeric_limits<double>::infinity();
  out.r.setZero(3 * n);
  if (tangent) out.k.setZero(3 * n, 3 * n);
  StressAt s;
  // With G the point's gradients (n x 3, row c = grad Phi_c): r[3c + i] = sum_p w P_iJ G_cJ, and
  // k[3c + i][3d + k] = sum_p w G_cJ A(3i + J, 3k + L) G_dL, accumulated as the 9 n x n blocks
  // (i, k) and arranged at the end: the structure of dF/dU, without its zeros.
  Eigen::Matrix<double, Eigen::Dynamic, 3> G(n, 3), R = Eigen::Matrix<double, Eigen::Dynamic, 3>::Zero(n, 3);
  std::array<Eigen::MatrixXd, 9> blocks;
  if (tangent)
    for (Eigen::MatrixXd& b : blocks) b.setZero(n, n);
  Eigen::Matrix<double, Eigen::Dynamic, 9> H(n, 9);
  const double volume = points.weight.sum();
  for (int p = 0; p < points.size(); ++p) {
    const Eigen::Matrix3d F = deformation_gradient(points, p, ue);
    const double J = F.determinant();
    out.min_J = std::min(out.min_J, J);
    if (law.model != MaterialModel::Linear && !(J > 0.0)) {
      if (points.weight[p] < 1e-9 * volume) continue;  // next to a crack front: docs/METHOD.md
      return false;
    }
    if (!stress_at(law, F, s)) return false;
    const double w = points.weight[p];
    for (int c = 0; c < n; ++c) G.row(c) = points.gradient.block<1, 3>(p, 3 * c);
    out.energy += w * s.energy;
    R.noalias() += w * G * s.P.transpose();
    if (!tangent) continue;
    if (kind == Tangent::Projected) {
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>> eigen(s.A);
      s.A = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() * eigen.eigenvectors().transpose();
    }
    for (int i = 0; i < 3; ++i) {
      H.noalias() = w * G * s.A.block<3, 9>(3 * i, 0);
      for (int k = 0; k < 3; ++k) blocks[3 * i + k].noalias() += H.middleCols<3>(3 * k) * G.transpose();
    }
  }
  for (int c = 0; c < n; ++c)
    for (int i = 0; i < 3; ++i) out.r[3 * c + i] = R(c, i);
  if (tangent)
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k)
        for (int d = 0; d < n; ++d)
          for (int c = 0; c < n; ++c) out.k(3 * c + i, 3 * d + k) = blocks[3 * i + k](c, d);
  return true;
}

}  // namespace xfem
