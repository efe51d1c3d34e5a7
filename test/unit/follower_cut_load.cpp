// SPDX-License-Identifier: MIT
// The pressure on a cut's faces as a follower load at large deformation (xfem-newton, issue 33).
#include <catch2/catch.hpp>
#include <cmath>

#include "enriched_test_meshes.h"
#include "xfem/system/cut_loads.h"
#include "xfem/system/follower_cut_load.h"
#include "xfem/system/problem.h"

namespace {

xfem::Problem pressure_problem(double p) {
  return xfem::parse_problem(xfem::Json::parse(R"({"material": {"E": 1e3, "nu": 0.3}, "cut_loads": [{"pressure": )" +
                                               std::to_string(p) + "}]}"),
                             "p.json");
}

// A smooth, moderately large displacement of every DOF (the original ones and the sign ones).
Eigen::VectorXd wavy(const xfem::EnrichedMesh& em) {
  Eigen::VectorXd u(3 * em.n);
  for (long i = 0; i < u.size(); ++i) u[i] = 0.08 * std::sin(1.7 * static_cast<double>(i) + 0.3);
  return u;
}

}  // namespace

TEST_CASE("follower cut load: at u = 0 it is the linear path's pressure load", "[follower_cut_load]") {
  const xfem::EnrichedMesh em = xfem_test::cut_box(0.3);
  const xfem::Problem problem = pressure_problem(2.5);
  const xfem::FollowerCutLoad load = xfem::follower_cut_load(em, problem);
  REQUIRE(!load.empty());
  CHECK(load.area == Approx(1.0).epsilon(1e-12));  // the plane z = 0.3 across the unit box
  Eigen::VectorXd linear = Eigen::VectorXd::Zero(3 * em.n), follower = Eigen::VectorXd::Zero(3 * em.n);
  xfem::add_cut_loads(em, problem, linear);
  xfem::add_follower_forces(em, load, Eigen::VectorXd::Zero(3 * em.n), 1.0, follower, nullptr);
  REQUIRE(linear.norm() > 1.0);
  CHECK((follower - linear).cwiseAbs().maxCoeff() <= 1e-14 * linear.cwiseAbs().maxCoeff());
  // The tractions stay dead: add_dead_cut_tractions adds nothing for a pressure alone.
  Eigen::VectorXd dead = Eigen::VectorXd::Zero(3 * em.n);
  xfem::add_dead_cut_tractions(em, problem, dead);
  CHECK(dead.norm() == 0.0);
}

TEST_CASE("follower cut load: a homogeneous deformation gives p cof(F) n times the area", "[follower_cut_load]") {
  const xfem::EnrichedMesh em = xfem_test::cut_box(0.3);
  const double p = 3.0;
  const xfem::FollowerCutLoad load = xfem::follower_cut_load(em, pressure_problem(p));
  Eigen::Matrix3d F;
  F << 1.1, 0.2, -0.1, 0.05, 0.9, 0.3, 0.0, -0.15, 1.2;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * em.n);  // sign DOFs 0: no jump, F on both faces
  for (long k = 0; k < em.np; ++k)
    u.segment<3>(3 * k) = (F - Eigen::Matrix3d::Identity()) * em.mesh.points.row(k).transpose();
  const Eigen::Vector3d expected = p * F.determinant() * F.inverse().transpose() * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d above = xfem::follower_face_force(load, em, u);
  CHECK((above - expected).norm() <= 1e-13 * expected.norm());
  // Equal and opposite on the two faces when they deform alike: no net force on the body.
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * em.n);
  xfem::add_follower_forces(em, load, u, 1.0, f, nullptr);
  Eigen::Vector3d net = Eigen::Vector3d::Zero();
  for (long k = 0; k < em.n; ++k)
    if (k < em.np) net += f.segment<3>(3 * k);
  CHECK(net.norm() <= 1e-13 * expected.norm());
}

TEST_CASE("follower cut load: its stiffness is the symmetric part of -df/du (central differences)",
          "[follower_cut_load]") {
  const xfem::EnrichedMesh em = xfem_test::cut_box(0.3);
  const double s = 0.7;
  const xfem::FollowerCutLoad load = xfem::follower_cut_load(em, pressure_problem(4.0));
  const Eigen::VectorXd u = wavy(em);
  const long n = 3 * em.n;
  std::vector<Eigen::Triplet<double, int>> triplets;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  xfem::add_follower_forces(em, load, u, s, f, &triplets);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (const auto& t : triplets) K(t.row(), t.col()) += t.value();
  // -df/du by central differences (f is quadratic in u: exact up to round-off).
  Eigen::MatrixXd D(n, n);
  const double h = 1e-5;
  for (long j = 0; j < n; ++j) {
    Eigen::VectorXd up = u, down = u, fp = Eigen::VectorXd::Zero(n), fm = Eigen::VectorXd::Zero(n);
    up[j] += h;
    down[j] -= h;
    xfem::add_follower_forces(em, load, up, s, fp, nullptr);
    xfem::add_follower_forces(em, load, down, s, fm, nullptr);
    D.col(j) = -(fp - fm) / (2 * h);
  }
  const Eigen::MatrixXd sym = 0.5 * (D + D.transpose());
  const double size = sym.cwiseAbs().maxCoeff();
  REQUIRE(size > 0.1);
  CHECK((K - sym).cwiseAbs().maxCoeff() <= 1e-8 * size);
  CHECK((K - K.transpose()).cwiseAbs().maxCoeff() <= 1e-14 * size);
  // The exact derivative is not symmetric: a follower load on an open face is not conservative.
  CHECK((D - D.transpose()).cwiseAbs().maxCoeff() > 1e-3 * size);
}
