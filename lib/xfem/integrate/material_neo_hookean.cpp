// SPDX-License-Identifier: MIT
// Compressible neo-Hookean: Psi = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2, docs/METHOD.md
// "Material models".
#include "xfem/integrate/material_neo_hookean.h"

#include <cmath>

namespace xfem {

bool neo_hookean_stress(const Lame& lame, const Eigen::Matrix3d& F, StressAt& out, double continued_below) {
  const double J = F.determinant();
  if (continued_below > 0.0 && J < continued_below) {
    // Psi = mu/2 (I1 - 3) + h(J), h(J) = -mu ln J + lambda/2 (ln J)^2, with h continued below Jc by
    // its second-order Taylor polynomial (h, h' and h'' continuous at Jc; h'' > 0 for Jc < 1, so
    // the continuation is convex in J): P = mu F + h'(J) cof F and
    // A = mu I + h''(J) cof F (x) cof F + h'(J) d cof F / dF, defined for every F.
    const double mu = lame.mu, lambda = lame.lambda, Jc = continued_below, ln = std::log(Jc), d = J - Jc;
    const double h0 = -mu * ln + 0.5 * lambda * ln * ln, h1 = (-mu + lambda * ln) / Jc,
                 h2 = (mu + lambda - lambda * ln) / (Jc * Jc);
    const double dh = h1 + h2 * d;
    const Eigen::Matrix3d C = cofactor(F);
    Eigen::Matrix<double, 9, 1> c;  // C flattened as A's index 3 i + J
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) c[3 * i + j] = C(i, j);
    out.energy = 0.5 * mu * (F.squaredNorm() - 3.0) + h0 + h1 * d + 0.5 * h2 * d * d;
    out.P = mu * F + dh * C;
    out.A = mu * Eigen::Matrix<double, 9, 9>::Identity() + h2 * c * c.transpose() + dh * cofactor_derivative(F);
    return true;
  }
  if (!(J > 0.0)) return false;
  const double mu = lame.mu, lambda = lame.lambda, lnJ = std::log(J);
  const Eigen::Matrix3d G = F.inverse().transpose();  // F^-T = d ln J / dF
  out.energy = 0.5 * mu * (F.squaredNorm() - 3.0) - mu * lnJ + 0.5 * lambda * lnJ * lnJ;
  out.P = mu * (F - G) + lambda * lnJ * G;
  // d G_iJ / d F_kL = -G_iL G_kJ (from d F^-1 = -F^-1 dF F^-1), d ln J / d F_kL = G_kL.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L)
          out.A(3 * i + j, 3 * k + L) = (i == k && j == L ? mu : 0.0) + lambda * G(i, j) * G(k, L) +
                                        (mu - lambda * lnJ) * G(i, L) * G(k, j);
  return true;
}

}  // namespace xfem
