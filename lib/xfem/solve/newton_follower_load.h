// SPDX-License-Identifier: MIT
#pragma once
#include <cmath>

#include "xfem/solve/newton.h"
#include "xfem/system/follower_cut_load.h"

namespace xfem {

/// The follower pressure on the cut's faces (follower_cut_load.h) as a term of Newton's residual:
/// R -= s f(u), tangent += the symmetric part of -s df/du.
class NewtonFollowerLoad : public NewtonTerms {
 public:
  NewtonFollowerLoad(const EnrichedMesh& em, const FollowerCutLoad& load) : em_(em), load_(load) {}
  double add(double s, const Eigen::VectorXd& u, Eigen::VectorXd& R,
             std::vector<Eigen::Triplet<double, int>>* K) const override {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(R.size());
    add_follower_forces(em_, load_, u, s, f, K);
    R -= f;
    return f.norm();
  }

 private:
  const EnrichedMesh& em_;
  const FollowerCutLoad& load_;
};

}  // namespace xfem
