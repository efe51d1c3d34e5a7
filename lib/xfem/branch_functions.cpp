// SPDX-License-Identifier: MIT
#include "xfem/branch_functions.h"

#include <cmath>

namespace xfem {

BranchValues branch_functions(const CrackTipFrame& frame, const Eigen::Vector3d& x, int side) {
  const Eigen::Vector3d abc = frame.R.transpose() * (x - frame.origin);
  const double xa = abc[0], xb = abc[1];
  const double r = std::hypot(xa, xb);
  BranchValues out;
  if (r == 0.0) {
    out.F.setZero();
    out.dF.setZero();
    return out;
  }
  double theta = std::atan2(xb, xa);
  // On the cut's plane behind the front the face is a choice, not a computation: a rounding of xb
  // must not move a point to the other face.
  if (side != 0 && xa < 0 && std::abs(xb) <= 1e-12 * r) theta = side > 0 ? M_PI : -M_PI;
  const double sr = std::sqrt(r), s2 = std::sin(theta / 2), c2 = std::cos(theta / 2);
  const double st = std::sin(theta), ct = std::cos(theta);
  out.F << sr * s2, sr * c2, sr * s2 * st, sr * c2 * st;
  // dF/dr and dF/dtheta, then the chain rule through (xa, xb): dr = (ct, st), dtheta = (-st, ct) / r.
  const double h = 0.5 / sr;
  Eigen::Matrix<double, 4, 2> dpolar;
  dpolar << h * s2, 0.5 * sr * c2,                                   //
      h * c2, -0.5 * sr * s2,                                        //
      h * s2 * st, sr * (0.5 * c2 * st + s2 * ct),                   //
      h * c2 * st, sr * (-0.5 * s2 * st + c2 * ct);
  Eigen::Matrix<double, 2, 3> dpolar_dabc;
  dpolar_dabc << ct, st, 0.0,  //
      -st / r, ct / r, 0.0;
  // grad_x = R grad_abc because x_abc = R^T (x - origin): as rows, dF_x = dF_abc R^T.
  out.dF = dpolar * dpolar_dabc * frame.R.transpose();
  return out;
}

}  // namespace xfem
