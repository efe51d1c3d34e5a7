// SPDX-License-Identifier: MIT
#include "xfem/integrate/element_forces.h"
#include "xfem/integrate/element_stiffness.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <limits>

namespace xfem {

namespace {

// A projected onto the positive semi-definite matrices (negative eigenvalues set to 0). A matrix
// that is already positive definite up to round-off (a Cholesky factorization of A + 1e-12 |A| I
// succeeds: the common case) is left as it is, which spares the eigensolver at most points.
void project_positive(Eigen::Matrix<double, 9, 9>& A) {
  const Eigen::Matrix<double, 9, 9> shifted =
      A + 1e-12 * A.cwiseAbs().maxCoeff() * Eigen::Matrix<double, 9, 9>::Identity();
  if (Eigen::LLT<Eigen::Matrix<double, 9, 9>>(shifted).info() == Eigen::Success) return;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>> eigen(A);
  A = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() * eigen.eigenvectors().transpose();
}

// Work space of one thread, reused from tet to tet.
struct Scratch {
  Eigen::MatrixXd D;        // 3q x 3: row J q + p, column i = F_p(i, J) - delta_iJ
  Eigen::MatrixXd W;        // 3q x 3: row J q + p, column i = w_p P_p(i, J)
  Eigen::MatrixXd A;        // q x 81: row p = w_p A_p, column 9 (3 i + J) + 3 k + L
  Eigen::MatrixXd H;        // 3q x n
  Eigen::MatrixXd block;    // n x n
  Eigen::MatrixXd kc;       // 3n x 3n: the straight-front correction's stiffness
};

}  // namespace

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
  const int q = points.size();
  out.energy = 0.0;
  out.min_J = std::numeric_limits<double>::infinity();
  out.continued = 0;
  out.r.setZero(3 * n);
  if (tangent) out.k.setZero(3 * n, 3 * n);
  thread_local Scratch s;
  // The gradients as S (3q x n), S(J q + p, c) = dPhi_c/dX_J at p: the same memory as
  // points.gradient (q x 3n, column-major), read in another shape. Every sum over the points is
  // then a product with S: F - I = S U (U(c, i) = ue[3c + i]), r = S^T W, and the tangent's
  // blocks k_ik(c, d) = S^T H_ik with H_ik(J q + p, d) = sum_L w_p A_p(3i + J, 3k + L) S(L q + p, d).
  const Eigen::Map<const Eigen::MatrixXd> S(points.gradient.data(), 3 * q, n);
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> U(ue.data(), n, 3);
  s.D.noalias() = S * U;
  s.W.setZero(3 * q, 3);
  if (tangent) s.A.resize(q, 81);
  const double volume = points.weight.sum();
  StressAt at;
  for (int p = 0; p < q; ++p) {
    Eigen::Matrix3d F;
    for (int J = 0; J < 3; ++J) F.col(J) = s.D.row(J * q + p).transpose();
    F += Eigen::Matrix3d::Identity();
    const double J = F.determinant();
    out.min_J = std::min(out.min_J, J);
    const double w = points.weight[p];
    // Next to a crack front (docs/METHOD.md): a point of negligible volume is evaluated with the
    // law continued below det F = next_to_front_J, so that it never refuses a step.
    const bool negligible = w < next_to_front_weight * volume;
    if (law.model != MaterialModel::Linear && !(J > 0.0) && !negligible) return false;
    if (!stress_at(law, F, at, negligible ? next_to_front_J : 0.0)) return false;
    if (negligible && J < next_to_front_J && law.model == MaterialModel::NeoHookean) ++out.continued;
    out.energy += w * at.energy;
    for (int J = 0; J < 3; ++J) s.W.row(J * q + p) = w * at.P.col(J).transpose();
    if (!tangent) continue;
    if (kind == Tangent::Projected) project_positive(at.A);
    s.A.row(p) = w * Eigen::Map<const Eigen::Matrix<double, 1, 81>>(at.A.data());  // A symmetric: either order
  }
  const Eigen::MatrixXd R = S.transpose() * s.W;  // n x 3
  for (int c = 0; c < n; ++c)
    for (int i = 0; i < 3; ++i) out.r[3 * c + i] = R(c, i);
  if (points.correction.size() > 0) {
    stiffness_from_moments(points.correction, law.lame, s.kc);
    const Eigen::VectorXd kcu = s.kc * ue;
    out.r += kcu;
    out.energy += 0.5 * ue.dot(kcu);
  }
  if (!tangent) return true;
  // A is symmetric, so k_ki = k_ik^T: the 6 blocks with i <= k.
  s.H.resize(3 * q, n);
  for (int i = 0; i < 3; ++i)
    for (int k = i; k < 3; ++k) {
      for (int J = 0; J < 3; ++J) {
        auto h = s.H.middleRows(J * q, q);
        h.setZero();
        for (int L = 0; L < 3; ++L)
          h.array() += S.middleRows(L * q, q).array().colwise() * s.A.col(9 * (3 * i + J) + 3 * k + L).array();
      }
      s.block.noalias() = S.transpose() * s.H;
      for (int d = 0; d < n; ++d)
        for (int c = 0; c < n; ++c) {
          out.k(3 * c + i, 3 * d + k) = s.block(c, d);
          out.k(3 * d + k, 3 * c + i) = s.block(c, d);
        }
    }
  if (points.correction.size() > 0) out.k += s.kc;
  return true;
}

}  // namespace xfem
