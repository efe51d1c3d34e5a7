// SPDX-License-Identifier: MIT
#include "xfem/integrate/element_stiffness.h"

#include <catch2/catch.hpp>

namespace {
const Eigen::Vector3d o(0, 0, 0), ex(1, 0, 0), ey(0, 1, 0), ez(0, 0, 1);

// Rigid motions of the 4 nodes as 12-vectors: 3 translations, 3 rotations.
Eigen::Matrix<double, 12, 6> rigid_modes(const Eigen::Vector3d* p) {
  Eigen::Matrix<double, 12, 6> r = Eigen::Matrix<double, 12, 6>::Zero();
  for (int n = 0; n < 4; ++n)
    for (int a = 0; a < 3; ++a) {
      r(3 * n + a, a) = 1.0;
      r.block<3, 1>(3 * n, 3 + a) = Eigen::Vector3d::Unit(a).cross(p[n]);
    }
  return r;
}
}  // namespace

TEST_CASE("element_stiffness: Lame parameters of E = 1, nu = 0.25", "[element_stiffness]") {
  const xfem::Lame m = xfem::lame(1.0, 0.25);
  CHECK_THAT(m.lambda, Catch::WithinRel(0.4, 1e-15));  // 0.25 / (1.25 * 0.5)
  CHECK_THAT(m.mu, Catch::WithinRel(0.4, 1e-15));      // 1 / 2.5
}

TEST_CASE("element_stiffness: the reference tet with E = 1, nu = 0.25 against hand values", "[element_stiffness]") {
  // Reference tet (0,0,0), (1,0,0), (0,1,0), (0,0,1): V = 1/6, grad N0 = (-1,-1,-1), grad N1 = e_x,
  // grad N2 = e_y, grad N3 = e_z; lambda = mu = 0.4. With k[3n+j][3m+i] =
  // V (mu g_n,i g_m,j + lambda g_n,j g_m,i + delta_ij mu g_n.g_m):
  //   k[0][0] (n=m=0, i=j=x):   (0.4 + 0.4 + 0.4*3) / 6 = 1/3
  //   k[3][3] (n=m=1, x,x):     (0.4 + 0.4 + 0.4*1) / 6 = 0.2
  //   k[4][4] (n=m=1, y,y):     (0 + 0 + 0.4) / 6       = 1/15
  //   k[3][7] (n=1 x, m=2 y):   mu g_1,y g_2,x = 0; lambda g_1,x g_2,y = 0.4 -> 1/15
  //   k[4][6] (n=1 y, m=2 x):   mu g_1,x g_2,y = 0.4; lambda g_1,y g_2,x = 0 -> 1/15
  //   k[0][3] (n=0 x, m=1 x):   (0.4*(-1) + 0.4*(-1) + 0.4*(-1)) / 6 = -0.2
  //   k[1][3] (n=0 y, m=1 x):   mu g_0,x g_1,y = 0; lambda g_0,y g_1,x = -0.4 -> -1/15
  //   k[3][6] (n=1 x, m=2 x):   0 (g_1 . g_2 = 0, no x-y products)
  const auto k = xfem::tet_stiffness(xfem::tet_shape(o, ex, ey, ez), xfem::lame(1.0, 0.25));
  CHECK_THAT(k(0, 0), Catch::WithinAbs(1.0 / 3.0, 1e-15));
  CHECK_THAT(k(3, 3), Catch::WithinAbs(0.2, 1e-15));
  CHECK_THAT(k(4, 4), Catch::WithinAbs(1.0 / 15.0, 1e-15));
  CHECK_THAT(k(3, 7), Catch::WithinAbs(1.0 / 15.0, 1e-15));
  CHECK_THAT(k(4, 6), Catch::WithinAbs(1.0 / 15.0, 1e-15));
  CHECK_THAT(k(0, 3), Catch::WithinAbs(-0.2, 1e-15));
  CHECK_THAT(k(1, 3), Catch::WithinAbs(-1.0 / 15.0, 1e-15));
  CHECK_THAT(k(3, 6), Catch::WithinAbs(0.0, 1e-15));
}

TEST_CASE("element_stiffness: a tet's stiffness is symmetric PSD with the 6 rigid modes as null space", "[element_stiffness]") {
  const Eigen::Vector3d p[4] = {{0.1, 0.2, 0.3}, {1.3, 0.1, 0.4}, {0.2, 1.1, 0.2}, {0.3, 0.4, 1.5}};
  const auto k = xfem::tet_stiffness(xfem::tet_shape(p[0], p[1], p[2], p[3]), xfem::lame(300e3, 0.35));
  const double scale = k.cwiseAbs().maxCoeff();
  CHECK((k - k.transpose()).cwiseAbs().maxCoeff() <= 1e-14 * scale);
  CHECK((k * rigid_modes(p)).cwiseAbs().maxCoeff() <= 1e-12 * scale);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 12, 12>> eig(k);
  const auto ev = eig.eigenvalues();  // increasing
  for (int i = 0; i < 6; ++i) CHECK(std::abs(ev[i]) <= 1e-12 * ev[11]);
  CHECK(ev[6] > 1e-6 * ev[11]);
}
