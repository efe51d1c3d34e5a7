// SPDX-License-Identifier: MIT
#include "xfem/geometry/tet_shape.h"

#include <catch2/catch.hpp>

#include "xfem/core/error.h"

namespace {
const Eigen::Vector3d p0(0.1, 0.2, 0.3), p1(1.3, 0.1, 0.4), p2(0.2, 1.1, 0.2), p3(0.3, 0.4, 1.5);
}

TEST_CASE("tet_shape: N_m is 1 at node m and 0 at the others", "[tet_shape]") {
  const xfem::TetShape s = xfem::tet_shape(p0, p1, p2, p3);
  const Eigen::Vector3d p[4] = {p0, p1, p2, p3};
  for (int n = 0; n < 4; ++n) {
    const Eigen::Vector4d N = s.values(p[n]);
    for (int m = 0; m < 4; ++m) CHECK_THAT(N[m], Catch::WithinAbs(m == n ? 1.0 : 0.0, 1e-14));
  }
  // Partition of unity: the gradients sum to zero.
  CHECK(s.grad.colwise().sum().norm() < 1e-14);
  CHECK_THAT(s.volume, Catch::WithinRel(xfem::signed_volume(p0, p1, p2, p3), 1e-14));
}

TEST_CASE("tet_shape: interpolation reproduces a linear function and its gradient", "[tet_shape]") {
  const xfem::TetShape s = xfem::tet_shape(p0, p1, p2, p3);
  const Eigen::Vector3d g(0.7, -1.3, 2.1);
  const auto f = [&](const Eigen::Vector3d& x) { return 0.5 + g.dot(x); };
  const Eigen::Vector4d nodal(f(p0), f(p1), f(p2), f(p3));
  const Eigen::Vector3d x(0.4, 0.35, 0.5);
  CHECK_THAT(s.values(x).dot(nodal), Catch::WithinAbs(f(x), 1e-13));
  CHECK((s.grad.transpose() * nodal - g).norm() < 1e-13);
}

TEST_CASE("tet_shape: a flat tet is rejected", "[tet_shape]") {
  CHECK_THROWS_AS(xfem::tet_shape(p0, p1, p2, p0 + (p1 - p0) + (p2 - p0)), xfem::Error);
}
