// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <string>

#include "xfem/core/json_io.h"
#include "xfem/system/contact_operator.h"
#include "xfem/system/linear_system.h"

namespace xfem {

/// Settings of the contact iteration (xfem-solve --contact-tol, --contact-iterations).
struct ContactIteration {
  double tolerance = 0.0;  ///< largest penetration accepted, metres; 0: 1e-8 max |u| of the solve without contact
  int max_solves = 100;    ///< factorizations at most (a refused run says how far it got)
};

/// What the contact iteration did (xfem-solve's report, "contact").
struct ContactOutcome {
  int solves = 0;                  ///< factorizations (the first one is the solve without contact)
  int updates = 0;                 ///< multiplier (Uzawa) updates
  long active = 0;                 ///< points in contact at the end
  double active_area = 0.0;        ///< their area, m^2
  double max_penetration = 0.0;    ///< largest -g over all points at the end, metres (0 if none)
  double tolerance = 0.0;          ///< the penetration tolerance used, metres
  double opened_volume = 0.0;      ///< sum over the points of w g: the volume between the faces, m^3
  double force = 0.0;              ///< sum over the points of w p: the normal force the faces carry, N
  Eigen::VectorXd pressure;        ///< Q: contact pressure at each point, Pa (>= 0)
};

/// Solves K u = f with frictionless contact on the points of `c` (docs/METHOD.md "Contact"): the
/// augmented Lagrangian with multipliers lambda_q (the pressure) and penalty kappa_q, whose inner
/// problem for fixed lambda is solved by an active-set (semismooth Newton) iteration: with the
/// active set A = {q : lambda_q - kappa_q g_q > 0},
///   (K + sum_A kappa_q w_q G_q^T G_q) u = f + sum_A w_q lambda_q G_q^T
/// until A stops changing; then lambda_q <- max(0, lambda_q - kappa_q g_q) (Uzawa), until the
/// largest penetration max(-g) is below the tolerance with A unchanged. Every matrix has the same
/// pattern (K's, with the contact tets' blocks), so CHOLMOD's analysis is done once and each
/// later solve only refactors. The first solve is the one without contact (solve_with_cholmod's):
/// when nothing penetrates beyond the tolerance it is returned as it is, bit for bit.
/// Throws xfem::Error when max_solves is reached. Fills `report["contact"]` and the outcome.
Eigen::VectorXd solve_with_contact(const LinearSystem& s, const ContactOperator& c, const ContactIteration& settings,
                                   const std::string& ordering, bool ticking, Json& report, double* residual,
                                   ContactOutcome* outcome = nullptr);

}  // namespace xfem
