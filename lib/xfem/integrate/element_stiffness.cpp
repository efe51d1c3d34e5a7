// SPDX-License-Identifier: MIT
#include "xfem/integrate/element_stiffness.h"

#include <cmath>

#include "xfem/enrich/enriched_basis.h"

namespace xfem {

Eigen::Matrix<double, 12, 12> tet_stiffness(const TetShape& shape, const Lame& material) {
  const double v = std::abs(shape.volume);
  const double mu = material.mu * v, la = material.lambda * v;
  const Eigen::Matrix<double, 4, 3>& g = shape.grad;
  const Eigen::Matrix4d dots = g * g.transpose();
  Eigen::Matrix<double, 12, 12> k;
  for (int n = 0; n < 4; ++n)
    for (int m = 0; m < 4; ++m)
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
          k(3 * n + j, 3 * m + i) = mu * g(n, i) * g(m, j) + la * g(n, j) * g(m, i) + (i == j ? mu * dots(n, m) : 0.0);
  return k;
}

void element_stiffness(const EnrichedMesh& em, int t, const Quadrature& rule, const Lame& material,
                       Eigen::MatrixXd& k) {
  const TetShape shape = tet_shape(em.mesh, t);
  const int n = em.size(t);
  if (em.plain(t)) {
    k = tet_stiffness(shape, material);
    return;
  }
  // S(3n+a, 3m+b) = integral of dPhi_n/dx_a dPhi_m/dx_b = G^T G, where row q of G holds the
  // gradients at point q scaled by sqrt(weight * volume); formula (5) rearranges S.
  // Cut tets (not blending ones: their basis is smooth) refine the rule where H changes.
  const bool cut = !em.cut_class.empty() && em.cut_class[t] > 0 && em.cut && rule.refine_levels > 0;
  const Quadrature refined =
      cut ? refine_at_cut(rule, [&](const Eigen::Vector4d& l) { return em.cut->side(tet_point(em.mesh, t, l)); })
          : Quadrature();
  const Quadrature& use = cut ? refined : rule;
  const int q = use.size();
  Eigen::MatrixXd G(q, 3 * n);
  BasisAt b;
  const double v = std::abs(shape.volume);
  for (int p = 0; p < q; ++p) {
    const Eigen::Vector3d x = tet_point(em.mesh, t, use.lambda[p]);
    enriched_basis(em, t, shape, x, 0, b);
    const double s = std::sqrt(use.weights[p] * v);
    for (int c = 0; c < n; ++c)
      for (int a = 0; a < 3; ++a) G(p, 3 * c + a) = s * b.dN(c, a);
  }
  stiffness_from_gradients(G, material, k);
}

void stiffness_from_gradients(const Eigen::MatrixXd& G, const Lame& material, Eigen::MatrixXd& k) {
  const int n = static_cast<int>(G.cols() / 3);
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  S.selfadjointView<Eigen::Lower>().rankUpdate(G.transpose());
  S.triangularView<Eigen::StrictlyUpper>() = S.transpose();
  stiffness_from_moments(S, material, k);
}

void stiffness_from_moments(const Eigen::Ref<const Eigen::MatrixXd>& S, const Lame& material, Eigen::MatrixXd& k) {
  const int n = static_cast<int>(S.cols() / 3);
  k.resize(3 * n, 3 * n);
  const double mu = material.mu, la = material.lambda;
  for (int a = 0; a < n; ++a)
    for (int c = 0; c < n; ++c) {
      const double dot = S(3 * a, 3 * c) + S(3 * a + 1, 3 * c + 1) + S(3 * a + 2, 3 * c + 2);
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
          k(3 * a + j, 3 * c + i) =
              mu * S(3 * a + i, 3 * c + j) + la * S(3 * a + j, 3 * c + i) + (i == j ? mu * dot : 0.0);
    }
}

}  // namespace xfem
