// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>

#include "xfem/integrate/element_points.h"
#include "xfem/integrate/material_law.h"

namespace xfem {

/// One tet's share of the total-Lagrangian equilibrium under the element displacement `ue`
/// (3|C|: entry 3c + i is component i of the tet's c-th DOF vector), in the reference
/// configuration. At each point p, F = I + sum_c u_c (x) grad Phi_c, and
///   energy = sum_p w_p Psi(F_p)                                  (J)
///   r[3c + i] = sum_p w_p P_iJ(F_p) dPhi_c/dX_J                   (N, internal forces)
///   k[3c + i][3d + k] = sum_p w_p A_iJkL(F_p) dPhi_c/dX_J dPhi_d/dX_L   (N/m, the tangent dr/du)
/// With the linear model, k is the linear stiffness of the same points and r = k ue.
struct ElementForces {
  double energy = 0.0;
  Eigen::VectorXd r;
  Eigen::MatrixXd k;
  double min_J = 0.0;  ///< the smallest det F over the points
  int continued = 0;   ///< points next to a crack front evaluated below next_to_front_J (neo-Hookean)
};

/// Next to a crack front the branch functions' gradients grow like r^-1/2, and some points of the
/// front-singular rule always invert once the cut opens (docs/METHOD.md "Next to a crack front").
/// A point carrying less than next_to_front_weight of its tet's integrated volume is "next to the
/// front": it never refuses a step, and the neo-Hookean law is continued for it below
/// det F = next_to_front_J (neo_hookean_stress), so that its energy and forces stay smooth
/// functions of u (the corotational and linear laws are defined for every F as they are).
constexpr double next_to_front_weight = 1e-4;
constexpr double next_to_front_J = 0.1;

/// How the tangent is formed: the exact dr/du, or with each point's A projected onto the positive
/// semi-definite matrices (its negative eigenvalues set to 0: "projected Newton"), which keeps K
/// positive definite where the exact tangent is not (buckling, the extreme strains next to a
/// crack front) at the price of quadratic convergence while a projection is active.
enum class Tangent { Exact, Projected };

/// Evaluates the tet at `ue`; k only when `tangent`. Returns false, leaving `out` incomplete, when
/// a point of a model other than "linear" that is not next to a front has det F <= 0 (an inverted
/// point: the solve rejects the step); the linear model never refuses. A tet with a straight-front
/// `correction` (element_points.h) adds the linear law's k_c = stiffness_from_moments(correction):
/// energy + u.k_c u / 2, r + k_c u, k + k_c.
bool element_forces(const ElementPoints& points, const MaterialLaw& law, const Eigen::VectorXd& ue, bool tangent,
                    ElementForces& out, Tangent kind = Tangent::Exact);

/// The deformation gradient at point p: I + sum_c u_c (x) grad Phi_c.
Eigen::Matrix3d deformation_gradient(const ElementPoints& points, int p, const Eigen::VectorXd& ue);

}  // namespace xfem
