// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>

#include "xfem/solve/contact_solve.h"
#include "xfem/solve/newton.h"
#include "xfem/system/contact_operator.h"

namespace xfem {

/// Settings of contact in xfem-newton (--contact-tol, --contact-updates).
struct NewtonContactSettings {
  /// Largest penetration (and open gap under pressure) accepted at the end of a load step, metres;
  /// 0: 1e-8 times the largest |u| of the original DOFs at that step (xfem-solve's default).
  double tolerance = 0.0;
  int max_updates = 50;  ///< multiplier updates per load step at most
};

/// Frictionless contact between a cut's faces in the large-deformation solve (docs/METHOD.md
/// "Contact and pressure on the cut's faces at large deformation"), on contact_operator's per-node
/// weighted gaps g = G u, measured in the REFERENCE configuration (small sliding: the faces' points
/// that face each other before the load still do; valid while the faces slide along each other
/// by much less than a contact node's spacing and turn by small angles relative to each other, a
/// rigid motion of the two faces together included: it leaves g = 0). With multipliers lambda_i
/// (nominal pressure, Pa) and penalties kappa_i, the pressure p_i = max(0, lambda_i - kappa_i g_i)
/// adds
///   R -= sum_i W_i p_i G_i^T,   tangent += sum_{i: p_i > 0} kappa_i W_i G_i^T G_i
/// at every Newton iteration: the active set follows u inside Newton (semismooth Newton); after
/// a load step has converged the multipliers are updated, lambda_i <- p_i (Uzawa), and Newton runs
/// again at the same load until the largest penetration, and the largest gap left open under
/// pressure, are below the tolerance. The multipliers carry over to the next load step.
class NewtonContact : public NewtonTerms {
 public:
  /// `c` must outlive this; `np` the mesh's nodes (the tolerance's max |u| is over their DOFs).
  NewtonContact(const ContactOperator& c, long np, const NewtonContactSettings& settings);
  double add(double s, const Eigen::VectorXd& u, Eigen::VectorXd& R,
             std::vector<Eigen::Triplet<double, int>>* K) const override;
  SparseMatrix pattern(long dofs) const override;
  bool update(double s, const Eigen::VectorXd& u, LoadStep& step) override;
  void begin_step() override;
  void reject_step() override;
  /// The state at u (the converged solution): pressures, active set, penetration, force; the
  /// fields of xfem-solve's ContactOutcome (solves: 0; updates: all load steps').
  ContactOutcome outcome(const Eigen::VectorXd& u) const;
  /// The tolerance of u (settings', or 1e-8 max |u| on the original DOFs).
  double tolerance(const Eigen::VectorXd& u) const;

 private:
  const ContactOperator& c_;
  long np_;
  NewtonContactSettings settings_;
  SparseMatrix Gt_;
  Eigen::VectorXd lambda_, saved_;
  int step_updates_ = 0, updates_ = 0;
};

}  // namespace xfem
