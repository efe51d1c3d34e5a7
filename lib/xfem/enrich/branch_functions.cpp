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
  const double r = std::sqrt(xa * xa + xb * xb);
  BranchValues out;
  if (r == 0.0) {
    out.F.setZero();
    out.dF.setZero();
    return out;
  }
  // theta = atan2(xb, xa) in (-pi, pi] enters only through sin and cos of theta and of theta / 2,
  // which follow from (xa, xb, r) without a trigonometric function (this runs for every integration
  // point of a tet with branch DOFs; atan2 and two sincos were a fifth of the straight-front rule's
  // time): cos t = xa / r, sin t = xb / r, and the half angle from whichever of cos^2(t/2) =
  // (r + xa) / 2r and sin^2(t/2) = (r - xa) / 2r has no cancellation (the other from
  // sin t = 2 sin(t/2) cos(t/2)); cos(t/2) >= 0, sin(t/2) has the sign of xb (of a signed zero too,
  // as atan2: -pi for xb = -0 behind the front).
  // On the cut's plane behind the front the face is a choice, not a computation: a rounding of xb
  // must not move a point to the other face.
  const bool on_plane = side != 0 && xa < 0 && std::abs(xb) <= 1e-12 * r;
  // A cut that curves away from the plane of b behind the front leaves points of one side with
  // the other sign of xb (between that plane and the cut): they get their face's theta, so that
  // theta = +-pi on the cut faces and F jumps across the cut, nowhere else.
  const bool clamped = side != 0 && xa < 0 && std::abs(xb) > 1e-12 * r && (xb > 0) != (side > 0);
  double s2, c2, st, ct;
  if (on_plane || clamped) {  // theta = side * pi
    s2 = side > 0 ? 1.0 : -1.0;
    c2 = 0.0;
    st = 0.0;
    ct = -1.0;
  } else if (xa >= 0) {
    c2 = std::sqrt((r + xa) / (2 * r));
    s2 = xb / (2 * r * c2);
    st = xb / r;
    ct = xa / r;
  } else {
    s2 = std::copysign(std::sqrt((r - xa) / (2 * r)), xb);
    c2 = xb / (2 * r * s2);
    st = xb / r;
    ct = xa / r;
  }
  const double sr = std::sqrt(r);
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
