// SPDX-License-Identifier: MIT
// Fixed-corotated elasticity (Stomakhin, Howes, Schroeder, Teran 2012, "Energetically consistent
// invertible elasticity"): Psi = mu |F - R|^2 + lambda/2 (J - 1)^2, docs/METHOD.md "Material models".
#include "xfem/integrate/material_corotational.h"

#include <algorithm>

namespace xfem {
namespace {

// dR/dF divides by sigma_a + sigma_b, which vanishes only where the polar rotation itself is not
// unique (sigma_1 = -sigma_2 of an inverted F, or two zero singular values). There the tangent's
// rotation part is clamped to mu / kRotationSumFloor, as the literature does: P stays exact,
// only the Newton tangent is approximate at such (degenerate) points. Singular values are
// dimensionless, so the floor is too.
constexpr double kRotationSumFloor = 1e-6;

// d R / d F_kL for the unit direction dF = e_k e_L^T. With F = R S and W = R^T dR (skew):
// W S + S W = R^T dF - dF^T R. In the basis V (S = V diag(sigma) V^T) this is diagonal:
// W'_ab (sigma_a + sigma_b) = dF'_ab - dF'_ba with dF' = U^T dF V, and dR = U W' V^T.
Eigen::Matrix3d rotation_derivative(const RotationVariantSvd& s, int k, int L) {
  const Eigen::Matrix3d dF = s.U.row(k).transpose() * s.V.row(L);  // U^T e_k e_L^T V
  Eigen::Matrix3d W = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 3; ++a)
    for (int b = a + 1; b < 3; ++b) {
      const double w = (dF(a, b) - dF(b, a)) / std::max(s.sigma(a) + s.sigma(b), kRotationSumFloor);
      W(a, b) = w;
      W(b, a) = -w;
    }
  return s.U * W * s.V.transpose();
}

}  // namespace

RotationVariantSvd rotation_variant_svd(const Eigen::Matrix3d& F) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
  RotationVariantSvd s{svd.matrixU(), svd.matrixV(), svd.singularValues()};  // sorted decreasing
  if (s.U.determinant() * s.V.determinant() < 0) {
    s.U.col(2) *= -1.0;
    s.sigma(2) *= -1.0;
  }
  return s;
}

void corotational_stress(const Lame& lame, const Eigen::Matrix3d& F, StressAt& out) {
  const double mu = lame.mu, lambda = lame.lambda;
  const RotationVariantSvd s = rotation_variant_svd(F);
  const Eigen::Matrix3d R = s.U * s.V.transpose();
  const double J = F.determinant();
  const Eigen::Matrix3d C = cofactor(F);  // dJ/dF = J F^-T, defined for every F
  out.energy = mu * (s.sigma.array() - 1.0).square().sum() + 0.5 * lambda * (J - 1.0) * (J - 1.0);
  out.P = 2.0 * mu * (F - R) + lambda * (J - 1.0) * C;

  const Eigen::Matrix<double, 9, 9> H = cofactor_derivative(F);
  for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L) {
      const Eigen::Matrix3d dR = rotation_derivative(s, k, L);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const double identity = (i == k && j == L) ? 1.0 : 0.0;
          out.A(3 * i + j, 3 * k + L) = 2.0 * mu * (identity - dR(i, j)) + lambda * C(i, j) * C(k, L) +
                                        lambda * (J - 1.0) * H(3 * i + j, 3 * k + L);
        }
    }
}

}  // namespace xfem
