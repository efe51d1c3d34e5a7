// SPDX-License-Identifier: MIT
#include "xfem/enrich/branch_functions.h"

#include <cmath>

namespace xfem {

BranchValues branch_functions(const CrackTipFrame& frame, const Eigen::Vector3d& x, int side) {
  const Eigen::Vector3d abc = frame.R.transpose() * (x - frame.origin);
  TipCoordinates tc;
  tc.xa = abc[0];
  tc.xb = abc[1];
  // grad_x = R grad_abc because x_abc = R^T (x - origin): rows of R^T.
  tc.grad = frame.R.transpose().topRows<2>();
  return branch_functions(tc, side);
}

BranchValues branch_functions(const TipCoordinates& tc, int side) {
  const double xa = tc.xa, xb = tc.xb;
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
  // A cut that curves away from the plane of b behind the front leaves points of one side with
  // the other sign of xb (between that plane and the cut): they get their face's theta, so that
  // theta = +-pi on the cut faces and F jumps across the cut, nowhere else.
  const bool clamped = side != 0 && xa < 0 && std::abs(xb) > 1e-12 * r && (xb > 0) != (side > 0);
  if (clamped) theta = side > 0 ? M_PI : -M_PI;
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
  // d(r, theta) / d(xa, xb) at the point's own (xa, xb); theta is constant where it is clamped.
  Eigen::Matrix2d dpolar_dab;
  dpolar_dab << xa / r, xb / r,  //
      -xb / (r * r), xa / (r * r);
  if (clamped) dpolar_dab.row(1).setZero();
  out.dF = dpolar * dpolar_dab * tc.grad;
  return out;
}

}  // namespace xfem
