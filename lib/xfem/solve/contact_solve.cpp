// SPDX-License-Identifier: MIT
#include "xfem/solve/contact_solve.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/solve/cholmod_solver.h"
#include "xfem/solve/direct_backend.h"
#include "xfem/system/dirichlet.h"

namespace xfem {
namespace {

// Solves of the inner (fixed multipliers) iteration before the multipliers are updated anyway.
constexpr int kInnerSolves = 10;

// The step length alpha in (0, 1] along d from u that minimises the energy of the problem with
// fixed multipliers, Pi(u) = u^T K u / 2 - f^T u + sum_i W_i [lambda_i - kappa_i g_i]_+^2 / (2 kappa_i):
// Pi is convex and piecewise quadratic along d, its derivative
//   Pi'(alpha) = d^T (K u - f) + alpha d^T K d - sum_i W_i h_i [lambda_i - kappa_i (g_i + alpha h_i)]_+
// (h = G d) is increasing and piecewise linear: 1 when Pi'(1) <= 0 (the full Newton step, always
// taken when the active set did not change), else its root by bisection. d is zero on the fixed
// DOFs (u and u + d both satisfy the Dirichlet conditions), so their reactions do not enter.
double line_search(const LinearSystem& s, const ContactOperator& c, const Eigen::VectorXd& lambda,
                   const Eigen::VectorXd& u, const Eigen::VectorXd& g, const Eigen::VectorXd& d, double slack) {
  const Eigen::VectorXd Kd = s.K * d, h = c.G * d;
  const double slope = d.dot(s.K * u - s.f), curvature = d.dot(Kd);
  const auto derivative = [&](double alpha) {
    double value = slope + alpha * curvature;
    for (long i = 0; i < h.size(); ++i)
      value -= c.weight[i] * h[i] * std::max(0.0, lambda[i] - c.penalty[i] * (g[i] + alpha * h[i]));
    return value;
  };
  return convex_step_length(derivative, std::abs(slope) + std::abs(curvature), slack);
}

}  // namespace

SparseMatrix contact_pattern(const SparseMatrix& K, const SparseMatrix& G) {
  const SparseMatrix GtG = SparseMatrix(G.transpose()) * G;
  std::vector<Eigen::Triplet<double, int>> zeros;
  zeros.reserve(static_cast<std::size_t>(GtG.nonZeros()));
  for (int j = 0; j < GtG.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(GtG, j); it; ++it) zeros.emplace_back(static_cast<int>(it.row()), j, 0.0);
  SparseMatrix Z(K.rows(), K.cols());
  Z.setFromTriplets(zeros.begin(), zeros.end());
  SparseMatrix P = K + Z;
  P.makeCompressed();
  return P;
}

Eigen::VectorXd CholmodPenalisedSolver::solve_unpenalised(const LinearSystem& s, Json& report, double* residual) {
  return solve_with_cholmod(s, ordering_, ticking_, report, residual);
}

Eigen::VectorXd CholmodPenalisedSolver::solve(const LinearSystem& s, const SparseMatrix& K, const Eigen::VectorXd& f,
                                              const char* what, double* residual) {
  const ReducedSystem reduced = eliminate_dirichlet(K, f, s.fixed, s.fixed_values);
  if (!factor_)
    factor_ = std::make_unique<CholeskyFactor>(reduced.K, ordering_ == "amd" ? Ordering::Amd : Ordering::Metis);
  else
    factor_->refactor(reduced.K);
  if (factor_->rcond < 1e-14)
    cli::warn(std::string(what) + ": K with the penalty is near-singular (CHOLMOD reciprocal condition estimate " +
              cli::three_digits(factor_->rcond) + "): lower the contact penalty");
  Eigen::VectorXd u = expand_solution(reduced, factor_->solve(reduced.f), s.fixed, s.fixed_values);
  *residual = relative_residual(K, f, u, reduced);
  return u;
}

double penalised_step_slack(const PenalisedSolver& solver, const SparseMatrix& K, const Eigen::VectorXd& f,
                            const Eigen::VectorXd& u, const Eigen::VectorXd& x) {
  if (!solver.iterative()) return 0.0;
  return std::abs((x - u).dot(K * x - f));
}

double convex_step_length(const std::function<double(double)>& derivative, double size, double slack) {
  // Round-off: the full step's derivative is zero up to the size of its terms.
  if (derivative(1.0) <= 1e-9 * size + slack) return 1.0;
  double lo = 0, hi = 1;
  for (int k = 0; k < 60 && hi - lo > 1e-15; ++k) {
    const double mid = 0.5 * (lo + hi);
    (derivative(mid) > 0 ? hi : lo) = mid;
  }
  return std::max(hi, 1e-12);
}

void report_contact(const ContactOperator& c, const ContactOutcome& out, Json& report) {
  using cli::three_digits;
  const long Q = c.points();
  cli::info("contact: " + std::to_string(out.active) + " of " + std::to_string(Q) + " contact nodes in contact (area " +
            three_digits(out.active_area) + " m^2), " + std::to_string(out.solves) + " solves, " +
            std::to_string(out.updates) + " multiplier updates; largest penetration " +
            three_digits(out.max_penetration) + " m (tolerance " + three_digits(out.tolerance) + " m), normal force " +
            three_digits(out.force) + " N");
  report["contact"] = Json{{"points", Q},
                           {"area", Q > 0 ? c.weight.sum() : 0.0},
                           {"active_points", out.active},
                           {"active_area", out.active_area},
                           {"solves", out.solves},
                           {"multiplier_updates", out.updates},
                           {"damped_steps", out.damped},
                           {"max_penetration", out.max_penetration},
                           {"tolerance", out.tolerance},
                           {"opened_volume", out.opened_volume},
                           {"force", out.force},
                           {"max_pressure", Q > 0 ? out.pressure.maxCoeff() : 0.0}};
}

Eigen::VectorXd solve_with_contact(const LinearSystem& s, const ContactOperator& c, const ContactIteration& settings,
                                   PenalisedSolver& solver, Json& report, double* residual,
                                   ContactOutcome* outcome) {
  using cli::three_digits;
  Eigen::VectorXd u = solver.solve_unpenalised(s, report, residual);
  ContactOutcome out;
  out.solves = 1;
  const SparseMatrix& G = c.G;
  const long Q = c.points();
  double scale = 0;
  for (long d = 0; d < 3 * s.np; ++d) scale = std::max(scale, std::abs(u[d]));
  out.tolerance = settings.tolerance > 0 ? settings.tolerance : 1e-8 * scale;
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(Q), g = G * u;
  std::vector<char> active(static_cast<std::size_t>(Q), 0);
  // The error the iteration must bring below the tolerance: penetration anywhere, and a gap
  // open where the faces still press (g p = 0).
  const auto violation = [&]() {
    double worst = 0;
    for (long q = 0; q < Q; ++q) worst = std::max(worst, active[static_cast<std::size_t>(q)] ? std::abs(g[q]) : -g[q]);
    return worst;
  };
  const auto update_active = [&]() {
    bool changed = false;
    for (long q = 0; q < Q; ++q) {
      const char now = lambda[q] - c.penalty[q] * g[q] > 0;
      changed = changed || now != active[static_cast<std::size_t>(q)];
      active[static_cast<std::size_t>(q)] = now;
    }
    return changed;
  };
  if (violation() > out.tolerance) {
    const SparseMatrix pattern = contact_pattern(s.K, c.G);
    const SparseMatrix Gt = c.G.transpose();
    cli::detail("contact: K has " + std::to_string(s.K.nonZeros()) + " non-zeros, with the contact nodes' couplings " +
                std::to_string(pattern.nonZeros()));
    int inner = 0;
    update_active();
    Eigen::VectorXd stiffness(Q), force(Q);
    for (;;) {
      if (out.solves >= settings.max_solves)
        throw Error("contact: no convergence in " + std::to_string(out.solves) + " solves (largest penetration or "
                    "open gap under pressure " + three_digits(violation()) + " m, tolerance " +
                    three_digits(out.tolerance) + " m); raise --contact-iterations or the contact penalty");
      // (K + sum_A kappa_i W_i G_i^T G_i) u = f + sum_A W_i lambda_i G_i^T
      for (long q = 0; q < Q; ++q) {
        const bool on = active[static_cast<std::size_t>(q)];
        stiffness[q] = on ? c.penalty[q] * c.weight[q] : 0.0;
        force[q] = on ? c.weight[q] * lambda[q] : 0.0;
      }
      SparseMatrix K = pattern + SparseMatrix(Gt * (stiffness.asDiagonal() * c.G));
      if (K.nonZeros() != pattern.nonZeros())  // the penalty term lies inside G^T G's pattern: never
        throw Error("contact: the penalty term left the contact pattern (internal error)");
      const Eigen::VectorXd f = s.f + Gt * force;
      double next_residual = 0;
      const Eigen::VectorXd next = solver.solve(s, K, f, "contact", &next_residual);
      ++out.solves;
      // The Newton step next - u, damped where it would raise the energy of the fixed-lambda
      // problem (line_search): on a curved cut the undamped active-set steps cycle.
      const double alpha = line_search(s, c, lambda, u, g, next - u, penalised_step_slack(solver, K, f, u, next));
      if (alpha == 1.0) {
        u = next;
        *residual = next_residual;
      } else {
        u += alpha * (next - u);
        ++out.damped;
      }
      g = G * u;
      const bool changed = update_active();
      cli::detail("contact: solve " + std::to_string(out.solves) + ": " +
                  std::to_string(std::count(active.begin(), active.end(), 1)) + " nodes active" +
                  (changed ? " (changed)" : "") + (alpha < 1 ? ", step " + three_digits(alpha) : std::string()) +
                  ", largest violation " + three_digits(violation()) + " m");
      if (alpha == 1.0 && violation() <= out.tolerance) break;
      // The inner (semismooth Newton) iteration while A changes, kInnerSolves at most; then the
      // multiplier update (an inexact Uzawa step) makes the progress.
      if ((changed || alpha < 1) && ++inner < kInnerSolves) continue;
      inner = 0;
      for (long q = 0; q < Q; ++q) lambda[q] = std::max(0.0, lambda[q] - c.penalty[q] * g[q]);  // Uzawa
      ++out.updates;
      update_active();
    }
  }
  out.opened_volume = Q > 0 ? c.weight.dot(g) : 0.0;
  out.pressure.resize(Q);
  for (long q = 0; q < Q; ++q) {
    out.pressure[q] = std::max(0.0, lambda[q] - c.penalty[q] * g[q]);
    out.force += c.weight[q] * out.pressure[q];
    if (active[static_cast<std::size_t>(q)]) {
      ++out.active;
      out.active_area += c.weight[q];
    }
    out.max_penetration = std::max(out.max_penetration, -g[q]);
  }
  report_contact(c, out, report);
  if (outcome) *outcome = out;
  return u;
}

}  // namespace xfem
