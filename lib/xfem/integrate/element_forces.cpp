// SPDX-License-Identifier: MIT
#include "xfem/integrate/element_forces.h"

#include <Eigen/Eigenvalues>

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
  // B (9 x 3n): d vec(F) / d ue, vec(F)[3 i + J] = F_iJ, so that r = sum w B^T vec(P) and
  // k = sum w B^T A B.
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(9, 3 * n);
  const double volume = points.weight.sum();
  for (int p = 0; p < points.size(); ++p) {
    const Eigen::Matrix3d F = deformation_gradient(points, p, ue);
    const double J = F.determinant();
    out.min_J = std::min(out.min_J, J);
    if (law.model != MaterialModel::Linear && !(J > 0.0)) {
      if (points.weight[p] < 1e-9 * volume) continue;
      return false;
    }
    if (!stress_at(law, F, s)) return false;
    const double w = points.weight[p];
    for (int c = 0; c < n; ++c)
      for (int i = 0; i < 3; ++i)
        for (int J2 = 0; J2 < 3; ++J2) B(3 * i + J2, 3 * c + i) = points.gradient(p, 3 * c + J2);
    Eigen::Matrix<double, 9, 1> P;
    for (int i = 0; i < 3; ++i)
      for (int J2 = 0; J2 < 3; ++J2) P[3 * i + J2] = s.P(i, J2);
    out.energy += w * s.energy;
    out.r.noalias() += w * B.transpose() * P;
    if (tangent && kind == Tangent::Projected) {
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>> eigen(s.A);
      s.A = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() * eigen.eigenvectors().transpose();
    }
    if (tangent) out.k.noalias() += w * B.transpose() * s.A * B;
  }
  return true;
}

}  // namespace xfem
