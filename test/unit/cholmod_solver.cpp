// SPDX-License-Identifier: MIT
#include "xfem/solve/cholmod_solver.h"

#include <Eigen/SparseCholesky>
#include <catch2/catch.hpp>
#include <thread>
#include <vector>

#include "../../bench/elastic_box.h"
#include "xfem/system/dirichlet.h"

TEST_CASE("cholmod_solver: the pulled beam solves to a relative residual below 1e-10", "[cholmod_solver]") {
  const xfem::LinearSystem s = xfem::bench::beam_system({2, 4, 14});
  const xfem::ReducedSystem r = xfem::eliminate_dirichlet(s.K, s.f, s.fixed, s.fixed_values);
  for (const auto ordering : {xfem::Ordering::Metis, xfem::Ordering::Amd}) {
    const xfem::CholmodResult c = xfem::cholmod_solve(r.K, r.f, ordering);
    CHECK(c.ordering == (ordering == xfem::Ordering::Metis ? "metis" : "amd"));
    CHECK(c.factor_nonzeros > r.K.nonZeros() / 2);
    const Eigen::VectorXd u = xfem::expand_solution(r, c.x, s.fixed, s.fixed_values);
    CHECK(xfem::relative_residual(s.K, s.f, u, r) < 1e-10);
    // Against Eigen's own sparse Cholesky on the same reduced system: the same solution to
    // rounding (condition number ~1e4 for this mesh, so 1e-9 relative is generous).
    Eigen::SimplicialLDLT<xfem::SparseMatrix> ldlt(r.K);
    const Eigen::VectorXd x = ldlt.solve(r.f);
    CHECK((x - c.x).norm() <= 1e-9 * x.norm());
    // The pulled beam stretches: the far end moves up, the fixed end does not.
    CHECK(u.maxCoeff() == Approx(0.02));
  }
}

TEST_CASE("cholmod_solver: an indefinite matrix is refused naming its column", "[cholmod_solver]") {
  xfem::SparseMatrix A(3, 3);
  std::vector<Eigen::Triplet<double>> t = {{0, 0, 1}, {1, 1, 1}, {2, 2, -1}};
  A.setFromTriplets(t.begin(), t.end());
  try {
    xfem::cholmod_solve(A, Eigen::Vector3d(1, 1, 1));
    FAIL("expected NotPositiveDefinite");
  } catch (const xfem::NotPositiveDefinite& e) {
    CHECK(e.column == 2);
    CHECK_THAT(e.what(), Catch::Matchers::Contains("not positive definite"));
  }
}

TEST_CASE("cholmod_solver: a singular matrix is refused, never a NaN solution", "[cholmod_solver]") {
  // [[1, 1], [1, 1]]: the second pivot is exactly zero.
  xfem::SparseMatrix A(2, 2);
  std::vector<Eigen::Triplet<double>> t = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  A.setFromTriplets(t.begin(), t.end());
  CHECK_THROWS_AS(xfem::cholmod_solve(A, Eigen::Vector2d(1, 2)), xfem::NotPositiveDefinite);
}

TEST_CASE("cholmod_solver: one factor solved from several threads at once gives each its own answer", "[cholmod_solver]") {
  // xfem-sweep completes a step's solution with the uncut body's factor in its frame thread while
  // the next step may solve with it too: the calls share CHOLMOD's workspace and must take turns.
  const xfem::LinearSystem s = xfem::bench::beam_system({2, 3, 10});
  const xfem::ReducedSystem r = xfem::eliminate_dirichlet(s.K, s.f, s.fixed, s.fixed_values);
  const xfem::CholeskyFactor factor(r.K);
  const int threads = 4, rounds = 50;
  std::vector<Eigen::MatrixXd> rhs, expected;
  for (int i = 0; i < threads; ++i) {
    rhs.push_back(Eigen::MatrixXd::Random(factor.size(), 1 + i % 2));
    expected.push_back(factor.solve(rhs.back()));
  }
  std::vector<int> wrong(threads, 0);
  std::vector<std::thread> pool;
  for (int i = 0; i < threads; ++i)
    pool.emplace_back([&, i] {
      for (int n = 0; n < rounds; ++n) wrong[i] += factor.solve(rhs[i]) != expected[i];
    });
  for (auto& t : pool) t.join();
  for (int i = 0; i < threads; ++i) CHECK(wrong[i] == 0);
  CHECK((r.K.selfadjointView<Eigen::Lower>() * expected[0] - rhs[0]).norm() <= 1e-10 * rhs[0].norm());
}
