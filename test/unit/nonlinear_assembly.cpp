// SPDX-License-Identifier: MIT
// The nonlinear path (element_points, element_forces, nonlinear_assembly, newton): the linear model
// reproduces the linear assembly and solve, the tangent is the derivative of the forces and the
// forces the derivative of the energy over every DOF kind (original, sign, branch), rigid motions
// are stress-free cut or not (each side of a cut turned on its own too), and Newton converges
// quadratically to a closed-form finite deformation.
#include "xfem/system/nonlinear_assembly.h"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>

#include "xfem/enrich/classification.h"
#include "xfem/generate/box_mesh.h"
#include "xfem/generate/cut_generation.h"
#include "xfem/progressive/progressive_cut.h"
#include "xfem/solve/cholmod_solver.h"
#include "xfem/solve/newton.h"
#include "xfem/system/assembly.h"
#include "xfem/system/deformed_volume_at_points.h"
#include "xfem/system/dirichlet.h"
#include "enriched_test_meshes.h"

namespace {

using V = Eigen::Vector3d;
constexpr double kE = 1e3, kNu = 0.3;

xfem::MaterialLaw law(xfem::MaterialModel model) { return {model, xfem::lame(kE, kNu)}; }

// A 3 x 3 x 6 box of [0,1]^2 x [0,2] cut by the plane z = 0.93 from x < 0 to x = 0.55: original,
// sign and branch DOFs, completely and partially cut tets and blending tets.
xfem::EnrichedMesh partially_cut_box() {
  const xfem::TetMesh mesh = xfem::box_mesh({3, 3, 6}, {0, 0, 0}, {1, 1, 2});
  const auto cut = std::make_shared<xfem::CutSurface>(
      xfem::cut_parallelogram({-0.2, -0.2, 0.93}, {0.55, -0.2, 0.93}, {-0.2, 1.2, 0.93}, {3, 3}));
  return xfem::enriched_mesh(mesh, xfem::classify(mesh, *cut), cut);
}

Eigen::VectorXd random_vector(long n, double scale, unsigned seed) {
  std::srand(seed);
  return scale * Eigen::VectorXd::Random(n);
}

// The displacement of every original DOF from a field of the position; enriched DOFs 0.
template <class Field>
Eigen::VectorXd nodal(const xfem::EnrichedMesh& em, Field field) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * em.n);
  for (long k = 0; k < em.np; ++k) u.segment<3>(3 * k) = field(V(em.mesh.points.row(k).transpose()));
  return u;
}

Eigen::Matrix3d rotation(const V& axis, double degrees) {
  return Eigen::AngleAxisd(degrees * M_PI / 180.0, axis.normalized()).toRotationMatrix();
}

double forces_norm(const xfem::EnrichedMesh& em, const xfem::BodyIntegration& body, const xfem::MaterialLaw& m,
                   const Eigen::VectorXd& u) {
  double energy = 0.0;
  Eigen::VectorXd r;
  REQUIRE(xfem::internal_forces(em, body, m, u, energy, r, nullptr));
  return r.lpNorm<Eigen::Infinity>();
}

}  // namespace

TEST_CASE("nonlinear assembly: the linear model's tangent is the linear stiffness and its forces K u", "[nonlinear]") {
  const xfem::EnrichedMesh em = partially_cut_box();
  REQUIRE(em.ns > 0);
  REQUIRE(em.nb > 0);
  const xfem::SparseMatrix K = xfem::stiffness_matrix(em, xfem::lame(kE, kNu), xfem::Quadrature(), nullptr, {}, 3);
  const xfem::BodyIntegration body = xfem::integrate_body(em, 3);
  std::vector<int> outer;
  xfem::SparseMatrix T = xfem::pattern_matrix(em, body.pattern, outer);
  const Eigen::VectorXd u = random_vector(3 * em.n, 1e-3, 7);
  double energy = 0.0;
  Eigen::VectorXd r;
  REQUIRE(xfem::internal_forces(em, body, law(xfem::MaterialModel::Linear), u, energy, r, &T));
  const double scale = Eigen::MatrixXd(K).cwiseAbs().maxCoeff();
  CHECK(Eigen::MatrixXd(T - K).cwiseAbs().maxCoeff() <= 1e-12 * scale);
  const Eigen::VectorXd Ku = xfem::SparseMatrix(K.selfadjointView<Eigen::Lower>()) * u;
  CHECK((r - Ku).lpNorm<Eigen::Infinity>() <= 1e-12 * Ku.lpNorm<Eigen::Infinity>());
  CHECK(energy == Approx(0.5 * u.dot(Ku)).epsilon(1e-12));
  // Heaviside-only tets are evaluated once per side: fewer points than the linear rule has.
  CHECK(body.points < 40000);
}

TEST_CASE("nonlinear assembly: tangent and forces are the derivatives of the energy over every DOF kind",
          "[nonlinear]") {
  const xfem::EnrichedMesh em = partially_cut_box();
  const xfem::BodyIntegration body = xfem::integrate_body(em, 3);
  for (auto model : {xfem::MaterialModel::Corotational, xfem::MaterialModel::NeoHookean}) {
    INFO(xfem::material_model_name(model));
    const xfem::MaterialLaw m = law(model);
    // A finite rotation and stretch with a random perturbation of every DOF, enriched ones too.
    const Eigen::Matrix3d F = rotation(V(1, 2, 3), 40) * Eigen::Vector3d(1.2, 0.9, 1.05).asDiagonal();
    const Eigen::VectorXd u = nodal(em, [&](const V& x) { V y = F * x - x; return y; }) + random_vector(3 * em.n, 2e-3, 11);
    const Eigen::VectorXd v = random_vector(3 * em.n, 1.0, 13);
    std::vector<int> outer;
    xfem::SparseMatrix K = xfem::pattern_matrix(em, body.pattern, outer);
    double energy = 0.0, ep = 0.0, em_ = 0.0;
    Eigen::VectorXd r, rp, rm;
    REQUIRE(xfem::internal_forces(em, body, m, u, energy, r, &K));
    const double h = 1e-6;
    REQUIRE(xfem::internal_forces(em, body, m, u + h * v, ep, rp, nullptr));
    REQUIRE(xfem::internal_forces(em, body, m, u - h * v, em_, rm, nullptr));
    const Eigen::VectorXd Kv = xfem::SparseMatrix(K.selfadjointView<Eigen::Lower>()) * v;
    const Eigen::VectorXd fd = (rp - rm) / (2 * h);
    CHECK((Kv - fd).norm() <= 1e-6 * Kv.norm());
    CHECK((ep - em_) / (2 * h) == Approx(r.dot(v)).epsilon(1e-6));
    // The check sees every DOF kind: the tangent's enriched block is not zero.
    CHECK(Kv.tail(3 * (em.n - em.np)).norm() > 1e-3 * Kv.norm());
  }
}

TEST_CASE("nonlinear assembly: rigid rotations are stress-free, uncut, cut through, and each side turned alone",
          "[nonlinear]") {
  const xfem::EnrichedMesh uncut = xfem_test::plain(xfem::box_mesh({2, 2, 2}, {0, 0, 0}, {1, 1, 1}));
  const xfem::EnrichedMesh cut = xfem_test::cut_box(0.25);  // cut clean through at z = 0.25
  const V centre(0.3, 0.4, 0.5);
  const Eigen::Matrix3d R1 = rotation(V(1, 1, 0), 90), R2 = rotation(V(0, 1, 1), -60);
  auto rigid = [&](const Eigen::Matrix3d& R) { return [&R, &centre](const V& x) { return V(R * (x - centre) + centre - x); }; };
  // The open book: the side z > 0.25 turned by R1, the side below by R2. With the shifted
  // Heaviside a node's original DOF carries its own side's motion and its sign DOF the jump.
  Eigen::VectorXd book = Eigen::VectorXd::Zero(3 * cut.n);
  for (int t = 0; t < cut.tets(); ++t)
    for (long e = cut.offsets[t]; e < cut.offsets[t + 1]; ++e) {
      const int k = cut.mesh.tets(t, cut.local[e]);
      const V x = cut.mesh.points.row(k).transpose();
      const V upper = rigid(R1)(x), lower = rigid(R2)(x);
      if (cut.dofs[e] < cut.np) book.segment<3>(3 * k) = cut.side[k] > 0 ? upper : lower;
      else book.segment<3>(3 * cut.dofs[e]) = upper - lower;
    }
  const xfem::BodyIntegration body_uncut = xfem::integrate_body(uncut, 3), body_cut = xfem::integrate_body(cut, 3);
  const double limit = 1e-8 * kE;  // forces over faces of order 1 m^2
  for (auto model : {xfem::MaterialModel::Corotational, xfem::MaterialModel::NeoHookean}) {
    INFO(xfem::material_model_name(model));
    CHECK(forces_norm(uncut, body_uncut, law(model), nodal(uncut, rigid(R1))) < limit);
    CHECK(forces_norm(cut, body_cut, law(model), nodal(cut, rigid(R1))) < limit);
    CHECK(forces_norm(cut, body_cut, law(model), book) < limit);
  }
  // The linear model stretches a rotated body: forces of the order of E.
  const double linear = forces_norm(uncut, body_uncut, law(xfem::MaterialModel::Linear), nodal(uncut, rigid(R1)));
  WARN("largest nodal force of a 90 degree rotation, linear model: " << linear << " N (E = " << kE << " Pa)");
  CHECK(linear > 0.01 * kE);
}

TEST_CASE("nonlinear assembly: a homogeneous uniaxial stretch along a cut is in equilibrium, enriched DOFs too",
          "[nonlinear]") {
  // Stretch 1.5 along x with the lateral stretch that makes the neo-Hookean stress uniaxial: the
  // cut's faces (normal z) carry no traction, so no DOF of a node inside the body, original or
  // sign, feels a force (the others carry the traction of the faces x = 0, 1).
  const xfem::TetMesh mesh = xfem::box_mesh({4, 4, 4}, {0, 0, 0}, {1, 1, 1});
  const auto plane = std::make_shared<xfem::CutSurface>(
      xfem::cut_parallelogram({-0.2, -0.2, 0.43}, {1.2, -0.2, 0.43}, {-0.2, 1.2, 0.43}, {3, 3}));
  const xfem::EnrichedMesh cut = xfem::enriched_mesh(mesh, xfem::classify(mesh, *plane), plane);
  REQUIRE(cut.ns > 0);
  REQUIRE(cut.nb == 0);
  const xfem::BodyIntegration body = xfem::integrate_body(cut, 3);
  const xfem::Lame lame = xfem::lame(kE, kNu);
  auto lateral_stress = [&](double l) {
    xfem::StressAt s;
    REQUIRE(xfem::stress_at(law(xfem::MaterialModel::NeoHookean), Eigen::Vector3d(1.5, l, l).asDiagonal(), s));
    return s.P(1, 1);
  };
  double l = 0.9;
  for (int i = 0; i < 50; ++i) l -= lateral_stress(l) / ((lateral_stress(l + 1e-7) - lateral_stress(l - 1e-7)) / 2e-7);
  REQUIRE(std::abs(lateral_stress(l)) < 1e-9 * kE);
  const Eigen::Matrix3d F = Eigen::Vector3d(1.5, l, l).asDiagonal();
  double energy = 0.0;
  Eigen::VectorXd r;
  REQUIRE(xfem::internal_forces(cut, body, law(xfem::MaterialModel::NeoHookean), nodal(cut, [&](const V& x) { return V(F * x - x); }),
                                energy, r, nullptr));
  // Every DOF of a node inside the body: zero force. The body is [0,1]^3: its energy is Psi.
  std::vector<int> node_of(cut.n, -1);
  for (int t = 0; t < cut.tets(); ++t)
    for (long e = cut.offsets[t]; e < cut.offsets[t + 1]; ++e) node_of[cut.dofs[e]] = cut.mesh.tets(t, cut.local[e]);
  long checked_sign = 0;
  for (long k = 0; k < cut.n; ++k) {
    const V x = cut.mesh.points.row(node_of[k]).transpose();
    if ((x.array() > 1e-9).all() && (x.array() < 1 - 1e-9).all()) {
      CHECK(r.segment<3>(3 * k).norm() < 1e-9 * kE);
      checked_sign += k >= cut.np;
    }
  }
  CHECK(checked_sign >= 9);
  const double J = 1.5 * l * l;
  const double psi = lame.mu / 2 * (1.5 * 1.5 + 2 * l * l - 3) - lame.mu * std::log(J) + lame.lambda / 2 * std::pow(std::log(J), 2);
  CHECK(energy == Approx(psi).epsilon(1e-12));
}

TEST_CASE("newton: the linear model equals the linear solve; neo-Hookean converges quadratically to uniaxial stress",
          "[nonlinear]") {
  const xfem::EnrichedMesh em = partially_cut_box();
  const xfem::BodyIntegration body = xfem::integrate_body(em, 3);
  // Bottom z = 0 fixed, top z = 2 pulled up by `lift` and sideways (a linear problem needs only this).
  auto dirichlet = [&](double lift) {
    return [&em, lift](double s, std::vector<long>& fixed, std::vector<double>& values) {
      fixed.clear();
      values.clear();
      for (long k = 0; k < em.np; ++k) {
        const double z = em.mesh.points(k, 2);
        if (z > 1e-12 && z < 2 - 1e-12) continue;
        for (int i = 0; i < 3; ++i) {
          fixed.push_back(3 * k + i);
          values.push_back(z > 1 && i == 2 ? s * lift : z > 1 && i == 0 ? s * 0.1 * lift : 0.0);
        }
      }
    };
  };
  xfem::NonlinearProblem p;
  p.em = &em;
  p.body = &body;
  p.f = Eigen::VectorXd::Zero(3 * em.n);
  p.dirichlet = dirichlet(0.01);
  p.law = law(xfem::MaterialModel::Linear);
  const xfem::NewtonResult linear = xfem::solve_newton(p, {});
  // The linear path: K from the assembly, Dirichlet eliminated, CHOLMOD.
  const xfem::SparseMatrix K(xfem::stiffness_matrix(em, xfem::lame(kE, kNu), xfem::Quadrature(), nullptr, {}, 3)
                                 .selfadjointView<Eigen::Lower>());
  const xfem::ReducedSystem reduced = xfem::eliminate_dirichlet(K, p.f, linear.fixed, linear.fixed_values);
  const Eigen::VectorXd u = xfem::expand_solution(reduced, xfem::cholmod_solve(reduced.K, reduced.f).x, linear.fixed,
                                                  linear.fixed_values);
  CHECK((linear.u - u).lpNorm<Eigen::Infinity>() <= 1e-10 * u.lpNorm<Eigen::Infinity>());
  CHECK(linear.steps.size() == 1);

  // Neo-Hookean, lifted by 0.6 m (30 %) in 3 load steps: quadratic convergence in every step.
  p.law = law(xfem::MaterialModel::NeoHookean);
  p.dirichlet = dirichlet(0.6);
  xfem::NewtonOptions o;
  o.load_steps = 3;
  o.rtol = 1e-11;
  const xfem::NewtonResult big = xfem::solve_newton(p, o);
  REQUIRE(big.steps.size() == 3);
  for (const xfem::LoadStep& step : big.steps) {
    REQUIRE(step.converged);
    const auto& it = step.iterations;
    REQUIRE(it.size() >= 3);
    bool quadratic = false;  // some iteration from below 1e-2 lands below 10 x its square
    for (std::size_t k = 1; k + 1 < it.size(); ++k)
      quadratic = quadratic || (it[k].residual < 1e-2 && it[k + 1].residual < 10 * it[k].residual * it[k].residual);
    CHECK(quadratic);
    CHECK(it.size() <= 10);
  }
  CHECK(big.min_J > 0);
  CHECK(big.factorizations >= 6);
}

TEST_CASE("element forces: the projected tangent is positive semi-definite and exact where the exact one is",
          "[nonlinear]") {
  // One plain tet's single point.
  const xfem::EnrichedMesh em = xfem_test::plain(xfem::box_mesh({1, 1, 1}, {0, 0, 0}, {1, 1, 1}));
  const xfem::CutElementSplits none;
  xfem::ElementPoints points;
  xfem::element_points(em, none, 0, 3, nullptr, points);
  REQUIRE(points.size() == 1);
  const xfem::MaterialLaw m = law(xfem::MaterialModel::NeoHookean);
  xfem::ElementForces exact, projected;
  // Undeformed: the exact tangent is positive semi-definite (zero on rotations), the projection
  // changes nothing but round-off. (Strained, a rotation's second variation is the stress, of
  // either sign: the projection then differs.)
  const Eigen::VectorXd small = Eigen::VectorXd::Zero(12);
  REQUIRE(xfem::element_forces(points, m, small, true, exact));
  REQUIRE(xfem::element_forces(points, m, small, true, projected, xfem::Tangent::Projected));
  CHECK((exact.k - projected.k).cwiseAbs().maxCoeff() <= 1e-10 * exact.k.cwiseAbs().maxCoeff());
  // A strong compression (J = 0.05) makes the neo-Hookean tangent indefinite; projected, it is not.
  const Eigen::Matrix3d F = Eigen::Vector3d(0.2, 0.5, 0.5).asDiagonal();
  Eigen::VectorXd squeezed(12);
  for (int c = 0; c < 4; ++c) {
    const V x = em.mesh.points.row(em.mesh.tets(0, em.local[c])).transpose();
    squeezed.segment<3>(3 * c) = F * x - x;
  }
  REQUIRE(xfem::element_forces(points, m, squeezed, true, exact));
  REQUIRE(xfem::element_forces(points, m, squeezed, true, projected, xfem::Tangent::Projected));
  const double lowest_exact = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(exact.k).eigenvalues().minCoeff();
  const double lowest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(projected.k).eigenvalues().minCoeff();
  CHECK(lowest_exact < -1e-3 * exact.k.norm());
  CHECK(lowest > -1e-12 * projected.k.norm());
  CHECK((exact.r - projected.r).norm() == 0.0);  // the forces are the same: only the tangent is changed
}

TEST_CASE("element forces: an inverted point refuses the step unless it is next to a front (negligible volume)",
          "[nonlinear]") {
  // Two points of one plain tet's gradients: the second inverted (F = diag(0, 1, 1)).
  const xfem::EnrichedMesh em = xfem_test::plain(xfem::box_mesh({1, 1, 1}, {0, 0, 0}, {1, 1, 1}));
  xfem::ElementPoints one;
  xfem::element_points(em, xfem::CutElementSplits(), 0, 3, nullptr, one);
  xfem::ElementPoints two;
  two.gradient.resize(2, 12);
  two.gradient.row(0) = one.gradient.row(0);
  two.gradient.row(1) = -one.gradient.row(0);  // F_1 = I - (F_0 - I) = 2 I - F_0
  const double volume = one.weight[0];
  Eigen::VectorXd ue(12);
  const Eigen::Matrix3d F0 = Eigen::Vector3d(2.0, 1.0, 1.0).asDiagonal();  // F_1 = diag(0, 1, 1): J = 0
  for (int c = 0; c < 4; ++c) {
    const V x = em.mesh.points.row(em.mesh.tets(0, em.local[c])).transpose();
    ue.segment<3>(3 * c) = F0 * x - x;
  }
  xfem::ElementForces out;
  const xfem::MaterialLaw m = law(xfem::MaterialModel::NeoHookean);
  // 1e-3 of the tet's volume carries weight: the step is refused.
  two.weight = Eigen::Vector2d(volume, 1e-3 * volume);
  CHECK_FALSE(xfem::element_forces(two, m, ue, true, out));
  // Below next_to_front_weight: evaluated with the law continued below next_to_front_J.
  const double w = 1e-6 * volume;
  two.weight = Eigen::Vector2d(volume, w);
  REQUIRE(xfem::element_forces(two, m, ue, true, out));
  CHECK(out.continued == 1);
  xfem::ElementForces alone;
  REQUIRE(xfem::element_forces(one, m, ue, true, alone));
  xfem::StressAt s;
  REQUIRE(xfem::stress_at(m, Eigen::Vector3d(0.0, 1.0, 1.0).asDiagonal(), s, xfem::next_to_front_J));
  CHECK(out.energy == Approx(alone.energy + w * s.energy).epsilon(1e-12));
  CHECK(out.r.allFinite());
  CHECK(out.k.allFinite());
  CHECK(out.min_J == Approx(0.0).margin(1e-12));
  // The linear model never refuses.
  two.weight = Eigen::Vector2d(volume, 1e-3 * volume);
  CHECK(xfem::element_forces(two, law(xfem::MaterialModel::Linear), ue, true, out));
}

TEST_CASE("newton: a cut opened wide (lifted 2 m and slid 1 m at its top) converges quadratically in every step",
          "[nonlinear]") {
  // The box's cut (z = 0.93, front x = 0.55) opened by moving the top's nodes with x < 0.5 by
  // (-1, 0, 2) m, the rest of the top and the bottom held: 4 load steps, none halved, no
  // projected tangent, quadratic convergence in each. (On this coarse box no point next to the
  // front inverts, min det F 0.26; the organ's do: docs/VERIFICATION.md.)
  const xfem::EnrichedMesh em = partially_cut_box();
  const xfem::BodyIntegration body = xfem::integrate_body(em, 3);
  xfem::NonlinearProblem p;
  p.em = &em;
  p.body = &body;
  p.f = Eigen::VectorXd::Zero(3 * em.n);
  p.law = law(xfem::MaterialModel::NeoHookean);
  p.dirichlet = [&em](double s, std::vector<long>& fixed, std::vector<double>& values) {
    fixed.clear();
    values.clear();
    for (long k = 0; k < em.np; ++k) {
      const V x = em.mesh.points.row(k).transpose();
      const bool bottom = x.z() < 1e-12, top = x.z() > 2 - 1e-12, lifted = top && x.x() < 0.5;
      if (!bottom && !top) continue;
      for (int i = 0; i < 3; ++i) {
        fixed.push_back(3 * k + i);
        values.push_back(lifted && i == 2 ? s * 2.0 : lifted && i == 0 ? -s * 1.0 : 0.0);
      }
    }
  };
  xfem::NewtonOptions o;
  o.load_steps = 4;
  const xfem::NewtonResult result = xfem::solve_newton(p, o);
  REQUIRE(result.steps.size() == 4);  // no step halved
  int iterations = 0;
  for (const xfem::LoadStep& step : result.steps) {
    REQUIRE(step.converged);
    const auto& it = step.iterations;
    bool quadratic = false;
    for (std::size_t k = 1; k + 1 < it.size(); ++k)
      quadratic = quadratic || (it[k].residual < 1e-2 && it[k + 1].residual < 10 * it[k].residual * it[k].residual);
    CHECK(quadratic);
    CHECK(step.projected == 0);
    iterations += static_cast<int>(it.size()) - 1;
  }
  CHECK(iterations <= 28);
  CHECK(result.min_J > 0);
}

TEST_CASE("deformed volume at points: affine maps give det F per kind of tet, branch DOFs move only their tets",
          "[nonlinear]") {
  // [0,2] x [0,1] x [0,2] cut at z = 0.93 up to x = 1.3: sign-only tets far from the front too.
  const xfem::TetMesh mesh = xfem::box_mesh({8, 2, 4}, {0, 0, 0}, {2, 1, 2});
  const auto cut = std::make_shared<xfem::CutSurface>(
      xfem::cut_parallelogram({-0.2, -0.2, 0.93}, {1.3, -0.2, 0.93}, {-0.2, 1.2, 0.93}, {3, 3}));
  const xfem::EnrichedMesh em = xfem::enriched_mesh(mesh, xfem::classify(mesh, *cut), cut);
  const xfem::BodyIntegration body = xfem::integrate_body(em, 3);
  Eigen::Matrix3d F;
  F << 1.3, 0.2, 0.0, -0.1, 0.9, 0.15, 0.05, 0.0, 1.1;
  const Eigen::VectorXd u = nodal(em, [&](const V& X) { return V((F - Eigen::Matrix3d::Identity()) * X); });
  const xfem::PointVolume v = xfem::deformed_volume_at_points(em, body, u);
  CHECK(v.body.before == Approx(4.0).epsilon(1e-12));
  CHECK(v.body.tets == em.tets());
  CHECK(v.plain.tets + v.sign.tets + v.branch.tets == em.tets());
  CHECK(v.plain.tets > 0);
  CHECK(v.sign.tets > 0);
  CHECK(v.branch.tets > 0);
  CHECK(v.plain.before + v.sign.before + v.branch.before == Approx(v.body.before).epsilon(1e-12));
  for (const xfem::PointVolume::Part* p : {&v.body, &v.plain, &v.sign, &v.branch}) {
    CHECK(p->after == Approx(F.determinant() * p->before).epsilon(1e-12));
    CHECK(p->max_J == Approx(F.determinant()).epsilon(1e-12));
  }
  // A rotation keeps the volume.
  const Eigen::Matrix3d R = rotation(V(1, 2, 3), 70);
  const xfem::PointVolume turned =
      xfem::deformed_volume_at_points(em, body, nodal(em, [&](const V& X) { return V((R - Eigen::Matrix3d::Identity()) * X); }));
  CHECK(turned.body.after == Approx(turned.body.before).epsilon(1e-12));
  // Only the branch DOFs moved: the other tets keep their volume exactly, the branch tets' changes.
  Eigen::VectorXd w = Eigen::VectorXd::Zero(3 * em.n);
  w.tail(12 * em.nb) = random_vector(12 * em.nb, 0.02, 7);
  const xfem::PointVolume b = xfem::deformed_volume_at_points(em, body, w);
  CHECK(b.plain.after == b.plain.before);
  CHECK(b.sign.after == Approx(b.sign.before).epsilon(1e-15));
  CHECK(std::abs(b.branch.after - b.branch.before) > 1e-6 * b.branch.before);
  CHECK(b.body.max_J_tet >= 0);
  CHECK(em.branch(b.body.max_J_tet));
}
