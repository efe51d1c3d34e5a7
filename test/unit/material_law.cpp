// SPDX-License-Identifier: MIT
#include "xfem/integrate/material_law.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "xfem/core/error.h"

namespace {

using Mat9 = Eigen::Matrix<double, 9, 9>;
using xfem::MaterialLaw;
using xfem::MaterialModel;
using xfem::StressAt;

const double kE = 5e3;  // Pa: soft tissue
const xfem::Lame kLame = xfem::lame(kE, 0.4);

MaterialLaw law_of(MaterialModel model) { return {model, kLame}; }

StressAt evaluate(MaterialModel model, const Eigen::Matrix3d& F) {
  StressAt s;
  REQUIRE(xfem::stress_at(law_of(model), F, s));
  return s;
}

Eigen::Matrix3d unit_matrix(int k, int L) {
  Eigen::Matrix3d e = Eigen::Matrix3d::Zero();
  e(k, L) = 1.0;
  return e;
}

// Central differences of the energy: dPsi/dF_kL.
Eigen::Matrix3d stress_by_differences(MaterialModel model, const Eigen::Matrix3d& F, double h) {
  Eigen::Matrix3d P;
  for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L)
      P(k, L) = (evaluate(model, F + h * unit_matrix(k, L)).energy - evaluate(model, F - h * unit_matrix(k, L)).energy) /
                (2 * h);
  return P;
}

// Central differences of P: column 3k+L holds dP_iJ/dF_kL at row 3i+J.
Mat9 tangent_by_differences(MaterialModel model, const Eigen::Matrix3d& F, double h) {
  Mat9 A;
  for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L) {
      const Eigen::Matrix3d dP =
          (evaluate(model, F + h * unit_matrix(k, L)).P - evaluate(model, F - h * unit_matrix(k, L)).P) / (2 * h);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A(3 * i + j, 3 * k + L) = dP(i, j);
    }
  return A;
}

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
}

// F = Q1 diag(sigma) Q2 with random rotations: any singular values, signs and rotation sizes.
Eigen::Matrix3d deformation(std::mt19937& rng, const Eigen::Vector3d& sigma) {
  return random_rotation(rng) * sigma.asDiagonal() * random_rotation(rng);
}

struct Case {
  const char* what;
  Eigen::Matrix3d F;
};

std::vector<Case> deformations(bool inverted) {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  std::vector<Case> cases;
  for (int n = 0; n < 3; ++n) {
    Eigen::Matrix3d small;
    for (int k = 0; k < 9; ++k) small(k / 3, k % 3) = u(rng);
    cases.push_back({"well-conditioned I + G", Eigen::Matrix3d::Identity() + small});
    cases.push_back({"large rotations", deformation(rng, Eigen::Vector3d(1.3, 1.1, 0.9))});
    cases.push_back({"strong stretch", deformation(rng, Eigen::Vector3d(2.5, 1.0, 0.4))});
    cases.push_back({"near-repeated singular values", deformation(rng, Eigen::Vector3d(1.1, 1.1 + 1e-9, 0.7))});
    cases.push_back({"repeated singular values", deformation(rng, Eigen::Vector3d(0.8, 1.2, 1.2))});
    if (inverted) cases.push_back({"inverted, J < 0", deformation(rng, Eigen::Vector3d(1.6, 1.2, -0.4))});
  }
  return cases;
}

double relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / b.norm(); }

// lambda d_iJ d_kL + mu (d_ik d_JL + d_iL d_Jk): the elasticity tensor of linear elasticity.
Mat9 elasticity_tensor() {
  Mat9 C = Mat9::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L)
          C(3 * i + j, 3 * k + L) = kLame.lambda * (i == j) * (k == L) + kLame.mu * ((i == k) * (j == L) + (i == L) * (j == k));
  return C;
}

const MaterialModel kModels[] = {MaterialModel::Linear, MaterialModel::Corotational, MaterialModel::NeoHookean};

}  // namespace

TEST_CASE("material law: P and A match central differences of the energy and of P, A symmetric", "[material]") {
  for (MaterialModel model : kModels) {
    for (const Case& c : deformations(model == MaterialModel::Corotational)) {
      INFO(xfem::material_model_name(model) << ", " << c.what << ", F =\n" << c.F);
      const StressAt s = evaluate(model, c.F);
      const double h = 1e-5;
      const double p_error = relative(stress_by_differences(model, c.F, h), s.P);
      const double a_error = relative(tangent_by_differences(model, c.F, h), s.A);
      INFO("P error " << p_error << ", A error " << a_error);
      CHECK(p_error < 1e-6);
      CHECK(a_error < 1e-6);
      CHECK((s.A - s.A.transpose()).norm() <= 1e-12 * s.A.norm());
    }
  }
}

TEST_CASE("material law: rigid rotations are stress-free for corotational and neo-Hookean", "[material]") {
  std::mt19937 rng(7);
  std::vector<Eigen::Matrix3d> rotations = {
      Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix(),
      Eigen::AngleAxisd(M_PI, Eigen::Vector3d(0, 0, 1)).toRotationMatrix(),
      Eigen::AngleAxisd(3.0, Eigen::Vector3d(-1, 0.5, 2).normalized()).toRotationMatrix()};
  for (int n = 0; n < 5; ++n) rotations.push_back(random_rotation(rng));
  for (MaterialModel model : {MaterialModel::Corotational, MaterialModel::NeoHookean})
    for (const Eigen::Matrix3d& R : rotations) {
      INFO(xfem::material_model_name(model) << ", R =\n" << R);
      const StressAt s = evaluate(model, R);
      CHECK(s.P.norm() < 1e-12 * kE);
      CHECK(std::abs(s.energy) < 1e-12 * kE);
    }
}

TEST_CASE("material law: the linear law's stress under a rotation is its closed form", "[material]") {
  for (double theta : {0.3, 1.0, M_PI / 2, 2.5}) {
    const Eigen::Matrix3d R = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const StressAt s = evaluate(MaterialModel::Linear, R);
    const double c = std::cos(theta) - 1.0;  // eps = diag(c, c, 0)
    Eigen::Matrix3d expected = Eigen::Matrix3d::Zero();
    expected(0, 0) = expected(1, 1) = 2.0 * (kLame.lambda + kLame.mu) * c;
    expected(2, 2) = 2.0 * kLame.lambda * c;
    CHECK((s.P - expected).norm() <= 1e-12 * expected.norm());
    CHECK(s.energy == Approx(2.0 * kLame.mu * c * c + 2.0 * kLame.lambda * c * c).epsilon(1e-12));
  }
}

TEST_CASE("material law: at F = I all three models are stress-free with the linear elasticity tensor", "[material]") {
  const Mat9 C = elasticity_tensor();
  for (MaterialModel model : kModels) {
    INFO(xfem::material_model_name(model));
    const StressAt s = evaluate(model, Eigen::Matrix3d::Identity());
    CHECK(s.P.norm() < 1e-12 * kE);
    CHECK(std::abs(s.energy) < 1e-12 * kE);
    CHECK(relative(s.A, C) < 1e-12);
  }
}

TEST_CASE("material law: neo-Hookean uniaxial stress to stretch 1.5", "[material]") {
  const double mu = kLame.mu, lambda = kLame.lambda, stretch = 1.5;
  // Lateral stretch s with P22 = mu (s - 1/s) + lambda ln(stretch s^2) / s = 0, by Newton.
  double s = 1.0;
  for (int it = 0; it < 50; ++it) {
    const double lnJ = std::log(stretch * s * s);
    const double g = mu * (s - 1 / s) + lambda * lnJ / s;
    const double dg = mu * (1 + 1 / (s * s)) + lambda * (2 - lnJ) / (s * s);
    s -= g / dg;
  }
  REQUIRE(s < 1.0);
  const StressAt st = evaluate(MaterialModel::NeoHookean, Eigen::Vector3d(stretch, s, s).asDiagonal());
  const double P11 = mu * (stretch - 1 / stretch) + lambda * std::log(stretch * s * s) / stretch;
  REQUIRE(P11 > 0.0);
  CHECK(st.P(0, 0) == Approx(P11).epsilon(1e-12));
  Eigen::Matrix3d rest = st.P;
  rest(0, 0) = 0.0;
  CHECK(rest.norm() < 1e-10 * P11);  // lateral faces and every shear traction free
}

TEST_CASE("material law: neo-Hookean simple shear gives Cauchy sigma_12 = mu gamma", "[material]") {
  for (double gamma : {0.1, 0.5, 2.0}) {
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    F(0, 1) = gamma;
    const StressAt s = evaluate(MaterialModel::NeoHookean, F);
    const Eigen::Matrix3d sigma = xfem::cauchy_stress(s.P, F);
    CHECK(sigma(0, 1) == Approx(kLame.mu * gamma).epsilon(1e-10));
    CHECK(sigma(1, 0) == Approx(kLame.mu * gamma).epsilon(1e-10));
    CHECK(sigma(0, 0) == Approx(kLame.mu * gamma * gamma).epsilon(1e-10));  // the Poynting effect
    CHECK(std::abs(sigma(1, 1)) < 1e-10 * kLame.mu);
    CHECK(std::abs(sigma(2, 2)) < 1e-10 * kLame.mu);
  }
}

TEST_CASE("material law: cauchy_stress is P F^T / J: neo-Hookean (mu (B - I) + lambda ln J I) / J, objective", "[material]") {
  std::mt19937 rng(11);
  const Eigen::Matrix3d F = deformation(rng, Eigen::Vector3d(1.4, 0.9, 0.7));
  const Eigen::Matrix3d Q = random_rotation(rng);
  const double J = F.determinant();
  const Eigen::Matrix3d expected =
      (kLame.mu * (F * F.transpose() - Eigen::Matrix3d::Identity()) + kLame.lambda * std::log(J) * Eigen::Matrix3d::Identity()) / J;
  const Eigen::Matrix3d sigma = xfem::cauchy_stress(evaluate(MaterialModel::NeoHookean, F).P, F);
  CHECK(relative(sigma, expected) < 1e-12);
  CHECK((sigma - sigma.transpose()).norm() < 1e-12 * sigma.norm());
  for (MaterialModel model : {MaterialModel::Corotational, MaterialModel::NeoHookean}) {
    INFO(xfem::material_model_name(model));
    const Eigen::Matrix3d rotated = xfem::cauchy_stress(evaluate(model, Q * F).P, Q * F);
    CHECK(relative(rotated, Q * xfem::cauchy_stress(evaluate(model, F).P, F) * Q.transpose()) < 1e-12);
  }
}

TEST_CASE("material law: corotational stays finite where the polar rotation is not unique", "[material]") {
  // sigma_2 + sigma_3 = 0 (a plane flipped by 180 degrees), a flat and a collapsed element.
  for (const Eigen::Vector3d& d : {Eigen::Vector3d(1, 1, -1), Eigen::Vector3d(2, 0.5, -0.5), Eigen::Vector3d(1, 1, 0),
                                   Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, 0)}) {
    INFO("F = diag(" << d.transpose() << ")");
    const StressAt s = evaluate(MaterialModel::Corotational, d.asDiagonal());
    CHECK(std::isfinite(s.energy));
    CHECK(s.P.allFinite());
    CHECK(s.A.allFinite());
    CHECK((s.A - s.A.transpose()).norm() <= 1e-12 * s.A.norm());
    // Psi = mu sum (sigma_a - 1)^2 + lambda/2 (J - 1)^2 with the reflection in the smallest value.
    Eigen::Vector3d sorted = d.cwiseAbs();
    std::sort(sorted.data(), sorted.data() + 3, std::greater<double>());
    if (d.prod() < 0) sorted(2) = -sorted(2);
    const double J = d.prod();
    CHECK(s.energy == Approx(kLame.mu * (sorted.array() - 1).square().sum() + 0.5 * kLame.lambda * (J - 1) * (J - 1)).epsilon(1e-12));
  }
}

TEST_CASE("material law: the corotational energy of an inverted F counts the reflection", "[material]") {
  // F = diag(1, 1, -1): the nearest rotation is 180 degrees about an axis in the x-y plane, so
  // |F - R|^2 = (1 - 1)^2 + (1 - 1)^2 + (-1 - 1)^2 = 4 and J - 1 = -2.
  const StressAt s = evaluate(MaterialModel::Corotational, Eigen::Vector3d(1, 1, -1).asDiagonal());
  CHECK(s.energy == Approx(4 * kLame.mu + 2 * kLame.lambda).epsilon(1e-12));
}

TEST_CASE("material law: neo-Hookean rejects J <= 0", "[material]") {
  StressAt s;
  const MaterialLaw law = law_of(MaterialModel::NeoHookean);
  CHECK_FALSE(xfem::stress_at(law, Eigen::Vector3d(1, 1, -1).asDiagonal(), s));
  CHECK_FALSE(xfem::stress_at(law, Eigen::Vector3d(1, 1, 0).asDiagonal(), s));
  CHECK(xfem::stress_at(law, Eigen::Vector3d(1, 1, 1e-3).asDiagonal(), s));
  CHECK(s.P.allFinite());
}

TEST_CASE("material law: neo-Hookean continued below Jc is the law above it, C2 at Jc, and its own derivatives below",
          "[material]") {
  // The law the points next to a crack front use (element_forces.h): h(J) = -mu ln J +
  // lambda/2 (ln J)^2 replaced below Jc by its Taylor polynomial of degree 2.
  const double Jc = 0.1;
  const MaterialLaw law = law_of(MaterialModel::NeoHookean);
  auto continued = [&](const Eigen::Matrix3d& F) {
    StressAt s;
    REQUIRE(xfem::stress_at(law, F, s, Jc));
    return s;
  };
  std::mt19937 rng(7);
  // Above Jc: the law itself, bit for bit.
  for (const Eigen::Vector3d& sigma : {Eigen::Vector3d(1.2, 0.9, 0.8), Eigen::Vector3d(0.5, 0.5, 0.5)}) {
    const Eigen::Matrix3d F = deformation(rng, sigma);
    const StressAt a = evaluate(MaterialModel::NeoHookean, F), b = continued(F);
    CHECK(a.energy == b.energy);
    CHECK(a.P == b.P);
    CHECK(a.A == b.A);
  }
  // At Jc: energy, P and A continuous (F = s Q1 Q2 with s^3 = Jc (1 -+ 1e-9)).
  const Eigen::Matrix3d Q = random_rotation(rng) * random_rotation(rng);
  const Eigen::Matrix3d F_above = std::cbrt(Jc * (1 + 1e-9)) * Q, F_below = std::cbrt(Jc * (1 - 1e-9)) * Q;
  const StressAt above = continued(F_above), below = continued(F_below);
  CHECK(std::abs(above.energy - below.energy) <= 1e-7 * std::abs(above.energy));
  CHECK((above.P - below.P).norm() <= 1e-7 * above.P.norm());
  CHECK((above.A - below.A).norm() <= 1e-6 * above.A.norm());
  // Below Jc, also at J <= 0: P and A are the derivatives of the energy; the energy grows as J falls.
  for (const Eigen::Vector3d& sigma :
       {Eigen::Vector3d(0.5, 0.3, 0.2), Eigen::Vector3d(2.0, 1.0, 0.01), Eigen::Vector3d(1.0, 1.0, 0.0),
        Eigen::Vector3d(1.5, 1.0, -0.4), Eigen::Vector3d(3.0, 2.0, -1.0)}) {
    const Eigen::Matrix3d F = deformation(rng, sigma);
    const StressAt s = continued(F);
    Eigen::Matrix3d P;
    Mat9 A;
    const double h = 1e-6;
    for (int k = 0; k < 3; ++k)
      for (int L = 0; L < 3; ++L) {
        const StressAt plus = continued(F + h * unit_matrix(k, L)), minus = continued(F - h * unit_matrix(k, L));
        P(k, L) = (plus.energy - minus.energy) / (2 * h);
        const Eigen::Matrix3d dP = (plus.P - minus.P) / (2 * h);
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) A(3 * i + j, 3 * k + L) = dP(i, j);
      }
    CHECK((s.P - P).norm() <= 1e-6 * s.P.norm());
    CHECK((s.A - A).norm() <= 1e-6 * s.A.norm());
    CHECK((s.A - s.A.transpose()).norm() <= 1e-12 * s.A.norm());
    CHECK(s.energy > 0);
  }
  // Along F = diag(1, 1, J): the energy rises monotonically as J falls through Jc, 0 and below.
  double previous = continued(Eigen::Vector3d(1, 1, 0.16).asDiagonal()).energy;
  for (double J = 0.08; J > -1.0; J -= 0.08) {
    const double e = continued(Eigen::Vector3d(1, 1, J).asDiagonal()).energy;
    CHECK(e > previous - 1e-9 * std::abs(previous));
    previous = e;
  }
}

TEST_CASE("material law: model names round-trip; an unknown name is an error listing the models", "[material]") {
  for (MaterialModel model : kModels) CHECK(xfem::material_model_named(xfem::material_model_name(model)) == model);
  CHECK(xfem::material_model_named("neo-hookean") == MaterialModel::NeoHookean);
  CHECK_THROWS_WITH(xfem::material_model_named("neohookean"),
                    Catch::Contains("\"neohookean\"") && Catch::Contains("linear, corotational, neo-hookean"));
  CHECK_THROWS_AS(xfem::material_model_named(""), xfem::Error);
}

TEST_CASE("material law: cofactor is J F^-T and its derivative matches differences", "[material]") {
  std::mt19937 rng(3);
  const Eigen::Matrix3d F = deformation(rng, Eigen::Vector3d(1.5, 0.8, -0.6));
  CHECK(relative(xfem::cofactor(F), F.determinant() * F.inverse().transpose()) < 1e-13);
  const Mat9 H = xfem::cofactor_derivative(F);
  const double h = 1e-4;  // cof is quadratic in F: central differences are exact up to round-off
  for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L) {
      const Eigen::Matrix3d dC = (xfem::cofactor(F + h * unit_matrix(k, L)) - xfem::cofactor(F - h * unit_matrix(k, L))) / (2 * h);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) CHECK(std::abs(H(3 * i + j, 3 * k + L) - dC(i, j)) < 1e-9);
    }
}
