// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "xfem/system/nonlinear_assembly.h"

namespace xfem {

class NewtonTerms;

/// The nonlinear equilibrium r(u) = s f for load factors s rising to 1 in load steps, with the
/// Dirichlet values of load factor s (a rotation is turned by s times its angle: dirichlet_data).
struct NonlinearProblem {
  const EnrichedMesh* em = nullptr;
  const BodyIntegration* body = nullptr;
  MaterialLaw law;
  Eigen::VectorXd f;  ///< external loads at s = 1 (3N, N), proportional to s
  /// The constrained scalar DOFs (increasing, the same at every s) and their values at s.
  std::function<void(double s, std::vector<long>& fixed, std::vector<double>& values)> dirichlet;
  /// Follower loads and contact (not owned), added in this order; empty: none.
  std::vector<NewtonTerms*> terms;
};

struct LoadStep;

/// Terms of the equilibrium beyond the body's forces and the dead loads s f (xfem-newton: the
/// follower pressure on the cut's faces, contact between them; newton_terms.h). At load factor s
/// and displacement u they add their share to the residual R = r(u) - s f and, with `K` non-null,
/// to the tangent: triplets of the full matrix (both triangles) inside the body's pattern plus
/// `pattern()`. After a load step has converged `update` may change their own state (the contact
/// multipliers) and ask for Newton again at the same s.
class NewtonTerms {
 public:
  virtual ~NewtonTerms() = default;
  /// Adds to R; returns the size of the forces it added (for the residual's scale), N.
  virtual double add(double s, const Eigen::VectorXd& u, Eigen::VectorXd& R,
                     std::vector<Eigen::Triplet<double, int>>* K) const = 0;
  /// Explicit zeros (full matrix) where the tangent may get entries the body's pattern lacks.
  virtual SparseMatrix pattern(long dofs) const { return SparseMatrix(dofs, dofs); }
  /// At a converged u of load factor s: true when the terms changed (Newton again at s); `step`
  /// gets their record. Throws xfem::Error when they cannot converge.
  virtual bool update(double /*s*/, const Eigen::VectorXd& /*u*/, LoadStep& /*step*/) { return false; }
  /// Before a load step (save the state), after a failed one (restore it).
  virtual void begin_step() {}
  virtual void reject_step() {}
};

/// The linear solve of a Newton iteration: K du = rhs on the free DOFs with du = `change` on the
/// `fixed` ones (K the tangent, both triangles, the same pattern every time). CHOLMOD
/// (cholmod_tangent_solver) or PETSc on MPI ranks (newton_petsc.h). Adds its times (and CG
/// iterations) to `step`. Throws NotPositiveDefinite when K_ff cannot be solved as positive
/// definite: the iteration then projects the tangent, and halves the load step if that fails too.
class TangentSolver {
 public:
  virtual ~TangentSolver() = default;
  virtual Eigen::VectorXd solve(const SparseMatrix& K, const Eigen::VectorXd& rhs, const std::vector<long>& fixed,
                                const std::vector<double>& change, LoadStep& step) = 0;
  double analyze_seconds = 0.0;  ///< one-off set-up (CHOLMOD's symbolic analysis), not in the steps' times
};

/// CHOLMOD with one symbolic analysis (ordering "metis" or "amd") for every factorization.
std::unique_ptr<TangentSolver> cholmod_tangent_solver(const std::string& ordering);

struct NewtonOptions {
  int load_steps = 1;       ///< equal steps of s to reach 1
  int max_iterations = 25;  ///< Newton iterations per step before the step is halved
  int max_halvings = 6;     ///< a step halved at most this often (1/64 of a load step)
  double rtol = 1e-8;       ///< converged: ||r - s f|| on the free DOFs <= rtol * its scale (below)
  std::string ordering = "metis";  ///< CHOLMOD's, when `solver` is null
  /// The linear solver (not owned); null: CHOLMOD with `ordering`.
  TangentSolver* solver = nullptr;
  /// Progress: a line per load step (`info`) and per Newton iteration (`detail`); either may be empty.
  std::function<void(const std::string&)> info, detail;
};

/// One Newton iteration: the residual before it, the line search's step length.
struct NewtonIteration {
  double residual = 0.0;  ///< ||r(u) - s f|| on the free DOFs, divided by the scale
  double step = 1.0;      ///< the line search's alpha
};

/// One load step as it finished (a failed attempt is followed by two halves).
struct LoadStep {
  double load = 0.0;                       ///< s at its end
  bool converged = false;
  std::vector<NewtonIteration> iterations;
  double final_residual = 0.0;             ///< relative residual at the accepted u
  /// Wall time: forces and tangents (assemble), numeric factorizations with the Dirichlet
  /// elimination before them (factor; PETSc: the matrix's distribution and the preconditioner's
  /// set-up), triangular solves (solve; PETSc: the CG iterations).
  double factor_seconds = 0.0, assemble_seconds = 0.0, solve_seconds = 0.0;
  int tangents = 0;        ///< tangent assemblies (each with its forces)
  int factorizations = 0;  ///< numeric factorizations (PETSc: preconditioner set-ups), failed ones included
  long linear_iterations = 0;  ///< PETSc: CG iterations of the step's solves (0 with CHOLMOD)
  int projected = 0;       ///< iterations that needed the projected tangent (element_forces.h)
  std::string failure;  ///< why it did not converge (empty when it did)
  /// Contact (NewtonTerms::update): multiplier updates of the step, and its state at the end.
  int multiplier_updates = 0;
  long active_points = 0;
  double max_penetration = 0.0, contact_force = 0.0, contact_tolerance = 0.0;
  bool has_contact = false;
};

struct NewtonResult {
  Eigen::VectorXd u;                 ///< 3N, metres
  Eigen::VectorXd r;                 ///< internal forces r(u) (3N, N); r - f are the reactions
  std::vector<LoadStep> steps;       ///< every attempt, the failed ones included
  std::vector<long> fixed;
  std::vector<double> fixed_values;  ///< at s = 1
  double energy = 0.0;               ///< strain energy at u (J)
  double min_J = 0.0;                ///< smallest det F at u
  int factorizations = 0;
  double analyze_seconds = 0.0;      ///< the one symbolic analysis (CHOLMOD)
};

/// Solves the problem with Newton's method and a backtracking line search in load steps:
///  - each iteration solves K_ff du_f = -(R_f + K_fc du_c) (K the tangent, R = r(u) - s f, du_c
///    the remaining change of the Dirichlet values) with options.solver (CHOLMOD by default, one
///    symbolic analysis for every factorization of the solve);
///  - the line search halves the step (up to 10 times) while a point of a nonlinear model would
///    invert (det F <= 0; the points next to a crack front never refuse: element_forces.h) or the
///    residual would grow (an iteration that moves the Dirichlet values is taken if it inverts
///    nothing); its full step evaluates forces and tangent together, which the next iteration
///    (or the next load step) reuses: one tangent per accepted iterate;
///  - a load step whose Newton iterations fail (no convergence in max_iterations, a line search
///    that finds no step, a tangent that is not positive definite) is tried again as two halves,
///    at most max_halvings times.
/// The residual's scale is the largest of ||s f||, the internal forces on the constrained DOFs
/// (the reactions), so that a displacement-driven problem converges relative to its forces, and
/// 1e-6 mu L^2 (L the body's diagonal: the force of a strain of 1e-6 across it), so that a
/// stress-free answer (a rigid motion) converges too.
/// Throws xfem::Error naming the load factor when a step fails after the last halving.
NewtonResult solve_newton(const NonlinearProblem& problem, const NewtonOptions& options);

}  // namespace xfem
