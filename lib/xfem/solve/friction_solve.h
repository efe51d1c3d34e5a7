// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <string>

#include "xfem/core/json_io.h"
#include "xfem/solve/contact_solve.h"
#include "xfem/system/contact_operator.h"
#include "xfem/system/linear_system.h"

namespace xfem {

/// What the friction part of the iteration found (xfem-solve's report, "friction").
struct FrictionOutcome {
  long stick = 0, slip = 0;          ///< contact nodes in contact that stick / slip at the end
  double stick_area = 0.0, slip_area = 0.0;  ///< their areas (sum W_i), m^2
  double max_slip = 0.0;             ///< largest |s_i| (the weighted tangential jump) over the nodes in contact, metres
  double max_slip_all = 0.0;         ///< the same over every contact node, metres
  double max_traction_ratio = 0.0;   ///< largest |t_i| / (mu_i p_i) over the nodes in contact (<= 1)
  double shear_force = 0.0;          ///< |sum_i W_i t_i| (3D, t_i on the face above): the shear the faces carry, N
  Eigen::MatrixXd traction;          ///< M x 3: the friction traction of each contact node (on the face above), Pa
};

/// Solves K u = f with Coulomb friction between the faces of the contact nodes of `c` (which must
/// have friction: c.has_friction(); docs/METHOD.md "Friction"). For fixed normal multipliers
/// lambda_i, tangential multipliers l_i (2-vectors) and slip bounds b_i the problem is the minimum
/// of the convex energy
///   Pi(u) = u^T K u / 2 - f^T u + sum_i W_i [lambda_i - kappa_i g_i]_+^2 / (2 kappa_i) + sum_i W_i psi_i(l_i - kappa_i s_i),
///   psi(z) = |z|^2 / (2 kappa) for |z| <= b (stick), (b |z| - b^2 / 2) / kappa else (slip),
/// (Tresca friction, augmented Lagrangian; s_i = T_i u the weighted slip), minimised by Newton
/// steps whose Hessian
///   K + sum_A kappa W G_i^T G_i + sum_stick kappa W T_i^T T_i + sum_slip kappa W b / |z| T_i^T (I - z z^T / |z|^2) T_i
/// is symmetric positive definite (the line search of contact_solve on Pi); then Uzawa updates
/// lambda <- [lambda - kappa g]_+, l <- the projection of l - kappa s on the disc of radius b, and
/// the Coulomb fixed point b <- mu lambda. Every matrix has the pattern of K with [G; T]^T [G; T]:
/// CHOLMOD analyses it once. The linear solves are `solver`'s (CHOLMOD's or PETSc's). The first
/// solve is the one without contact, returned as it is when nothing penetrates (an opening cut:
/// the same numbers as without friction, bit for bit). Fills report["contact"] (the keys of
/// solve_with_contact) and report["friction"]. Throws xfem::Error when settings.max_solves is reached.
Eigen::VectorXd solve_with_friction(const LinearSystem& s, const ContactOperator& c, const ContactIteration& settings,
                                    PenalisedSolver& solver, Json& report, double* residual,
                                    ContactOutcome* outcome = nullptr, FrictionOutcome* friction = nullptr);

}  // namespace xfem
