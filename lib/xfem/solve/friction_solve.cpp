// SPDX-License-Identifier: MIT
#include "xfem/solve/friction_solve.h"

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

using Vec2 = Eigen::Vector2d;

// Solves of the inner (fixed multipliers) iteration before the multipliers are updated anyway.
constexpr int kInnerSolves = 10;

// K with explicit zeros wherever a node's normal or tangential terms may add something: the
// pattern of B^T B, row i of B the union of the columns of G_i, T_2i and T_2i+1 (a slipping node's
// Hessian couples its two tangential rows): the one pattern of every solve.
SparseMatrix friction_pattern(const SparseMatrix& K, const ContactOperator& c) {
  std::vector<Eigen::Triplet<double, int>> ones;
  for (int j = 0; j < c.G.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(c.G, j); it; ++it) ones.emplace_back(static_cast<int>(it.row()), j, 1.0);
  for (int j = 0; j < c.T.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(c.T, j); it; ++it) ones.emplace_back(static_cast<int>(it.row() / 2), j, 1.0);
  SparseMatrix B(c.G.rows(), c.G.cols());
  B.setFromTriplets(ones.begin(), ones.end());
  return contact_pattern(K, B);
}

// The projection of z on the disc of radius b >= 0 (the friction traction of the augmented
// tangential multiplier z).
Vec2 project(const Vec2& z, double b) {
  const double n = z.norm();
  return n <= b ? z : Vec2(n > 0 ? Vec2(b / n * z) : Vec2::Zero());
}

// The state of the multipliers and the node sets, and the derivatives of the energy Pi.
struct FrictionState {
  const ContactOperator& c;
  Eigen::VectorXd lambda, bound;  // Q: normal multipliers, slip bounds b_i
  Eigen::MatrixXd tangential;     // Q x 2: tangential multipliers l_i
  Eigen::VectorXd g, slip;        // Q, 2Q: G u, T u
  std::vector<char> active, stick;
  long Q;

  explicit FrictionState(const ContactOperator& op)
      : c(op), lambda(Eigen::VectorXd::Zero(op.points())), bound(Eigen::VectorXd::Zero(op.points())),
        tangential(Eigen::MatrixXd::Zero(op.points(), 2)), active(static_cast<std::size_t>(op.points()), 0),
        stick(static_cast<std::size_t>(op.points()), 0), Q(op.points()) {}

  void measure(const Eigen::VectorXd& u) {
    g = c.G * u;
    slip = c.T * u;
  }
  Vec2 s(long q) const { return slip.segment<2>(2 * q); }
  Vec2 z(long q) const { return Vec2(tangential.row(q).transpose()) - c.penalty[q] * s(q); }
  double pressure(long q) const { return std::max(0.0, lambda[q] - c.penalty[q] * g[q]); }
  // Stick: |z| <= b with b > 0 (b = 0: the node is free, no traction).
  bool sticks(long q) const { return bound[q] > 0 && z(q).norm() <= bound[q]; }

  bool update_sets() {
    bool changed = false;
    for (long q = 0; q < Q; ++q) {
      const char a = lambda[q] - c.penalty[q] * g[q] > 0, st = sticks(q);
      changed = changed || a != active[static_cast<std::size_t>(q)] || st != stick[static_cast<std::size_t>(q)];
      active[static_cast<std::size_t>(q)] = a;
      stick[static_cast<std::size_t>(q)] = st;
    }
    return changed;
  }
  // Penetration anywhere and a gap open under pressure (solve_with_contact's measure), metres.
  double normal_violation() const {
    double worst = 0;
    for (long q = 0; q < Q; ++q) worst = std::max(worst, active[static_cast<std::size_t>(q)] ? std::abs(g[q]) : -g[q]);
    return worst;
  }
  // How far the next Uzawa update would move the tangential multipliers and the bounds, in
  // lengths (/ kappa): on a sticking node its slip |s_i|; on a slipping one how far l_i is from
  // the bound traction; and |b_i - mu_i p_i| / kappa_i, the Coulomb fixed point's error.
  double friction_violation() const {
    double worst = 0;
    for (long q = 0; q < Q; ++q) {
      const Vec2 l = tangential.row(q).transpose();
      worst = std::max(worst, (l - project(z(q), bound[q])).norm() / c.penalty[q]);
      worst = std::max(worst, std::abs(bound[q] - c.friction[q] * pressure(q)) / c.penalty[q]);
    }
    return worst;
  }
  // The multipliers of the glued solve: the pressures, their bounds, the tangential tractions
  // (projected on the bounds).
  void start_from_glued() {
    for (long q = 0; q < Q; ++q) {
      lambda[q] = pressure(q);
      bound[q] = c.friction[q] * lambda[q];
      tangential.row(q) = project(-c.penalty[q] * s(q), bound[q]).transpose();
    }
  }
  // Uzawa and the Coulomb fixed point.
  void update_multipliers() {
    for (long q = 0; q < Q; ++q) {
      tangential.row(q) = project(z(q), bound[q]).transpose();
      lambda[q] = pressure(q);
      bound[q] = c.friction[q] * lambda[q];
    }
  }
};

// The step length in (0, 1] along d from u that minimises Pi (friction_solve.h) for fixed
// multipliers: Pi is convex along d, its derivative
//   Pi'(alpha) = d^T (K u - f) + alpha d^T K d - sum_i W_i h_i p_i(alpha) - sum_i W_i k_i . P_b(z_i(alpha))
// (h = G d, k = T d) increasing: 1 when Pi'(1) <= 0, else its root by bisection.
double line_search(const LinearSystem& s, const FrictionState& state, const Eigen::VectorXd& u, const Eigen::VectorXd& d,
                   double slack) {
  const ContactOperator& c = state.c;
  const Eigen::VectorXd h = c.G * d, k = c.T * d;
  const double slope = d.dot(s.K * u - s.f), curvature = d.dot(s.K * d);
  const auto derivative = [&](double alpha) {
    double value = slope + alpha * curvature;
    for (long q = 0; q < state.Q; ++q) {
      value -= c.weight[q] * h[q] * std::max(0.0, state.lambda[q] - c.penalty[q] * (state.g[q] + alpha * h[q]));
      const Vec2 z = state.z(q) - alpha * c.penalty[q] * Vec2(k.segment<2>(2 * q));
      value -= c.weight[q] * Vec2(k.segment<2>(2 * q)).dot(project(z, state.bound[q]));
    }
    return value;
  };
  return convex_step_length(derivative, std::abs(slope) + std::abs(curvature), slack);
}

}  // namespace

Eigen::VectorXd solve_with_friction(const LinearSystem& s, const ContactOperator& c, const ContactIteration& settings,
                                    PenalisedSolver& solver, Json& report, double* residual,
                                    ContactOutcome* outcome, FrictionOutcome* friction) {
  using cli::three_digits;
  if (!c.has_friction() || c.T.rows() != 2 * c.points()) throw Error("friction: the contact operator has no slip rows (internal error)");
  Eigen::VectorXd u = solver.solve_unpenalised(s, report, residual);
  ContactOutcome out;
  out.solves = 1;
  const long Q = c.points();
  double scale = 0;
  for (long d = 0; d < 3 * s.np; ++d) scale = std::max(scale, std::abs(u[d]));
  out.tolerance = settings.tolerance > 0 ? settings.tolerance : 1e-8 * scale;
  FrictionState state(c);
  state.measure(u);
  if (state.normal_violation() > out.tolerance) {
    const SparseMatrix pattern = friction_pattern(s.K, c);
    const SparseMatrix Gt = c.G.transpose(), Tt = c.T.transpose();
    cli::detail("friction: K has " + std::to_string(s.K.nonZeros()) + " non-zeros, with the contact nodes' couplings " +
                std::to_string(pattern.nonZeros()));
    int inner = 0;
    state.update_sets();
    // The first contact solve glues the faces where they touch (every node in contact sticks, the
    // tangential multipliers 0): its pressures give the first slip bounds and its tangential
    // tractions the first tangential multipliers. Started from the frictionless slip instead, a
    // sticking node's z = l - kappa s is first far outside its disc, where the slip Hessian has no
    // stiffness along z: the Newton steps overshoot and the line search crawls (the penny at
    // mu = 1.2 tan beta: 100 solves without converging).
    bool glued = c.friction.maxCoeff() > 0;  // mu = 0 everywhere: nothing to glue
    Eigen::VectorXd stiffness(Q), force(Q), tangential_force(2 * Q);
    std::vector<Eigen::Matrix2d> hessian(static_cast<std::size_t>(Q));
    std::vector<Eigen::Triplet<double, int>> blocks;
    for (;;) {
      if (out.solves >= settings.max_solves)
        throw Error("contact with friction: no convergence in " + std::to_string(out.solves) +
                    " solves (largest penetration or open gap under pressure " + three_digits(state.normal_violation()) +
                    " m, largest friction violation " + three_digits(state.friction_violation()) + " m, tolerance " +
                    three_digits(out.tolerance) + " m); raise --contact-iterations or the contact penalty");
      // The Newton system of Pi at u (friction_solve.h): Hessian H, right-hand side H u - grad Pi(u).
      blocks.clear();
      for (long q = 0; q < Q; ++q) {
        const bool on = state.active[static_cast<std::size_t>(q)];
        const double kw = c.penalty[q] * c.weight[q];
        stiffness[q] = on ? kw : 0.0;
        force[q] = on ? c.weight[q] * state.lambda[q] : 0.0;
        Eigen::Matrix2d H = Eigen::Matrix2d::Zero();
        Vec2 r = Vec2::Zero();
        const Vec2 z = state.z(q);
        if (glued ? on : static_cast<bool>(state.stick[static_cast<std::size_t>(q)])) {
          H = kw * Eigen::Matrix2d::Identity();
          r = c.weight[q] * Vec2(state.tangential.row(q).transpose());
        } else if (state.bound[q] > 0) {  // slip: the bound traction along z, and its curvature across z
          const double norm = z.norm();
          const Vec2 e = z / norm;
          const Eigen::Matrix2d across = Eigen::Matrix2d::Identity() - e * e.transpose();
          H = kw * state.bound[q] / norm * across;
          r = c.weight[q] * state.bound[q] * e + H * state.s(q);
        }
        tangential_force.segment<2>(2 * q) = r;
        hessian[static_cast<std::size_t>(q)] = H;
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b)
            if (H(a, b) != 0.0) blocks.emplace_back(static_cast<int>(2 * q + a), static_cast<int>(2 * q + b), H(a, b));
      }
      SparseMatrix D(2 * Q, 2 * Q);
      D.setFromTriplets(blocks.begin(), blocks.end());
      SparseMatrix K = pattern + SparseMatrix(Gt * (stiffness.asDiagonal() * c.G)) + SparseMatrix(Tt * (D * c.T));
      if (K.nonZeros() != pattern.nonZeros())
        throw Error("friction: the penalty terms left the contact pattern (internal error)");
      const Eigen::VectorXd f = s.f + Gt * force + Tt * tangential_force;
      double next_residual = 0;
      const Eigen::VectorXd next = solver.solve(s, K, f, "friction", &next_residual);
      ++out.solves;
      const Eigen::VectorXd step = next - u;
      const double alpha = line_search(s, state, u, step, penalised_step_slack(solver, K, f, u, next));
      if (alpha == 1.0) {
        u = next;
        *residual = next_residual;
      } else {
        u += alpha * step;
        ++out.damped;
      }
      const double moved = alpha * step.lpNorm<Eigen::Infinity>();
      state.measure(u);
      // The Newton step's error on the friction forces: the linearised force of each node,
      // r_i - H_i s_i (what the solve balanced), against W_i P_b(z_i) at the new u, in lengths
      // (/ W kappa). Zero for sticking and free nodes whose set did not change (their force is
      // linear in u); on a slipping node it is the curvature the Hessian left out.
      double linearisation = 0;
      for (long q = 0; q < Q; ++q) {
        const Vec2 linear = tangential_force.segment<2>(2 * q) - hessian[static_cast<std::size_t>(q)] * state.s(q);
        const Vec2 actual = c.weight[q] * project(state.z(q), state.bound[q]);
        linearisation = std::max(linearisation, (actual - linear).norm() / (c.weight[q] * c.penalty[q]));
      }
      if (glued) {  // the first multipliers from the glued faces (above)
        glued = false;
        state.start_from_glued();
        ++out.updates;
        state.update_sets();
        continue;
      }
      const bool changed = state.update_sets();
      const double normal = state.normal_violation(), tangential = state.friction_violation();
      cli::detail("friction: solve " + std::to_string(out.solves) + ": " +
                  std::to_string(std::count(state.active.begin(), state.active.end(), 1)) + " nodes active, " +
                  std::to_string(std::count(state.stick.begin(), state.stick.end(), 1)) + " sticking" +
                  (changed ? " (changed)" : "") + (alpha < 1 ? ", step " + three_digits(alpha) : std::string()) +
                  ", moved " + three_digits(moved) + " m, largest violation normal " + three_digits(normal) +
                  " m, friction " + three_digits(tangential) + " m, linearisation " + three_digits(linearisation) + " m");
      // Converged: the last Newton step whole and its linearisation exact to the tolerance, the
      // contact and the friction laws met to the tolerance.
      if (alpha == 1.0 && linearisation <= out.tolerance && normal <= out.tolerance && tangential <= out.tolerance) break;
      // The inner (Newton) iteration for the fixed multipliers while the sets change or the
      // linearisation is off, kInnerSolves at most; then the multipliers' update.
      if ((changed || alpha < 1 || linearisation > out.tolerance) && ++inner < kInnerSolves) continue;
      inner = 0;
      state.update_multipliers();
      ++out.updates;
      state.update_sets();
    }
  }
  FrictionOutcome fr;
  fr.traction = Eigen::MatrixXd::Zero(Q, 3);
  Eigen::Vector3d shear = Eigen::Vector3d::Zero();
  out.opened_volume = Q > 0 ? c.weight.dot(state.g) : 0.0;
  out.pressure.resize(Q);
  for (long q = 0; q < Q; ++q) {
    out.pressure[q] = state.pressure(q);
    out.force += c.weight[q] * out.pressure[q];
    out.max_penetration = std::max(out.max_penetration, -state.g[q]);
    const Vec2 t = project(state.z(q), state.bound[q]);
    fr.traction.row(q) = t[0] * c.tangents.row(q).head<3>() + t[1] * c.tangents.row(q).tail<3>();
    shear += c.weight[q] * fr.traction.row(q).transpose();
    fr.max_slip_all = std::max(fr.max_slip_all, state.s(q).norm());
    if (!state.active[static_cast<std::size_t>(q)]) continue;
    ++out.active;
    out.active_area += c.weight[q];
    fr.max_slip = std::max(fr.max_slip, state.s(q).norm());
    if (state.stick[static_cast<std::size_t>(q)]) {
      ++fr.stick;
      fr.stick_area += c.weight[q];
    } else {
      ++fr.slip;
      fr.slip_area += c.weight[q];
    }
    if (c.friction[q] * out.pressure[q] > 0)
      fr.max_traction_ratio = std::max(fr.max_traction_ratio, t.norm() / (c.friction[q] * out.pressure[q]));
  }
  fr.shear_force = shear.norm();
  report_contact(c, out, report);
  cli::info("friction: " + std::to_string(fr.stick) + " nodes stick (area " + three_digits(fr.stick_area) + " m^2), " +
            std::to_string(fr.slip) + " slip (area " + three_digits(fr.slip_area) + " m^2); largest slip " +
            three_digits(fr.max_slip) + " m, shear force " + three_digits(fr.shear_force) + " N");
  report["friction"] = Json{{"max_coefficient", Q > 0 ? c.friction.maxCoeff() : 0.0},
                            {"stick_points", fr.stick},
                            {"stick_area", fr.stick_area},
                            {"slip_points", fr.slip},
                            {"slip_area", fr.slip_area},
                            {"max_slip", fr.max_slip},
                            {"max_slip_all", fr.max_slip_all},
                            {"max_traction_ratio", fr.max_traction_ratio},
                            {"shear_force", fr.shear_force}};
  if (outcome) *outcome = out;
  if (friction) *friction = fr;
  return u;
}

}  // namespace xfem
