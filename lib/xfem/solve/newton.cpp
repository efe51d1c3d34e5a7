// SPDX-License-Identifier: MIT
#include "xfem/solve/newton.h"

#include <chrono>
#include <cmath>
#include <memory>

#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/core/seconds_since.h"
#include "xfem/solve/cholmod_solver.h"
#include "xfem/system/dirichlet.h"

namespace xfem {

namespace {

// The state of one load step's Newton iterations.
struct StepContext {
  const NonlinearProblem& problem;
  const NewtonOptions& options;
  const std::vector<long>& fixed;
  std::vector<char> is_fixed;
  SparseMatrix K;  // the tangent, lower triangle, K's pattern
  TangentSolver& solver;
  NewtonResult& result;
  double force_floor;  // the smallest force scale: mu L^2 1e-6 (a strain of 1e-6 across the body)
  // The terms' explicit zeros (NewtonTerms::pattern): with the body's pattern, the one pattern of
  // every matrix the solver sees, so that its analysis is reused; that matrix's non-zeros.
  SparseMatrix extra_zeros = SparseMatrix();
  long solve_nonzeros = -1;
  // The forces at `at_u` and, in K, the exact tangent there: computed together once per accepted
  // iterate (the line search's full step evaluates both), reused by the next iteration and by the
  // next load step, which starts where this one converged.
  Eigen::VectorXd at_u = Eigen::VectorXd(), r_at_u = Eigen::VectorXd();
  double energy_at_u = 0.0;
  bool evaluated = false;
};

// Forces and exact tangent at u into c.r_at_u, c.K (unless they are there already); false when a
// point is inverted.
bool evaluate_at(StepContext& c, const Eigen::VectorXd& u, LoadStep& step) {
  if (c.evaluated && c.at_u.size() == u.size() && c.at_u == u) return true;
  c.evaluated = false;
  const auto clock = std::chrono::steady_clock::now();
  const bool valid =
      internal_forces(*c.problem.em, *c.problem.body, c.problem.law, u, c.energy_at_u, c.r_at_u, &c.K);
  step.assemble_seconds += seconds_since(clock);
  ++step.tangents;
  if (!valid) return false;
  c.at_u = u;
  c.evaluated = true;
  return true;
}

// The matrix of the linear solve: the body's tangent (both triangles), the terms' explicit zeros
// and their tangent `extra` (full), always with the same pattern.
SparseMatrix system_matrix(StepContext& c, const std::vector<Eigen::Triplet<double, int>>& extra) {
  SparseMatrix full = c.K.selfadjointView<Eigen::Lower>();
  if (c.problem.terms.empty()) return full;
  SparseMatrix E(full.rows(), full.cols());
  E.setFromTriplets(extra.begin(), extra.end());
  SparseMatrix sum = full + c.extra_zeros;
  sum = sum + E;
  sum.makeCompressed();
  if (c.solve_nonzeros < 0) c.solve_nonzeros = sum.nonZeros();
  if (sum.nonZeros() != c.solve_nonzeros)
    throw Error("Newton: the contact or follower-load tangent left the solve's pattern (internal error)");
  return sum;
}

double norm_on(const Eigen::VectorXd& v, const std::vector<char>& is_fixed, bool fixed_ones) {
  double s = 0.0;
  for (long i = 0; i < v.size(); ++i)
    if (static_cast<bool>(is_fixed[i]) == fixed_ones) s += v[i] * v[i];
  return std::sqrt(s);
}

// Newton at load factor s from u (a valid state); on success u is the equilibrium.
bool newton_at(StepContext& c, double s, Eigen::VectorXd& u, LoadStep& step) {
  const EnrichedMesh& em = *c.problem.em;
  std::vector<long> fixed;
  std::vector<double> target;
  c.problem.dirichlet(s, fixed, target);
  if (fixed != c.fixed) throw Error("the Dirichlet conditions fix other DOFs at load factor " + cli::three_digits(s));
  const Eigen::VectorXd fs = s * c.problem.f;
  Eigen::VectorXd r, r_trial, R;
  for (int it = 0; it <= c.options.max_iterations; ++it) {
    if (!evaluate_at(c, u, step)) {
      step.failure = "a point is inverted at the start of the step";
      return false;
    }
    r = c.r_at_u;
    R = r - fs;
    // Follower loads and contact: their forces in R, their tangent in `extra`.
    std::vector<Eigen::Triplet<double, int>> extra;
    double extra_forces = 0.0;
    for (NewtonTerms* t : c.problem.terms) extra_forces = std::max(extra_forces, t->add(s, u, R, &extra));
    const double scale = std::max({fs.norm(), extra_forces, norm_on(r, c.is_fixed, true), c.force_floor});
    const double residual = norm_on(R, c.is_fixed, false) / scale;
    std::vector<double> change(fixed.size());
    bool at_target = true;
    for (std::size_t k = 0; k < fixed.size(); ++k) {
      change[k] = target[k] - u[fixed[k]];
      at_target = at_target && change[k] == 0.0;
    }
    step.iterations.push_back({residual, 1.0});
    if (c.options.detail)
      c.options.detail("load " + cli::three_digits(s) + ", iteration " + std::to_string(it) + ": relative residual " +
                       cli::three_digits(residual));
    if (at_target && residual <= c.options.rtol) {
      step.final_residual = residual;
      step.iterations.back().step = 0.0;  // no step taken: converged
      return true;
    }
    if (it == c.options.max_iterations) {
      step.failure = "no convergence in " + std::to_string(it) + " iterations (relative residual " +
                     cli::three_digits(residual) + ")";
      return false;
    }
    // K_ff du_f = -(R_f + K_fc du_c), the same pattern every time: one analysis, many factorizations.
    // A tangent that is not positive definite (extreme strains next to a crack front, buckling) is
    // formed again with each point's tangent projected onto the positive semi-definite ones.
    Eigen::VectorXd du;
    for (Tangent kind : {Tangent::Exact, Tangent::Projected}) {
      if (kind == Tangent::Projected) {
        double e_projected = 0.0;
        c.evaluated = false;  // K is no longer the exact tangent
        const auto clock = std::chrono::steady_clock::now();
        internal_forces(em, *c.problem.body, c.problem.law, u, e_projected, r, &c.K, nullptr, Tangent::Projected);
        step.assemble_seconds += seconds_since(clock);
        ++step.projected;
        ++step.tangents;
      }
      const SparseMatrix full = system_matrix(c, extra);
      try {
        du = c.solver.solve(full, -R, fixed, change, step);
        break;
      } catch (const NotPositiveDefinite& e) {
        if (kind == Tangent::Projected) {  // not even the projected tangent: halve the step
          step.failure = e.column >= 0 ? "the tangent stiffness is singular even projected (a rigid motion left free?)"
                                       : std::string("the projected tangent was not solved: ") + e.what();
          return false;
        }
      }
    }
    ++c.result.factorizations;
    auto clock = std::chrono::steady_clock::now();
    // Line search: halve while a point inverts or the residual grows.
    const double before = norm_on(R, c.is_fixed, false);
    double alpha = 1.0;
    bool accepted = false;
    Eigen::VectorXd trial;
    int inverted = 0;
    for (int k = 0; k <= 10 && !accepted; ++k, alpha /= 2) {
      trial = u + alpha * du;
      if (k == 0)
        for (std::size_t j = 0; j < fixed.size(); ++j) trial[fixed[j]] = target[j];  // exactly, not u + (target - u)
      // The full step is usually taken: evaluate the tangent with its forces, for the next iteration.
      bool valid = false;
      if (k == 0) {
        valid = evaluate_at(c, trial, step);
        if (valid) r_trial = c.r_at_u;
      } else {
        double e_trial = 0.0;
        clock = std::chrono::steady_clock::now();
        valid = internal_forces(em, *c.problem.body, c.problem.law, trial, e_trial, r_trial, nullptr);
        step.assemble_seconds += seconds_since(clock);
      }
      if (!valid) {
        ++inverted;
        continue;
      }
      Eigen::VectorXd R_trial = r_trial - fs;
      for (NewtonTerms* t : c.problem.terms) t->add(s, trial, R_trial, nullptr);
      accepted = !at_target || norm_on(R_trial, c.is_fixed, false) <= before;
      if (accepted) step.iterations.back().step = alpha;
    }
    if (c.options.detail)
      c.options.detail(accepted ? "  line search: step " + cli::three_digits(step.iterations.back().step) +
                                      (inverted ? " (" + std::to_string(inverted) + " longer steps invert a point)" : "")
                                : "  line search: no step reduces the residual without inverting a point");
    if (!accepted) {
      step.failure = "every step length inverts a point or increases the residual";
      return false;
    }
    u = trial;
  }
  return false;
}

// CHOLMOD: the Dirichlet DOFs eliminated, one symbolic analysis (at the first solve), a numeric
// factorization per solve.
class CholmodTangentSolver : public TangentSolver {
 public:
  explicit CholmodTangentSolver(Ordering ordering) : ordering_(ordering) {}
  Eigen::VectorXd solve(const SparseMatrix& K, const Eigen::VectorXd& rhs, const std::vector<long>& fixed,
                        const std::vector<double>& change, LoadStep& step) override {
    auto clock = std::chrono::steady_clock::now();
    const ReducedSystem reduced = eliminate_dirichlet(K, rhs, fixed, change);
    try {
      if (!factor_) {
        factor_ = std::make_unique<CholeskyFactor>(reduced.K, ordering_);
        analyze_seconds = factor_->analyze_seconds;
        step.factor_seconds -= factor_->analyze_seconds;  // reported on its own
      } else {
        factor_->refactor(reduced.K);
      }
    } catch (const NotPositiveDefinite&) {
      step.factor_seconds += seconds_since(clock);
      ++step.factorizations;
      throw;
    }
    step.factor_seconds += seconds_since(clock);
    ++step.factorizations;
    clock = std::chrono::steady_clock::now();
    const Eigen::VectorXd x = factor_->solve(reduced.f);
    Eigen::VectorXd du = expand_solution(reduced, x, fixed, change);
    step.solve_seconds += seconds_since(clock);
    return du;
  }

 private:
  Ordering ordering_;
  std::unique_ptr<CholeskyFactor> factor_;
};

}  // namespace

std::unique_ptr<TangentSolver> cholmod_tangent_solver(const std::string& ordering) {
  return std::make_unique<CholmodTangentSolver>(ordering == "amd" ? Ordering::Amd : Ordering::Metis);
}

NewtonResult solve_newton(const NonlinearProblem& problem, const NewtonOptions& options) {
  const EnrichedMesh& em = *problem.em;
  if (options.load_steps < 1) throw Error("load_steps must be at least 1");
  NewtonResult result;
  problem.dirichlet(1.0, result.fixed, result.fixed_values);
  std::vector<int> outer;
  std::unique_ptr<TangentSolver> own_solver;
  if (!options.solver) own_solver = cholmod_tangent_solver(options.ordering);
  TangentSolver& solver = options.solver ? *options.solver : *own_solver;
  const double size = (em.mesh.points.colwise().maxCoeff() - em.mesh.points.colwise().minCoeff()).norm();
  StepContext context{problem, options, result.fixed, std::vector<char>(3 * em.n, 0),
                      pattern_matrix(em, problem.body->pattern, outer), solver, result,
                      std::max(1e-6 * problem.law.lame.mu * size * size, 1e-300)};
  for (long d : result.fixed) context.is_fixed[d] = 1;
  context.extra_zeros = SparseMatrix(3 * em.n, 3 * em.n);
  for (NewtonTerms* t : problem.terms) context.extra_zeros = context.extra_zeros + t->pattern(3 * em.n);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * em.n);
  const double full_step = 1.0 / options.load_steps;
  double done = 0.0, step = full_step;
  while (done < 1.0) {
    const double s = done + step >= 1.0 - 1e-12 ? 1.0 : done + step;
    LoadStep attempt;
    attempt.load = s;
    Eigen::VectorXd next = u;
    for (NewtonTerms* t : problem.terms) t->begin_step();
    attempt.converged = newton_at(context, s, next, attempt);
    // Contact: the multipliers updated (Uzawa) and Newton again at s until the gaps are closed.
    const auto changed = [&] {
      bool any = false;
      for (NewtonTerms* t : problem.terms) any = t->update(s, next, attempt) || any;
      return any;
    };
    while (attempt.converged && changed()) attempt.converged = newton_at(context, s, next, attempt);
    if (!attempt.converged)
      for (NewtonTerms* t : problem.terms) t->reject_step();
    result.steps.push_back(attempt);
    if (attempt.converged) {
      u = next;
      if (attempt.has_contact && options.info)
        options.info("load " + cli::three_digits(s) + ": contact: " + std::to_string(attempt.active_points) +
                     " nodes in contact, " + std::to_string(attempt.multiplier_updates) +
                     " multiplier updates, largest penetration " + cli::three_digits(attempt.max_penetration) +
                     " m (tolerance " + cli::three_digits(attempt.contact_tolerance) + " m), normal force " +
                     cli::three_digits(attempt.contact_force) + " N");
      done = s;
      if (options.info)
        options.info("load " + cli::three_digits(s) + ": " +
                     std::to_string(attempt.iterations.size() - 1 - attempt.multiplier_updates) +
                     " Newton iterations, relative residual " + cli::three_digits(attempt.final_residual) + "; " +
                     std::to_string(attempt.tangents) + " tangents in " + cli::three_digits(attempt.assemble_seconds) +
                     " s, " + std::to_string(attempt.factorizations) +
                     (attempt.linear_iterations ? " PETSc solves (" + std::to_string(attempt.linear_iterations) +
                                                      " CG iterations) in " +
                                                      cli::three_digits(attempt.factor_seconds + attempt.solve_seconds)
                                                : " factorizations in " + cli::three_digits(attempt.factor_seconds)) +
                     " s");
      continue;
    }
    if (step < full_step / std::pow(2.0, options.max_halvings) * 1.5)
      throw Error("Newton's method failed at load factor " + cli::three_digits(s) + " after halving the load step " +
                  std::to_string(options.max_halvings) + " times (" + attempt.failure +
                  "): give more load_steps, or a smaller load");
    step /= 2;
    if (options.info) options.info("load " + cli::three_digits(s) + ": " + attempt.failure + "; the step halved");
  }
  result.u = u;
  result.analyze_seconds = solver.analyze_seconds;
  internal_forces(em, *problem.body, problem.law, u, result.energy, result.r, nullptr, &result.min_J);
  return result;
}

}  // namespace xfem
