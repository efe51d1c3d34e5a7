// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>

#include "xfem/core/json_io.h"
#include "xfem/solve/cholmod_solver.h"
#include "xfem/system/dirichlet.h"
#include "xfem/system/contact_operator.h"
#include "xfem/system/linear_system.h"

namespace xfem {

/// Settings of the contact iteration (xfem-solve --contact-tol, --contact-iterations).
struct ContactIteration {
  double tolerance = 0.0;  ///< largest penetration accepted, metres; 0: 1e-8 max |u| of the solve without contact
  int max_solves = 100;    ///< linear solves (CHOLMOD: factorizations) at most (a refused run says how far it got)
};

/// What the contact iteration did (xfem-solve's report, "contact").
struct ContactOutcome {
  int solves = 0;                  ///< linear solves (the first one is the solve without contact)
  int damped = 0;                  ///< Newton steps shortened by the line search
  int updates = 0;                 ///< multiplier (Uzawa) updates
  long active = 0;                 ///< contact nodes (conditions) in contact at the end
  double active_area = 0.0;        ///< their area, m^2
  double max_penetration = 0.0;    ///< largest -g_i over the contact nodes at the end (the weighted gap), metres (0 if none)
  double tolerance = 0.0;          ///< the penetration tolerance used, metres
  double opened_volume = 0.0;      ///< sum over the contact nodes of W g (= sum over the face points of w g): the volume between the faces, m^3
  double force = 0.0;              ///< sum over the contact nodes of W p: the normal force the faces carry, N
  Eigen::VectorXd pressure;        ///< M: contact pressure of each contact node, Pa (>= 0)
};

/// K with explicit zeros wherever a penalty term B^T diag(c) B may add something (B^T B's pattern:
/// a contact node's row couples the DOFs of every cut tet around the node, which K does not always
/// couple): the one pattern of every solve of a contact iteration, so that CHOLMOD analyses it once.
SparseMatrix contact_pattern(const SparseMatrix& K, const SparseMatrix& B);

/// The linear solves of a contact iteration (solve_with_contact, solve_with_friction): one
/// iteration code, its backend pluggable. Each solve returns the full 3N solution, the Dirichlet
/// values in place; with several processes (PETSc) on every rank alike, so that every rank runs
/// the same iteration and takes the same decisions.
class PenalisedSolver {
 public:
  virtual ~PenalisedSolver() = default;
  /// The solve without contact, K u = f of `s`: the backend's own solve, its fields in `report`.
  virtual Eigen::VectorXd solve_unpenalised(const LinearSystem& s, Json& report, double* residual) = 0;
  /// One solve of the iteration: K (the contact pattern, the penalty terms added) u = f with the
  /// Dirichlet conditions of `s` (whose K and f are not used); `*residual` its relative residual
  /// on the free DOFs; `what` ("contact", "friction") prefixes warnings.
  virtual Eigen::VectorXd solve(const LinearSystem& s, const SparseMatrix& K, const Eigen::VectorXd& f,
                                const char* what, double* residual) = 0;
  /// Whether the solves are iterative (CG to a relative residual), not exact up to round-off:
  /// then the line search allows for the solve's residual (penalised_step_slack).
  virtual bool iterative() const { return false; }
};

/// What the line search allows a full step's energy derivative Pi'(1) beyond round-off: 0 for
/// an exact solver; for an iterative one |d^T (K x - f)|, d = x - u the step to the solve's x. With
/// the active set unchanged Pi'(1) is exactly that, the solve's residual along the step: not 0,
/// so without it the line search would cut every step near the solution (the step being as small
/// as the residual) and the iteration would never take a full one.
double penalised_step_slack(const PenalisedSolver& solver, const SparseMatrix& K, const Eigen::VectorXd& f,
                            const Eigen::VectorXd& u, const Eigen::VectorXd& x);

/// CHOLMOD's solves (solve_with_cholmod first): every penalised matrix has the contact pattern,
/// so CHOLMOD's analysis is done on the first and each later solve only refactors; a warning when
/// the penalty makes K near-singular.
class CholmodPenalisedSolver : public PenalisedSolver {
 public:
  CholmodPenalisedSolver(std::string ordering, bool ticking) : ordering_(std::move(ordering)), ticking_(ticking) {}
  Eigen::VectorXd solve_unpenalised(const LinearSystem& s, Json& report, double* residual) override;
  Eigen::VectorXd solve(const LinearSystem& s, const SparseMatrix& K, const Eigen::VectorXd& f, const char* what,
                        double* residual) override;

 private:
  std::string ordering_;
  bool ticking_;
  std::unique_ptr<CholeskyFactor> factor_;
};

/// The line search of the contact iterations: the step length in (0, 1] that minimises a convex
/// energy along a Newton step, given its derivative Pi'(alpha), increasing in alpha: 1 when Pi'(1)
/// <= 0 up to round-off (1e-9 `size`, the size of Pi's terms) and `slack` (penalised_step_slack),
/// else its root by bisection.
double convex_step_length(const std::function<double(double)>& derivative, double size, double slack = 0.0);

/// Prints the contact outcome's line on stderr and fills `report["contact"]` (docs/FORMATS.md):
/// xfem-solve's report of contact, frictionless or not.
void report_contact(const ContactOperator& c, const ContactOutcome& out, Json& report);

/// Solves K u = f with frictionless contact on the contact nodes of `c` (docs/METHOD.md
/// "Contact"): the augmented Lagrangian with multipliers lambda_i (the pressure) and penalty
/// kappa_i per node, whose inner problem for fixed lambda is solved by an active-set (semismooth
/// Newton) iteration: with the active set A = {i : lambda_i - kappa_i g_i > 0},
///   (K + sum_A kappa_i W_i G_i^T G_i) u = f + sum_A W_i lambda_i G_i^T
/// each step shortened by a line search on the energy of the fixed-lambda problem where it would
/// raise it, until A stops changing (10 solves at most); then lambda_i <- max(0, lambda_i - kappa_i g_i)
/// (Uzawa), until the largest penetration max(-g) and the largest gap left open under pressure are
/// below the tolerance. Every matrix has the same pattern (K's with G^T G's), so CHOLMOD's analysis
/// is done once and each later solve only refactors. The first solve is the one without contact
/// (the backend's plain solve): when nothing penetrates beyond the tolerance it is returned as it is,
/// bit for bit. Throws xfem::Error when max_solves is reached. Fills `report["contact"]` and the
/// outcome.
/// The linear solves are `solver`'s (CholmodPenalisedSolver; the PETSc backend's in petsc_backend.h).
Eigen::VectorXd solve_with_contact(const LinearSystem& s, const ContactOperator& c, const ContactIteration& settings,
                                   PenalisedSolver& solver, Json& report, double* residual,
                                   ContactOutcome* outcome = nullptr);

}  // namespace xfem
