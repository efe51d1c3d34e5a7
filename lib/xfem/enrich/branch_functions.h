// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>

#include "xfem/geometry/crack_front.h"

namespace xfem {

/// The four asymptotic crack-tip functions (ACTFs) at a point and their gradients (paper 3.4,
/// DESIGN.md "Numerics"):
///   F = (sqrt r sin(t/2), sqrt r cos(t/2), sqrt r sin(t/2) sin t, sqrt r cos(t/2) sin t),
/// with x_abc = R^T (x - origin), r = sqrt(xa^2 + xb^2), t = theta = atan2(xb, xa) in (-pi, pi].
/// The frame's a points away from the cut into intact material and b is the cut's normal, so the
/// cut lies at theta = +-pi: +pi on its upper face (H = +1), -pi on its lower face. F1 (index 0)
/// therefore jumps by 2 sqrt r across the cut and is smooth ahead of the front (theta = 0).
struct BranchValues {
  Eigen::Vector4d F;                  ///< F_0..F_3, sqrt(metre)
  Eigen::Matrix<double, 4, 3> dF;     ///< row j: grad F_j in global coordinates, 1/sqrt(metre)
};

/// Evaluates F and grad F at x in `frame`. `side` (+1 / -1, 0 = unknown) chooses the face for a
/// point on the cut's plane behind the front (xa < 0, |xb| <= 1e-12 r): theta = side * pi there,
/// so that both faces of the cut can be evaluated; with side 0 atan2 decides (+pi).
/// On the front itself (r = 0) F = 0 and the gradient, which is singular like 1/sqrt r, is
/// returned as 0: integration points never lie there in practice, and a set of measure zero
/// does not change an integral.
BranchValues branch_functions(const CrackTipFrame& frame, const Eigen::Vector3d& x, int side = 0);

/// The same from crack-tip coordinates and their gradients (CrackFront::coordinates, continuous
/// along a curved front): r = sqrt(xa^2 + xb^2), theta = atan2(xb, xa) (evaluated without trigonometric
/// functions: branch_functions.cpp). With `side` given, a point
/// behind the front (xa < 0) whose xb has the other sign than its side (it lies between the plane
/// of b and a cut that curves away from it) gets theta = side * pi, with d theta = 0 there: theta
/// is +-pi exactly on the cut's faces and F is continuous everywhere off the cut.
BranchValues branch_functions(const TipCoordinates& coordinates, int side = 0);

}  // namespace xfem
