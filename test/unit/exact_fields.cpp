// SPDX-License-Identifier: MIT
#include "xfem/fracture/exact_fields.h"

#include "xfem/enrich/branch_functions.h"

#include <catch2/catch.hpp>

namespace {

// Stress from the displacement gradient by central differences (step h), Hooke's law.
Eigen::Matrix3d stress(const xfem::WilliamsField& f, const Eigen::Vector3d& x, double h) {
  Eigen::Matrix3d G;
  for (int j = 0; j < 3; ++j) {
    const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(j);
    G.col(j) = (f.displacement(x + e) - f.displacement(x - e)) / (2 * h);
  }
  const Eigen::Matrix3d eps = 0.5 * (G + G.transpose());
  const double lambda = f.E * f.nu / ((1 + f.nu) * (1 - 2 * f.nu)), mu = f.E / (2 * (1 + f.nu));
  return lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2 * mu * eps;
}

xfem::WilliamsField tilted(double K1, double K2, double K3) {
  xfem::WilliamsField f;
  f.origin = Eigen::Vector3d(0.1, -0.2, 0.3);
  f.a = Eigen::Vector3d(1, 1, 0).normalized();
  f.b = Eigen::Vector3d(-1, 1, 1).normalized();
  f.b = (f.b - f.b.dot(f.a) * f.a).normalized();
  f.K1 = K1, f.K2 = K2, f.K3 = K3;
  f.E = 3e5, f.nu = 0.35;
  return f;
}

}  // namespace

TEST_CASE("exact_fields: Williams fields satisfy equilibrium away from the front", "[exact_fields]") {
  // div sigma = 0 by nested central differences; the scale is sigma / distance ~ K / r^1.5.
  auto mode = GENERATE(0, 1, 2);
  const auto f = tilted(mode == 0, mode == 1, mode == 2);
  const Eigen::Vector3d c = f.a.cross(f.b);
  for (double angle : {-2.5, -1.0, 0.3, 2.0}) {
    const double r = 0.05;
    const Eigen::Vector3d x = f.origin + r * (std::cos(angle) * f.a + std::sin(angle) * f.b) + 0.02 * c;
    const double h = 1e-3;
    Eigen::Vector3d div = Eigen::Vector3d::Zero();
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(j);
      div += (stress(f, x + e, 1e-5) - stress(f, x - e, 1e-5)).col(j) / (2 * h);
    }
    const double scale = stress(f, x, 1e-5).norm() / r;
    CAPTURE(mode, angle, div.transpose(), scale);
    CHECK(div.norm() < 1e-3 * scale);
  }
}

TEST_CASE("exact_fields: Williams fields leave the cut faces traction free and open them", "[exact_fields]") {
  auto mode = GENERATE(0, 1, 2);
  const auto f = tilted(mode == 0, mode == 1, mode == 2);
  const double r = 0.04, h = 1e-7;
  for (int side : {+1, -1}) {
    // Just off the face, on its own side: traction sigma . b vanishes on the face.
    const Eigen::Vector3d x = f.origin - r * f.a + side * 2 * h * f.b;
    const Eigen::Vector3d traction = stress(f, x, h) * f.b;
    const double scale = stress(f, f.origin + r * f.a, h).norm();
    CAPTURE(mode, side, traction.transpose(), scale);
    CHECK(traction.norm() < 1e-4 * scale);
  }
  // The faces separate: the jump is nonzero behind the front and zero ahead of it.
  const Eigen::Vector3d behind = f.origin - r * f.a, ahead = f.origin + r * f.a;
  CHECK((f.displacement(behind, +1) - f.displacement(behind, -1)).norm() > 0);
  CHECK((f.displacement(ahead, +1) - f.displacement(ahead, -1)).norm() == 0);
}

TEST_CASE("exact_fields: mode I opens the cut by the textbook crack opening", "[exact_fields]") {
  // Crack opening displacement, plane strain: delta = 8 K1 sqrt(r / 2pi) (1 - nu^2) / E.
  const auto f = tilted(2.0, 0, 0);
  const double r = 0.01;
  const Eigen::Vector3d x = f.origin - r * f.a;
  const double opening = (f.displacement(x, +1) - f.displacement(x, -1)).dot(f.b);
  CHECK_THAT(opening, Catch::WithinRel(8 * 2.0 * std::sqrt(r / (2 * M_PI)) * (1 - f.nu * f.nu) / f.E, 1e-12));
}

TEST_CASE("exact_fields: a rigid motion has no strain", "[exact_fields]") {
  xfem::RigidMotion m{{0.01, 0, 0.02}, {0.001, -0.002, 0.003}, {0.5, 0.5, 0.5}};
  const Eigen::Vector3d x(0.2, 0.7, 0.1);
  Eigen::Matrix3d G;
  for (int j = 0; j < 3; ++j) G.col(j) = m.displacement(x + Eigen::Vector3d::Unit(j)) - m.displacement(x);
  CHECK((G + G.transpose()).norm() < 1e-15);
}

TEST_CASE("exact_fields: Williams fields are combinations of the crack-tip functions", "[exact_fields]") {
  // u = C F(x) in the field's own frame and in a frame with the normal reversed; gradient = C dF.
  auto mode = GENERATE(0, 1, 2);
  const auto f = tilted(mode == 0, mode == 1, mode == 2);
  xfem::CrackTipFrame flipped = f.frame();
  flipped.R.col(1) *= -1;
  flipped.R.col(2) *= -1;
  flipped.origin += 0.3 * f.a.cross(f.b);  // another point of the same front line
  const auto C = f.branch_coefficients(), C2 = f.branch_coefficients(flipped, 1e-12);
  for (double angle : {-3.0, -1.0, 0.5, 2.9}) {
    const Eigen::Vector3d x = f.origin + 0.07 * (std::cos(angle) * f.a + std::sin(angle) * f.b) + 0.01 * f.a.cross(f.b);
    const Eigen::Vector3d u = f.displacement(x);
    CAPTURE(mode, angle);
    CHECK((C * xfem::branch_functions(f.frame(), x).F - u).norm() < 1e-14 * u.norm());
    CHECK((C2 * xfem::branch_functions(flipped, x).F - u).norm() < 1e-14 * u.norm());
    Eigen::Matrix3d G;
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d e = 1e-6 * Eigen::Vector3d::Unit(j);
      G.col(j) = (f.displacement(x + e) - f.displacement(x - e)) / 2e-6;
    }
    CHECK((f.gradient(x) - G).norm() < 1e-6 * G.norm());  // central differences: O(h^2) ~ 1e-10 relative
  }
}

TEST_CASE("exact_fields: a frame on another front line is refused", "[exact_fields]") {
  const auto f = tilted(1, 0, 0);
  xfem::CrackTipFrame other = f.frame();
  other.origin += 0.01 * f.b;
  CHECK_THROWS_WITH(f.branch_coefficients(other, 1e-6), Catch::Contains("is not the mesh's cut front"));
}
