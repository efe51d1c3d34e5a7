// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <string>

#include "xfem/integrate/element_stiffness.h"

namespace xfem {

/// The material models of problem.json `material.model` (docs/FORMATS.md "problem.json").
///  - Linear: small-strain Hooke, Psi = mu eps:eps + lambda/2 (tr eps)^2, eps = sym(F - I): the
///    linear path's law (element_stiffness.h), written as a law of F so that the nonlinear solve
///    with it reproduces the linear solve.
///  - Corotational: fixed-corotated, Psi = mu |F - R|^2 + lambda/2 (J - 1)^2, R = polar(F) from
///    the SVD with the reflection fixed (R a rotation even when det F < 0).
///  - NeoHookean: compressible, Psi = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2, I1 = tr(F^T F);
///    undefined for J <= 0.
enum class MaterialModel { Linear, Corotational, NeoHookean };

/// "linear", "corotational", "neo-hookean" (the names of problem.json).
const char* material_model_name(MaterialModel model);
/// The model of a name; throws xfem::Error listing the names for any other.
MaterialModel material_model_named(const std::string& name);

/// One material: its model and Lame parameters (lame() of element_stiffness.h).
struct MaterialLaw {
  MaterialModel model = MaterialModel::Linear;
  Lame lame;
};

/// Everything the solve needs at one integration point, for deformation gradient F:
/// the energy density Psi (J/m^3), the first Piola-Kirchhoff stress P = dPsi/dF (Pa), and the
/// tangent A = dP/dF, A(3 i + J, 3 k + L) = d P_iJ / d F_kL (Pa), symmetric (A = d2Psi/dF2).
struct StressAt {
  double energy = 0.0;
  Eigen::Matrix3d P = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 9, 9> A = Eigen::Matrix<double, 9, 9>::Zero();
};

/// Evaluates `law` at F (implementations: material_law.cpp for Linear, material_corotational.h,
/// material_neo_hookean.h). For NeoHookean, J = det F <= 0 has no energy: returns false (the caller
/// rejects the step) and leaves `out` unspecified; every other case returns true. `continued_below`
/// (NeoHookean only; 0: not used) continues the law below that J, for every F
/// (neo_hookean_stress): what the points next to a crack front are evaluated with (element_forces.h).
bool stress_at(const MaterialLaw& law, const Eigen::Matrix3d& F, StressAt& out, double continued_below = 0.0);

/// The Cauchy stress sigma = P F^T / J of a point (Pa), for output; J <= 0 gives NaNs (callers
/// check J first).
Eigen::Matrix3d cauchy_stress(const Eigen::Matrix3d& P, const Eigen::Matrix3d& F);

/// The cofactor matrix of F, cof F = J F^-T = d det F / d F, defined for every F (also J <= 0).
Eigen::Matrix3d cofactor(const Eigen::Matrix3d& F);
/// Its derivative d (cof F)_iJ / d F_kL = eps_ikl eps_JLM F_lM at (3 i + J, 3 k + L): the second
/// derivative of det F, symmetric.
Eigen::Matrix<double, 9, 9> cofactor_derivative(const Eigen::Matrix3d& F);

}  // namespace xfem
