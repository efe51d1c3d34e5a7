// SPDX-License-Identifier: MIT
#include "xfem/integrate/material_law.h"

#include "xfem/core/error.h"
#include "xfem/integrate/material_corotational.h"
#include "xfem/integrate/material_neo_hookean.h"

namespace xfem {
namespace {

// Levi-Civita symbol of three distinct indices: +1 for cyclic (0 1 2) orders, -1 otherwise.
double permutation_sign(int i, int k) { return (k - i + 3) % 3 == 1 ? 1.0 : -1.0; }

// Small-strain Hooke as a law of F: eps = sym(F - I), P = sigma(eps), A the elasticity tensor
// lambda d_iJ d_kL + mu (d_ik d_JL + d_iL d_Jk), independent of F.
void linear_stress(const Lame& lame, const Eigen::Matrix3d& F, StressAt& out) {
  const double mu = lame.mu, lambda = lame.lambda;
  const Eigen::Matrix3d eps = 0.5 * (F + F.transpose()) - Eigen::Matrix3d::Identity();
  const double tr = eps.trace();
  out.energy = mu * eps.squaredNorm() + 0.5 * lambda * tr * tr;
  out.P = lambda * tr * Eigen::Matrix3d::Identity() + 2.0 * mu * eps;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L)
          out.A(3 * i + j, 3 * k + L) = (i == j && k == L ? lambda : 0.0) + (i == k && j == L ? mu : 0.0) +
                                        (i == L && j == k ? mu : 0.0);
}

}  // namespace

const char* material_model_name(MaterialModel model) {
  switch (model) {
    case MaterialModel::Linear: return "linear";
    case MaterialModel::Corotational: return "corotational";
    case MaterialModel::NeoHookean: return "neo-hookean";
  }
  return "linear";
}

MaterialModel material_model_named(const std::string& name) {
  for (MaterialModel m : {MaterialModel::Linear, MaterialModel::Corotational, MaterialModel::NeoHookean})
    if (name == material_model_name(m)) return m;
  throw Error("unknown material model \"" + name + "\" (linear, corotational, neo-hookean)");
}

bool stress_at(const MaterialLaw& law, const Eigen::Matrix3d& F, StressAt& out, double continued_below) {
  switch (law.model) {
    case MaterialModel::Linear: linear_stress(law.lame, F, out); return true;
    case MaterialModel::Corotational: corotational_stress(law.lame, F, out); return true;
    case MaterialModel::NeoHookean: return neo_hookean_stress(law.lame, F, out, continued_below);
  }
  throw Error("stress_at: unknown material model");
}

Eigen::Matrix3d cauchy_stress(const Eigen::Matrix3d& P, const Eigen::Matrix3d& F) {
  return P * F.transpose() / F.determinant();
}

Eigen::Matrix3d cofactor(const Eigen::Matrix3d& F) {
  Eigen::Matrix3d C;  // column J: the cross product of F's other two columns, in cyclic order
  C.col(0) = F.col(1).cross(F.col(2));
  C.col(1) = F.col(2).cross(F.col(0));
  C.col(2) = F.col(0).cross(F.col(1));
  return C;
}

Eigen::Matrix<double, 9, 9> cofactor_derivative(const Eigen::Matrix3d& F) {
  Eigen::Matrix<double, 9, 9> H = Eigen::Matrix<double, 9, 9>::Zero();
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      if (i == k) continue;
      const int l = 3 - i - k;  // the third index: eps_ikl is zero for every other l
      for (int j = 0; j < 3; ++j)
        for (int L = 0; L < 3; ++L) {
          if (j == L) continue;
          const int M = 3 - j - L;
          H(3 * i + j, 3 * k + L) = permutation_sign(i, k) * permutation_sign(j, L) * F(l, M);
        }
    }
  return H;
}

}  // namespace xfem
