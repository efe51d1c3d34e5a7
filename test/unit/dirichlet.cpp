// SPDX-License-Identifier: MIT
#include "xfem/system/dirichlet.h"

#include <Eigen/Cholesky>
#include <catch2/catch.hpp>

#include "xfem/core/error.h"

namespace {

// The 3 x 3 second-difference matrix plus identity: SPD, hand-checkable.
xfem::SparseMatrix small_K() {
  xfem::SparseMatrix K(3, 3);
  std::vector<Eigen::Triplet<double>> t = {{0, 0, 3}, {1, 1, 3}, {2, 2, 3}, {0, 1, -1}, {1, 0, -1}, {1, 2, -1}, {2, 1, -1}};
  K.setFromTriplets(t.begin(), t.end());
  return K;
}

}  // namespace

TEST_CASE("dirichlet: elimination keeps K_ff and moves K_fc u_c to the right-hand side", "[dirichlet]") {
  const xfem::SparseMatrix K = small_K();
  const Eigen::Vector3d f(1, 2, 3);
  const xfem::ReducedSystem r = xfem::eliminate_dirichlet(K, f, {1}, {2.0});
  REQUIRE(r.free_dofs == std::vector<int>{0, 2});
  CHECK(r.reduced == std::vector<int>{0, -1, 1});
  // K_ff = diag(3, 3) (DOFs 0 and 2 do not couple); f_f = (1 + 2, 3 + 2) since K_01 = K_21 = -1.
  CHECK(Eigen::MatrixXd(r.K) == Eigen::Matrix2d::Identity() * 3);
  CHECK(r.f == Eigen::Vector2d(3, 5));
  const Eigen::VectorXd u = xfem::expand_solution(r, Eigen::Vector2d(1, 5.0 / 3), {1}, {2.0});
  CHECK(u == Eigen::Vector3d(1, 2, 5.0 / 3));
  // The free equations hold exactly (row 1 carries the reaction force and is not counted).
  CHECK(xfem::relative_residual(K, f, u, r) < 1e-15);
  CHECK_THROWS_WITH(xfem::eliminate_dirichlet(K, f, {0, 1, 2}, {0, 0, 0}), Catch::Matchers::Contains("every DOF"));
}

TEST_CASE("dirichlet: with no load the residual is absolute: 0 for u = 0, never 0/0", "[dirichlet]") {
  // f_f = 0 and u_c = 0: the reduced right-hand side is zero and so is the exact u_free; the
  // relative residual would be 0/0 (NaN), so the absolute one is reported.
  const xfem::SparseMatrix K = small_K();
  const Eigen::Vector3d f = Eigen::Vector3d::Zero();
  const xfem::ReducedSystem r = xfem::eliminate_dirichlet(K, f, {1}, {0.0});
  REQUIRE(r.f.squaredNorm() == 0.0);
  const Eigen::VectorXd zero = xfem::expand_solution(r, Eigen::Vector2d::Zero(), {1}, {0.0});
  CHECK(xfem::relative_residual(K, f, zero, r) == 0.0);
  // A wrong answer is measured absolutely: ||(K u)_f|| = ||(3 * 1e-3, 0)||.
  const Eigen::VectorXd off = xfem::expand_solution(r, Eigen::Vector2d(1e-3, 0), {1}, {0.0});
  CHECK(xfem::relative_residual(K, f, off, r) == Approx(3e-3).epsilon(1e-15));
}

TEST_CASE("dirichlet: a system without Dirichlet condition or with a loose piece is refused by name", "[dirichlet]") {
  using Catch::Matchers::Contains;
  xfem::LinearSystem s;
  CHECK_THROWS_WITH(xfem::require_constrained(s), Contains("no Dirichlet condition"));
  s.fixed = {0};
  s.fixed_values = {0.0};
  s.pieces = {{10, true}, {1234, false}};
  CHECK_THROWS_WITH(xfem::require_constrained(s),
                    Contains("the body falls apart into 2 pieces; piece 2 (1234 tets) has no Dirichlet condition"));
  s.pieces = {{10, true}, {4, true}};
  CHECK_NOTHROW(xfem::require_constrained(s));
}

TEST_CASE("dirichlet: DOFs are described with their kind in the paper's numbering", "[dirichlet]") {
  xfem::LinearSystem s;
  s.np = 10;
  s.ns = 2;
  s.nb = 1;
  s.n = 16;
  CHECK(xfem::describe_dof(s, 4) == "DOF 4 (vector 1, original, mesh point 1, component y)");
  CHECK(xfem::describe_dof(s, 3 * 11 + 2) == "DOF 35 (vector 11, sign-enriched vector 1 of 2, component z)");
  CHECK(xfem::describe_dof(s, 3 * 14) == "DOF 42 (vector 14, branch-enriched node 0 of 1, function F3, component x)");
}

TEST_CASE("dirichlet: tiny enriched diagonals are found against the mean original diagonal", "[dirichlet]") {
  xfem::LinearSystem s;
  s.np = 1;
  s.ns = 1;
  s.n = 2;
  s.K.resize(6, 6);
  std::vector<Eigen::Triplet<double>> t = {{0, 0, 2}, {1, 1, 4}, {2, 2, 6}, {3, 3, 1e-9}, {4, 4, 1.0}, {5, 5, 3.99e-6}};
  s.K.setFromTriplets(t.begin(), t.end());
  // Mean original diagonal 4: threshold 1e-6 * 4 catches DOFs 3 and 5 only.
  CHECK(xfem::tiny_enriched_dofs(s, 1e-6) == std::vector<long>{3, 5});
  s.fixed = {0, 4};
  s.fixed_values = {0.5, 0.25};
  xfem::fix_to_zero(s, {3, 4, 5});
  CHECK(s.fixed == std::vector<long>{0, 3, 4, 5});
  CHECK(s.fixed_values == std::vector<double>{0.5, 0.0, 0.25, 0.0});  // a prescribed value wins
}

TEST_CASE("dirichlet: enriched DOFs with an exactly zero row are fixed to 0, originals are refused", "[dirichlet]") {
  using Catch::Matchers::Contains;
  // NP = 1, NS = 1: DOFs 0..2 original, 3..5 sign-enriched. DOF 4's row holds only explicit zeros
  // (xfem-assemble keeps the pattern), DOF 5's diagonal is tiny but non-zero.
  xfem::LinearSystem s;
  s.np = 1;
  s.ns = 1;
  s.n = 2;
  s.K.resize(6, 6);
  std::vector<Eigen::Triplet<double>> t = {{0, 0, 2}, {1, 1, 4},  {2, 2, 6},    {3, 3, 1.0},
                                           {4, 4, 0}, {4, 0, 0},  {0, 4, 0},    {5, 5, 1e-12}};
  s.K.setFromTriplets(t.begin(), t.end());
  s.f = Eigen::VectorXd::Zero(6);
  s.fixed = {0};
  s.fixed_values = {0.5};
  CHECK(xfem::zero_rows(s) == std::vector<long>{4});
  CHECK(xfem::tiny_enriched_dofs(s, 1e-8) == std::vector<long>{4, 5});
  CHECK(xfem::fix_unsupported_enrichment(s) == std::vector<long>{4});
  CHECK(s.fixed == std::vector<long>{0, 4});
  CHECK(s.fixed_values == std::vector<double>{0.5, 0.0});
  // Once fixed, the zero DOF is no longer "tiny": only the tiny-but-non-zero one is left to drop.
  CHECK(xfem::tiny_enriched_dofs(s, 1e-8) == std::vector<long>{5});
  CHECK(xfem::fix_unsupported_enrichment(s).empty());

  // A free original DOF with a zero row is a broken mesh: named, never silently fixed.
  s.K.coeffRef(1, 1) = 0;
  CHECK_THROWS_WITH(xfem::fix_unsupported_enrichment(s),
                    Contains("K has an exactly zero row at DOF 1 (vector 0, original, mesh point 0, component y)"));
  // ... unless it is constrained anyway.
  s.fixed = {0, 1};
  s.fixed_values = {0.5, 0.0};
  CHECK(xfem::fix_unsupported_enrichment(s) == std::vector<long>{4});
}

TEST_CASE("dirichlet: fixing unsupported enriched DOFs leaves the rest of the solution unchanged", "[dirichlet]") {
  // K = small SPD block (DOFs 0..2) plus an enriched DOF 3 with an all-zero row: singular as is;
  // after the fix the solution on 0..2 is that of the block alone.
  xfem::LinearSystem s;
  s.np = 1;
  s.ns = 1;
  s.n = 2;
  s.K.resize(6, 6);
  std::vector<Eigen::Triplet<double>> t = {{0, 0, 3},  {1, 1, 3}, {2, 2, 3}, {0, 1, -1}, {1, 0, -1}, {1, 2, -1},
                                           {2, 1, -1}, {3, 3, 0}, {3, 0, 0}, {0, 3, 0},  {4, 4, 2},  {5, 5, 2}};
  s.K.setFromTriplets(t.begin(), t.end());
  s.f = Eigen::VectorXd::Zero(6);
  s.f << 1, 2, 3, 0, 4, 6;
  CHECK(xfem::fix_unsupported_enrichment(s) == std::vector<long>{3});
  const xfem::ReducedSystem r = xfem::eliminate_dirichlet(s.K, s.f, s.fixed, s.fixed_values);
  const Eigen::VectorXd x = Eigen::MatrixXd(r.K).ldlt().solve(r.f);
  const Eigen::VectorXd u = xfem::expand_solution(r, x, s.fixed, s.fixed_values);
  // Block solution by hand: [[3,-1,0],[-1,3,-1],[0,-1,3]] u = (1,2,3) -> u = (17/21, 10/7, 31/21).
  CHECK_THAT(u[0], Catch::Matchers::WithinAbs(17.0 / 21, 1e-14));
  CHECK_THAT(u[1], Catch::Matchers::WithinAbs(10.0 / 7, 1e-14));
  CHECK_THAT(u[2], Catch::Matchers::WithinAbs(31.0 / 21, 1e-14));
  CHECK(u[3] == 0.0);
  CHECK(u.tail<2>() == Eigen::Vector2d(2, 3));
}
