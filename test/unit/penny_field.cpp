// SPDX-License-Identifier: MIT
// Sneddon's penny-shaped crack (exact_fields.h): each property that makes it an exact solution,
// checked independently of the formulas it is built from.
#include <random>

#include "xfem/fracture/exact_fields.h"
#include "xfem/core/json_io.h"
#include "xfem/system/problem.h"

#include <catch2/catch.hpp>

namespace {

xfem::PennyField tilted_penny() {
  xfem::PennyField f;
  f.centre = Eigen::Vector3d(0.2, -0.1, 0.4);
  f.normal = Eigen::Vector3d(1, -2, 3).normalized();
  f.radius = 0.3;
  f.sigma = 2.5e3;
  f.E = 3e5;
  f.nu = 0.3;
  return f;
}

// A frame (e1, e2, n) of the disc.
Eigen::Matrix3d disc_frame(const xfem::PennyField& f) {
  Eigen::Matrix3d R;
  R.col(2) = f.normal;
  R.col(0) = f.normal.unitOrthogonal();
  R.col(1) = f.normal.cross(R.col(0));
  return R;
}

Eigen::Vector3d point(const xfem::PennyField& f, double r, double angle, double z) {
  const Eigen::Matrix3d R = disc_frame(f);
  return f.centre + r * (std::cos(angle) * R.col(0) + std::sin(angle) * R.col(1)) + z * R.col(2);
}

// Hooke's law applied to a displacement gradient.
Eigen::Matrix3d hooke(const xfem::PennyField& f, const Eigen::Matrix3d& G) {
  const Eigen::Matrix3d eps = 0.5 * (G + G.transpose());
  const double mu = f.E / (2 * (1 + f.nu)), lambda = 2 * mu * f.nu / (1 - 2 * f.nu);
  return lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2 * mu * eps;
}

// Random points away from the disc and its front (distance >= 0.05 a from the disc), both halves.
std::vector<Eigen::Vector3d> random_points(const xfem::PennyField& f, int count) {
  std::mt19937 gen(15);
  std::uniform_real_distribution<double> r(0.0, 2.5), angle(0.0, 2 * M_PI), z(-1.5, 1.5);
  std::vector<Eigen::Vector3d> out;
  while (static_cast<int>(out.size()) < count) {
    const double rr = r(gen) * f.radius, zz = z(gen) * f.radius;
    const double to_disc = rr <= f.radius ? std::abs(zz) : std::hypot(rr - f.radius, zz);
    if (to_disc < 0.05 * f.radius) continue;
    out.push_back(point(f, rr, angle(gen), zz));
  }
  return out;
}

}  // namespace

TEST_CASE("penny: the gradient is the displacement's, by central differences", "[penny]") {
  const auto f = tilted_penny();
  const double h = 1e-6 * f.radius;
  for (const Eigen::Vector3d& x : random_points(f, 40)) {
    Eigen::Matrix3d G;
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(j);
      G.col(j) = (f.displacement(x + e) - f.displacement(x - e)) / (2 * h);
    }
    const Eigen::Matrix3d exact = f.gradient(x);
    CAPTURE(x.transpose(), G, exact);
    CHECK((G - exact).norm() < 1e-7 * exact.norm());
    // Compatibility in stress form: sigma = C : grad u with the numerical gradient.
    CHECK((hooke(f, G) - f.stress(x)).norm() < 1e-7 * f.stress(x).norm());
  }
}

TEST_CASE("penny: equilibrium, div sigma = 0, at random points", "[penny]") {
  const auto f = tilted_penny();
  const double h = 1e-5 * f.radius;
  for (const Eigen::Vector3d& x : random_points(f, 40)) {
    Eigen::Vector3d div = Eigen::Vector3d::Zero();
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(j);
      div += (f.stress(x + e) - f.stress(x - e)).col(j) / (2 * h);
    }
    const double scale = f.sigma / f.radius;
    CAPTURE(x.transpose(), div.transpose());
    CHECK(div.norm() < 1e-5 * scale);
  }
}

TEST_CASE("penny: the crack faces are traction free and open by Sneddon's ellipsoid", "[penny]") {
  const auto f = tilted_penny();
  const double a = f.radius;
  for (double rho : {0.0, 0.2, 0.5, 0.8, 0.95, 0.995}) {
    for (double angle : {0.3, 2.0, 4.5}) {
      const Eigen::Vector3d x = point(f, rho * a, angle, 0.0);
      const double opening = (f.displacement(x, +1) - f.displacement(x, -1)).dot(f.normal);
      const double sneddon = 8 * (1 - f.nu * f.nu) * f.sigma / (M_PI * f.E) * std::sqrt(a * a - rho * rho * a * a);
      CAPTURE(rho, angle, opening, sneddon);
      CHECK_THAT(opening, Catch::WithinRel(sneddon, 1e-10));
      // The faces slide only radially and symmetrically: no tangential jump.
      const Eigen::Vector3d jump = f.displacement(x, +1) - f.displacement(x, -1);
      CHECK((jump - jump.dot(f.normal) * f.normal).norm() < 1e-12 * sneddon + 1e-20);
      for (int side : {+1, -1}) {
        const Eigen::Vector3d traction = f.stress(x, side) * f.normal;
        CAPTURE(side, traction.transpose());
        CHECK(traction.norm() < 1e-9 * f.sigma);
      }
    }
  }
  // Outside the disc the plane z = 0 does not open.
  const Eigen::Vector3d out = point(f, 1.3 * a, 1.0, 0.0);
  CHECK((f.displacement(out, +1) - f.displacement(out, -1)).norm() == 0);
}

TEST_CASE("penny: far away the stress is the remote tension", "[penny]") {
  const auto f = tilted_penny();
  const Eigen::Matrix3d remote = f.sigma * f.normal * f.normal.transpose();
  for (double distance : {10.0, 100.0}) {
    for (const Eigen::Vector3d& dir : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0.3, 0.5, -1).normalized()}) {
      const Eigen::Vector3d x = f.centre + distance * f.radius * dir;
      const double deviation = (f.stress(x) - remote).norm() / f.sigma;
      CAPTURE(distance, deviation);
      // The perturbation decays like (a / distance)^3.
      CHECK(deviation < 2.0 / (distance * distance * distance));
      CHECK(deviation > 1e-3 / (distance * distance * distance));
    }
  }
}

TEST_CASE("penny: K_I from the near-front field is 2 sigma sqrt(a / pi)", "[penny]") {
  const auto f = tilted_penny();
  const double a = f.radius;
  CHECK_THAT(f.K1(), Catch::WithinRel(2 * f.sigma * std::sqrt(a / M_PI), 1e-15));
  for (double angle : {0.0, 1.7, 4.0}) {
    // Ahead of the front: sigma_nn sqrt(2 pi rho) -> K_I; behind it: the opening
    // 8 (1 - nu^2) / E K_I sqrt(rho / 2 pi). Both converge like rho^(1/2): two radii, extrapolated.
    double stress_k[2], opening_k[2];
    const double rhos[2] = {1e-6 * a, 4e-6 * a};
    for (int i = 0; i < 2; ++i) {
      const double rho = rhos[i];
      stress_k[i] = f.normal.dot(f.stress(point(f, a + rho, angle, 0.0)) * f.normal) * std::sqrt(2 * M_PI * rho);
      const Eigen::Vector3d x = point(f, a - rho, angle, 0.0);
      const double opening = (f.displacement(x, +1) - f.displacement(x, -1)).dot(f.normal);
      opening_k[i] = opening * f.E / (8 * (1 - f.nu * f.nu) * std::sqrt(rho / (2 * M_PI)));
    }
    const double from_stress = 2 * stress_k[0] - stress_k[1], from_opening = 2 * opening_k[0] - opening_k[1];
    CAPTURE(angle, stress_k[0], stress_k[1], opening_k[0], opening_k[1]);
    CHECK_THAT(from_stress, Catch::WithinRel(f.K1(), 1e-5));
    CHECK_THAT(from_opening, Catch::WithinRel(f.K1(), 1e-5));
    // Mode I only: no shear traction on the plane ahead of the front.
    const Eigen::Vector3d t = f.stress(point(f, a + rhos[0], angle, 0.0)) * f.normal;
    CHECK((t - t.dot(f.normal) * f.normal).norm() < 1e-9 * std::abs(t.dot(f.normal)));
  }
}

TEST_CASE("penny: the field is finite and symmetric on the axis, the front and the plane", "[penny]") {
  const auto f = tilted_penny();
  const double a = f.radius;
  for (const Eigen::Vector3d& x : {f.centre, point(f, a, 1.0, 0.0), point(f, 0.0, 0.0, 0.7 * a), point(f, 2 * a, 0.5, 0.0)}) {
    CAPTURE(x.transpose());
    CHECK(f.displacement(x).allFinite());
    CHECK(f.gradient(x).allFinite());
  }
  // Mirror symmetry about the disc's plane: u_n odd, the in-plane part even (remote part removed).
  const Eigen::Vector3d above = point(f, 0.6 * a, 2.0, 0.3 * a), below = point(f, 0.6 * a, 2.0, -0.3 * a);
  const Eigen::Matrix3d eps = f.sigma / f.E * ((1 + f.nu) * f.normal * f.normal.transpose() - f.nu * Eigen::Matrix3d::Identity());
  const Eigen::Vector3d ua = f.displacement(above) - eps * (above - f.centre), ub = f.displacement(below) - eps * (below - f.centre);
  CHECK(std::abs(ua.dot(f.normal) + ub.dot(f.normal)) < 1e-12 * ua.norm());
  CHECK(((ua - ua.dot(f.normal) * f.normal) - (ub - ub.dot(f.normal) * f.normal)).norm() < 1e-12 * ua.norm());
  CHECK(ua.dot(f.normal) > 0);  // the upper face moves up
}

TEST_CASE("penny: parsed from an exact-field JSON, bad values refused", "[penny]") {
  const auto parse = [](const char* text) {
    return xfem::parse_exact_field(xfem::Json::parse(text), "exact.json", "");
  };
  const xfem::ExactField f = parse(
      R"({"penny": {"centre": [0.5, 0.5, 0.5], "normal": [0, 0, 2], "radius": 0.25, "sigma": 3, "E": 10, "nu": 0.25}})");
  REQUIRE(f.kind == xfem::ExactField::Kind::Penny);
  CHECK(f.penny.normal.isApprox(Eigen::Vector3d::UnitZ()));
  CHECK(f.penny.radius == 0.25);
  CHECK(f.penny.sigma == 3);
  CHECK(f.penny.E == 10);
  CHECK(f.penny.nu == 0.25);
  // ExactField dispatches to the penny.
  const Eigen::Vector3d x(0.6, 0.45, 0.5);
  CHECK(f.displacement(x, -1) == f.penny.displacement(x, -1));
  CHECK(f.gradient(x, +1) == f.penny.gradient(x, +1));
  CHECK_THROWS_WITH(parse(R"({"penny": {"normal": [0, 0, 1], "radius": -1, "sigma": 1, "E": 1, "nu": 0.3}})"),
                    Catch::Contains("radius must be positive"));
  CHECK_THROWS_WITH(parse(R"({"penny": {"normal": [0, 0, 1], "radius": 1, "sigma": 1}})"),
                    Catch::Contains("needs E and nu"));
  CHECK_THROWS_WITH(parse(R"({"penny": {"normal": [0, 0, 0], "radius": 1, "sigma": 1, "E": 1, "nu": 0.3}})"),
                    Catch::Contains("normal"));
}

TEST_CASE("penny: Somigliana's integral of Sneddon's opening gives Sneddon's field (the shear part's quadrature)",
          "[penny]") {
  // The normal part, a closed form, from the quadrature the shear part uses: the opening
  // 8 (1 - nu^2) sigma / (pi E) sqrt(a^2 - r^2) n, at points 0.25 a .. 3 a from the disc.
  const xfem::PennyField f = tilted_penny();
  const Eigen::Matrix3d eps =
      f.sigma / f.E * ((1 + f.nu) * f.normal * f.normal.transpose() - f.nu * Eigen::Matrix3d::Identity());
  const Eigen::Vector3d jump = 8 * (1 - f.nu * f.nu) * f.sigma / (M_PI * f.E) * f.normal;
  double worst = 0.0, scale = 0.0;
  for (const auto& [r, z] : std::vector<std::pair<double, double>>{
           {0.0, 0.26}, {0.5, -0.26}, {1.0, 0.26}, {1.26, 0.0}, {1.3, -0.2}, {2.0, 1.0}, {0.3, 3.0}, {3.0, -0.5}}) {
    for (double angle : {0.0, 1.0, 4.0}) {
      const Eigen::Vector3d x = point(f, r * f.radius, angle, z * f.radius);
      const Eigen::Vector3d exact = f.displacement(x) - eps * (x - f.centre);
      const Eigen::Vector3d quad = f.elliptical_jump_displacement(x, jump);
      worst = std::max(worst, (quad - exact).norm());
      scale = std::max(scale, exact.norm());
    }
  }
  INFO("worst " << worst << " of " << scale);
  CHECK(worst < 1e-8 * scale);
  // Closer than 0.25 a it refuses.
  CHECK_THROWS_WITH(f.elliptical_jump_displacement(point(f, 0.5 * f.radius, 0.0, 0.2 * f.radius), jump),
                    Catch::Contains("closer than 0.25 radius"));
}

TEST_CASE("penny: under remote shear an elastic field that tends to the remote shear and K_II and K_III along the front",
          "[penny]") {
  xfem::PennyField f = tilted_penny();
  f.sigma = 0.0;
  const Eigen::Matrix3d R = disc_frame(f);
  f.shear = 1.5e3 * (0.6 * R.col(0) + 0.8 * R.col(1));
  const double mu = f.E / (2 * (1 + f.nu)), lambda = 2 * mu * f.nu / (1 - 2 * f.nu);
  // Navier's equation (lambda + mu) grad div u + mu lap u = 0 by second differences at points away from the disc.
  const double h = 1e-3 * f.radius;
  for (const auto& [r, z] : std::vector<std::pair<double, double>>{{0.2, 0.6}, {1.6, 0.1}, {0.9, -0.8}, {2.5, 2.0}}) {
    const Eigen::Vector3d x = point(f, r * f.radius, 0.7, z * f.radius);
    Eigen::Matrix3d H[3];  // H[i](j, k) = d2 u_i / dx_j dx_k
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d ej = h * Eigen::Vector3d::Unit(j), ek = h * Eigen::Vector3d::Unit(k);
        const Eigen::Vector3d d2 = (f.displacement(x + ej + ek) - f.displacement(x + ej - ek) -
                                    f.displacement(x - ej + ek) + f.displacement(x - ej - ek)) / (4 * h * h);
        for (int i = 0; i < 3; ++i) H[i](j, k) = d2[i];
      }
    Eigen::Vector3d navier;
    for (int i = 0; i < 3; ++i) navier[i] = (lambda + mu) * (H[0](i, 0) + H[1](i, 1) + H[2](i, 2)) + mu * H[i].trace();
    INFO("r " << r << " z " << z << ": " << navier.transpose());
    CHECK(navier.norm() < 1e-4 * f.shear.norm() / f.radius);
  }
  // Far away the perturbation decays like (a / d)^2: the displacement tends to the remote shear strain's.
  const Eigen::Matrix3d eps = (1 + f.nu) / f.E * (f.shear * f.normal.transpose() + f.normal * f.shear.transpose());
  for (double d : {10.0, 20.0}) {
    const Eigen::Vector3d x = point(f, 0.6 * d * f.radius, 2.0, 0.8 * d * f.radius);
    const double rel = (f.displacement(x) - eps * (x - f.centre)).norm() / (eps * (x - f.centre)).norm();
    CHECK(rel < 3.0 / (d * d * d));
  }
  // The factors: K_II = 4 / (pi (2 - nu)) tau sqrt(pi a) cos phi, K_III = 4 (1 - nu) / (pi (2 - nu)) tau sqrt(pi a)
  // sin phi (phi from tau, about n; c = a x b = -e_phi), K_I = 0.
  const double tau = f.shear.norm(), phi0 = std::atan2(0.8, 0.6);
  for (double phi : {0.0, 0.9, 2.0, 4.5}) {
    const Eigen::Vector3d K = f.stress_intensity(point(f, 1.0001 * f.radius, phi, 0.0));
    CHECK_THAT(K[0], Catch::WithinAbs(0.0, 1e-12));
    CHECK_THAT(K[1], Catch::WithinAbs(4 / (M_PI * (2 - f.nu)) * tau * std::sqrt(M_PI * f.radius) * std::cos(phi - phi0), 1e-9 * tau));
    CHECK_THAT(K[2], Catch::WithinAbs(4 * (1 - f.nu) / (M_PI * (2 - f.nu)) * tau * std::sqrt(M_PI * f.radius) *
                                          std::sin(phi - phi0), 1e-9 * tau));
  }
  CHECK_THROWS_WITH(f.gradient(point(f, 2 * f.radius, 0, 0)), Catch::Contains("not available"));
}

TEST_CASE("penny: \"loading\": \"closed\" is the uniform compression with no opening; a tension refused",
          "[penny]") {
  const auto parse = [](const char* text) {
    return xfem::parse_exact_field(xfem::Json::parse(text), "exact.json", "");
  };
  const xfem::ExactField f = parse(
      R"({"penny": {"normal": [0, 0, 1], "radius": 0.3, "sigma": -2, "loading": "closed", "E": 1, "nu": 0.3}})");
  REQUIRE(f.penny.closed);
  // Uniform: sigma n n^T, the strain -2 ((1 + nu) e_z e_z - nu I) / E at every point, on both faces.
  const Eigen::Vector3d x(0.1, -0.05, 0.0);
  Eigen::Matrix3d eps = Eigen::Matrix3d::Identity() * 0.6;
  eps(2, 2) = -2.0;
  CHECK(f.gradient(x, 1).isApprox(eps, 1e-14));
  CHECK((f.displacement(x, 1) - f.displacement(x, -1)).norm() == 0.0);  // no opening
  CHECK(f.displacement(x, 1).isApprox(eps * x, 1e-14));
  CHECK_THROWS_WITH(
      parse(R"({"penny": {"normal": [0, 0, 1], "radius": 1, "sigma": 1, "loading": "closed", "E": 1, "nu": 0.3}})"),
      Catch::Contains("sigma must be <= 0 with \"loading\": \"closed\""));
  CHECK_THROWS_WITH(
      parse(R"({"penny": {"normal": [0, 0, 1], "radius": 1, "sigma": 1, "loading": "shut", "E": 1, "nu": 0.3}})"),
      Catch::Contains("\"remote\", \"faces\" or \"closed\""));
}
