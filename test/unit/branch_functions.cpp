// SPDX-License-Identifier: MIT
#include "xfem/branch_functions.h"

#include <catch2/catch.hpp>
#include <cmath>

namespace {
// A front along the line x = 0.5, z = 0.5 (direction -y), cut in the plane z = 0.5 for x < 0.5
// with normal +z: a = b x c = +x points away from the cut, into the intact material.
xfem::CrackTipFrame test_frame() {
  const xfem::CrackFront front({xfem::FrontSegment{{0.5, 1.0, 0.5}, {0.5, -1.0, 0.5}, {0, 0, 1}}});
  return front.frame({0.2, 0.3, 0.6});
}
}  // namespace

TEST_CASE("branch_functions: F1 jumps by 2 sqrt(r) across the cut and is continuous ahead of the front",
          "[branch_functions]") {
  const xfem::CrackTipFrame f = test_frame();
  const double eps = 1e-9;
  // Behind the front (x < 0.5) across the cut plane z = 0.5, at r = 0.25.
  const auto above = xfem::branch_functions(f, {0.25, 0.3, 0.5 + eps});
  const auto below = xfem::branch_functions(f, {0.25, 0.3, 0.5 - eps});
  CHECK_THAT(above.F[0], Catch::WithinAbs(0.5, 1e-6));  // sqrt(0.25) sin(pi/2)
  CHECK_THAT(below.F[0], Catch::WithinAbs(-0.5, 1e-6));
  // F2..F4 are continuous across the cut (cos(+-pi/2) = 0, sin(+-pi) = 0).
  for (int j = 1; j < 4; ++j) CHECK_THAT(above.F[j] - below.F[j], Catch::WithinAbs(0.0, 1e-6));
  // Ahead of the front (x > 0.5) F is continuous through z = 0.5.
  const auto up = xfem::branch_functions(f, {0.75, 0.3, 0.5 + eps});
  const auto down = xfem::branch_functions(f, {0.75, 0.3, 0.5 - eps});
  for (int j = 0; j < 4; ++j) CHECK_THAT(up.F[j] - down.F[j], Catch::WithinAbs(0.0, 1e-6));
  CHECK_THAT(up.F[1], Catch::WithinAbs(0.5, 1e-6));  // theta = 0: sqrt(r) cos 0
}

TEST_CASE("branch_functions: a point on the cut takes the face it is asked for", "[branch_functions]") {
  const xfem::CrackTipFrame f = test_frame();
  const Eigen::Vector3d on_cut(0.25, 0.3, 0.5);
  CHECK_THAT(xfem::branch_functions(f, on_cut, +1).F[0], Catch::WithinAbs(0.5, 1e-14));
  CHECK_THAT(xfem::branch_functions(f, on_cut, -1).F[0], Catch::WithinAbs(-0.5, 1e-14));
  // Without a side atan2 decides: theta = +pi.
  CHECK_THAT(xfem::branch_functions(f, on_cut, 0).F[0], Catch::WithinAbs(0.5, 1e-14));
  // On the front itself everything is 0 (the gradient's singularity is not evaluated).
  const auto tip = xfem::branch_functions(f, {0.5, 0.7, 0.5});
  CHECK(tip.F.norm() == 0.0);
  CHECK(tip.dF.norm() == 0.0);
}

TEST_CASE("branch_functions: gradients match central finite differences", "[branch_functions]") {
  // A tilted frame so that every component of R matters.
  const Eigen::Vector3d b = Eigen::Vector3d(0.2, -0.3, 1.0).normalized();
  const Eigen::Vector3d p0(0.1, 0.2, 0.3);
  const Eigen::Vector3d dir = Eigen::Vector3d(1.0, 2.0, 0.0).normalized();
  const xfem::CrackFront front({xfem::FrontSegment{p0, p0 + dir, b}});
  const xfem::CrackTipFrame f = front.frame(p0);
  const Eigen::Vector3d x = GENERATE(Eigen::Vector3d(0.4, 0.1, 0.5), Eigen::Vector3d(-0.2, 0.6, 0.1),
                                     Eigen::Vector3d(0.3, 0.5, 0.2), Eigen::Vector3d(-0.1, -0.3, 0.4));
  CAPTURE(x.transpose());
  const auto at = xfem::branch_functions(f, x);
  const double h = 1e-6;
  for (int d = 0; d < 3; ++d) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(d) * h;
    const Eigen::Vector4d fd = (xfem::branch_functions(f, x + e).F - xfem::branch_functions(f, x - e).F) / (2 * h);
    // Central differences: error O(h^2 F''') ~ 1e-11 here; 1e-7 leaves room for rounding (1e-16 / h).
    for (int j = 0; j < 4; ++j) CHECK_THAT(at.dF(j, d), Catch::WithinAbs(fd[j], 1e-7));
  }
}
