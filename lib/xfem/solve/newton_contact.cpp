// SPDX-License-Identifier: MIT
#include "xfem/solve/newton_contact.h"

#include <algorithm>
#include <cmath>

#include "xfem/core/cli.h"
#include "xfem/core/error.h"

namespace xfem {

NewtonContact::NewtonContact(const ContactOperator& c, long np, const NewtonContactSettings& settings)
    : c_(c), np_(np), settings_(settings), Gt_(c.G.transpose()), lambda_(Eigen::VectorXd::Zero(c.points())) {
  saved_ = lambda_;
}

double NewtonContact::add(double, const Eigen::VectorXd& u, Eigen::VectorXd& R,
                          std::vector<Eigen::Triplet<double, int>>* K) const {
  const long M = c_.points();
  if (M == 0) return 0.0;
  const Eigen::VectorXd g = c_.G * u;
  Eigen::VectorXd force(M), stiffness(M);
  for (long i = 0; i < M; ++i) {
    const double p = std::max(0.0, lambda_[i] - c_.penalty[i] * g[i]);
    force[i] = c_.weight[i] * p;
    stiffness[i] = p > 0 ? c_.penalty[i] * c_.weight[i] : 0.0;
  }
  const Eigen::VectorXd on_dofs = Gt_ * force;
  R -= on_dofs;
  if (K && stiffness.any()) {
    const SparseMatrix A = Gt_ * (stiffness.asDiagonal() * c_.G);
    for (int j = 0; j < A.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(A, j); it; ++it) K->emplace_back(static_cast<int>(it.row()), j, it.value());
  }
  return on_dofs.norm();
}

SparseMatrix NewtonContact::pattern(long dofs) const {
  // G^T G's pattern: a contact node's row couples the DOFs of every cut tet around the node, which
  // the body's pattern does not always couple.
  SparseMatrix P = Gt_ * c_.G;
  P.conservativeResize(dofs, dofs);
  std::fill(P.valuePtr(), P.valuePtr() + P.nonZeros(), 0.0);
  return P;
}

double NewtonContact::tolerance(const Eigen::VectorXd& u) const {
  if (settings_.tolerance > 0) return settings_.tolerance;
  return 1e-8 * u.head(3 * np_).cwiseAbs().maxCoeff();
}

void NewtonContact::begin_step() {
  saved_ = lambda_;
  step_updates_ = 0;
}

void NewtonContact::reject_step() { lambda_ = saved_; }

bool NewtonContact::update(double s, const Eigen::VectorXd& u, LoadStep& step) {
  const ContactOutcome now = outcome(u);
  const Eigen::VectorXd g = c_.G * u;
  // The error Uzawa must bring below the tolerance: penetration anywhere, a gap open under pressure.
  double violation = 0.0;
  for (long i = 0; i < c_.points(); ++i)
    violation = std::max(violation, now.pressure[i] > 0 ? std::abs(g[i]) : -g[i]);
  step.has_contact = true;
  step.active_points = now.active;
  step.max_penetration = now.max_penetration;
  step.contact_force = now.force;
  step.contact_tolerance = now.tolerance;
  if (violation <= now.tolerance) return false;
  if (step_updates_ >= settings_.max_updates)
    throw Error("contact: no convergence in " + std::to_string(step_updates_) + " multiplier updates at load factor " +
                cli::three_digits(s) + " (largest penetration or open gap under pressure " + cli::three_digits(violation) +
                " m, tolerance " + cli::three_digits(now.tolerance) + " m); raise --contact-updates or the contact penalty");
  for (long i = 0; i < c_.points(); ++i) lambda_[i] = std::max(0.0, lambda_[i] - c_.penalty[i] * g[i]);  // Uzawa
  ++step_updates_;
  ++updates_;
  ++step.multiplier_updates;
  return true;
}

ContactOutcome NewtonContact::outcome(const Eigen::VectorXd& u) const {
  ContactOutcome out;
  const long M = c_.points();
  const Eigen::VectorXd g = c_.G * u;
  out.tolerance = tolerance(u);
  out.updates = updates_;
  out.opened_volume = M > 0 ? c_.weight.dot(g) : 0.0;
  out.pressure.resize(M);
  for (long i = 0; i < M; ++i) {
    out.pressure[i] = std::max(0.0, lambda_[i] - c_.penalty[i] * g[i]);
    out.force += c_.weight[i] * out.pressure[i];
    if (out.pressure[i] > 0) {
      ++out.active;
      out.active_area += c_.weight[i];
    }
    out.max_penetration = std::max(out.max_penetration, -g[i]);
  }
  return out;
}

}  // namespace xfem
