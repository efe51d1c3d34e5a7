// SPDX-License-Identifier: MIT
#include "xfem/system/assembly.h"

#include <Eigen/SparseCholesky>
#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>
#include <memory>
#include <random>

#include "xfem/generate/box_mesh.h"
#include "xfem/core/error.h"
#include "enriched_test_meshes.h"

namespace {

using xfem_test::plain;

// The unit box of 1 x 1 x 2 cubes completely cut by the plane z = 0.3 (normal +z) reaching out
// of the box: the 6 tets of the lower cube are completely cut, its 8 nodes sign enriched.
xfem::EnrichedMesh cut_box() { return xfem_test::cut_box(0.3); }

Eigen::MatrixXd dense_full(const xfem::SparseMatrix& lower) {
  const Eigen::MatrixXd L = Eigen::MatrixXd(lower);
  Eigen::MatrixXd K = L + L.transpose();
  K.diagonal() = L.diagonal();
  return K;
}

// Solves K u = 0 with u prescribed on the boundary nodes as the linear field A x + c, returns the
// largest error over the interior nodes relative to the field's largest value.
double patch_test(const xfem::TetMesh& mesh) {
  const xfem::EnrichedMesh em = plain(mesh);
  const xfem::SparseMatrix lower = xfem::stiffness_matrix(em, xfem::lame(300e3, 0.35), xfem::oversampling_quadrature(30));
  const xfem::SparseMatrix K = lower.selfadjointView<Eigen::Lower>();
  Eigen::Matrix3d A;
  A << 0.01, -0.02, 0.005, 0.003, 0.02, -0.01, -0.004, 0.007, 0.015;
  const Eigen::Vector3d c(0.001, -0.002, 0.003);
  const Eigen::Vector3d lo = mesh.points.colwise().minCoeff(), hi = mesh.points.colwise().maxCoeff();
  const long n = 3 * em.n;
  Eigen::VectorXd exact(n);
  std::vector<int> reduced(n, -1), free;
  for (long k = 0; k < em.n; ++k) {
    const Eigen::Vector3d x = mesh.points.row(k).transpose();
    exact.segment<3>(3 * k) = A * x + c;
    const bool boundary = ((x - lo).cwiseAbs().minCoeff() < 1e-12) || ((x - hi).cwiseAbs().minCoeff() < 1e-12);
    if (!boundary)
      for (int i = 0; i < 3; ++i) {
        reduced[3 * k + i] = static_cast<int>(free.size());
        free.push_back(static_cast<int>(3 * k + i));
      }
  }
  REQUIRE(!free.empty());
  // K_ff u_f = -K_fc u_c.
  std::vector<Eigen::Triplet<double>> kff;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(free.size()));
  for (int j = 0; j < K.outerSize(); ++j)
    for (xfem::SparseMatrix::InnerIterator it(K, j); it; ++it) {
      const int r = reduced[it.row()];
      if (r < 0) continue;
      if (reduced[j] >= 0) kff.emplace_back(r, reduced[j], it.value());
      else rhs[r] -= it.value() * exact[j];
    }
  xfem::SparseMatrix Kff(static_cast<int>(free.size()), static_cast<int>(free.size()));
  Kff.setFromTriplets(kff.begin(), kff.end());
  const Eigen::SimplicialLDLT<xfem::SparseMatrix> ldlt(Kff);
  REQUIRE(ldlt.info() == Eigen::Success);
  const Eigen::VectorXd u = ldlt.solve(rhs);
  double error = 0;
  for (std::size_t r = 0; r < free.size(); ++r) error = std::max(error, std::abs(u[r] - exact[free[r]]));
  return error / exact.cwiseAbs().maxCoeff();
}

}  // namespace

TEST_CASE("assembly: patch test, a linear field imposed on the boundary is reproduced inside", "[assembly]") {
  SECTION("structured box mesh") {
    CHECK(patch_test(xfem::box_mesh({3, 4, 5}, {0, 0, 0}, {0.03, 0.06, 0.2})) < 1e-10);
  }
  SECTION("unstructured: interior nodes of a box mesh jittered by up to 30% of a cell") {
    xfem::TetMesh m = xfem::box_mesh({4, 4, 5}, {0, 0, 0}, {0.03, 0.06, 0.2});
    const Eigen::Vector3d h(0.03 / 4, 0.06 / 4, 0.2 / 5);
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    const Eigen::Vector3d lo(0, 0, 0), hi(0.03, 0.06, 0.2);
    for (int k = 0; k < m.points.rows(); ++k) {
      const Eigen::Vector3d x = m.points.row(k).transpose();
      if ((x - lo).cwiseAbs().minCoeff() < 1e-12 || (x - hi).cwiseAbs().minCoeff() < 1e-12) continue;
      for (int d = 0; d < 3; ++d) m.points(k, d) += jitter(rng) * h[d];
    }
    for (int t = 0; t < m.tets.rows(); ++t) REQUIRE(xfem::signed_volume(m, t) > 0);
    CHECK(patch_test(m) < 1e-10);
  }
}

TEST_CASE("assembly: K of an uncut mesh is symmetric PSD with exactly 6 zero eigenvalues", "[assembly]") {
  const xfem::EnrichedMesh em = plain(xfem::box_mesh({1, 2, 2}, {0, 0, 0}, {0.03, 0.06, 0.2}));
  const xfem::SparseMatrix K = xfem::stiffness_matrix(em, xfem::lame(300e3, 0.35), xfem::oversampling_quadrature(30));
  // Only the lower triangle is stored.
  for (int j = 0; j < K.outerSize(); ++j)
    for (xfem::SparseMatrix::InnerIterator it(K, j); it; ++it) CHECK(it.row() >= j);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(dense_full(K));
  const Eigen::VectorXd ev = eig.eigenvalues();
  const double tol = 1e-10 * ev.maxCoeff();  // rounding of a 54 x 54 matrix of size ~1e7
  CHECK(ev.minCoeff() > -tol);
  CHECK((ev.array().abs() < tol).count() == 6);
}

TEST_CASE("assembly: K of a completely cut mesh has 12 zero eigenvalues (two free rigid pieces)", "[assembly]") {
  const xfem::EnrichedMesh em = cut_box();
  REQUIRE(em.ns == 8);
  const xfem::SparseMatrix K = xfem::stiffness_matrix(em, xfem::lame(300e3, 0.35), xfem::oversampling_quadrature(30));
  REQUIRE(K.rows() == 3 * 20);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(dense_full(K));
  const Eigen::VectorXd ev = eig.eigenvalues();
  const double tol = 1e-10 * ev.maxCoeff();
  CAPTURE(ev.head(14).transpose());
  CHECK(ev.minCoeff() > -tol);
  CHECK((ev.array().abs() < tol).count() == 12);
}

TEST_CASE("assembly: a sign DOF without volume on the far side of the cut has a zero row, and is found",
          "[assembly]") {
  xfem::EnrichedMesh em = cut_box();
  xfem::SparseMatrix K = xfem::stiffness_matrix(em, xfem::lame(1e3, 0.3), xfem::oversampling_quadrature(30));
  CHECK(xfem::unsupported_dofs(K, em.np).empty());
  // Move the box up until its bottom face lies on the cut z = 0.3 (points on the cut count as
  // above): nothing of the box lies below it, so every sign function vanishes identically.
  em.mesh.points.col(2).array() += 0.3;
  for (int k = 0; k < em.mesh.points.rows(); ++k) em.side[k] = 1;
  K = xfem::stiffness_matrix(em, xfem::lame(1e3, 0.3), xfem::oversampling_quadrature(30));
  CHECK(xfem::unsupported_dofs(K, em.np).size() == 8);
}

TEST_CASE("assembly: direct scatter into the precomputed pattern equals a triplet assembly", "[assembly]") {
  const xfem::EnrichedMesh em = cut_box();
  const xfem::Lame material = xfem::lame(300e3, 0.35);
  const xfem::Quadrature rule = xfem::oversampling_quadrature(30);
  const xfem::SparseMatrix K = xfem::stiffness_matrix(em, material, rule);
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd k;
  for (int t = 0; t < em.tets(); ++t) {
    xfem::element_stiffness(em, t, rule, material, k);
    for (int a = 0; a < em.size(t); ++a)
      for (int b = 0; b < em.size(t); ++b)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            entries.emplace_back(static_cast<int>(3 * em.dofs[em.offsets[t] + a] + i),
                                 static_cast<int>(3 * em.dofs[em.offsets[t] + b] + j), k(3 * a + i, 3 * b + j));
  }
  xfem::SparseMatrix ref(K.rows(), K.cols());
  ref.setFromTriplets(entries.begin(), entries.end());
  const Eigen::MatrixXd diff = dense_full(K) - Eigen::MatrixXd(ref);
  CHECK(diff.cwiseAbs().maxCoeff() <= 1e-12 * K.coeffs().cwiseAbs().maxCoeff());
}

TEST_CASE("assembly: loads act on original DOFs and add up to the applied totals", "[assembly]") {
  const xfem::EnrichedMesh em = cut_box();
  xfem::Problem p = xfem::parse_problem(xfem::Json::parse(R"({
    "material": {"E": 1e3, "nu": 0.3},
    "neumann": [{"name": "top", "selector": {"box": {"lo": [0, 0, 1], "hi": [1, 1, 1]}}, "traction": [1, 2, 3]}],
    "body_force": [0, 0, -10]
  })"), "p.json");
  const Eigen::VectorXd f = xfem::load_vector(em, p);
  REQUIRE(f.size() == 3 * em.n);
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (long k = 0; k < em.n; ++k) total += f.segment<3>(3 * k);
  // Top face area 1, volume 1.
  CHECK((total - Eigen::Vector3d(1, 2, 3 - 10)).norm() < 1e-12);
  CHECK(f.tail(3 * em.ns).norm() == 0.0);
  p.neumann[0].selector.lo.z() = 0.5;  // the box now holds the midplane nodes too, but no new boundary face
  p.neumann[0].selector.hi = Eigen::Vector3d(1, 1, 0.5);
  CHECK_THROWS_WITH(xfem::load_vector(em, p),
                    "p.json: neumann[0] ('top') selects no boundary face (all three nodes of a face must be selected)");
}

TEST_CASE("assembly: Dirichlet data on original DOFs, free components left out, conflicts named", "[assembly]") {
  const xfem::EnrichedMesh em = cut_box();
  xfem::Json j = xfem::Json::parse(R"({
    "material": {"E": 1e3, "nu": 0.3},
    "dirichlet": [
      {"name": "base", "selector": {"box": {"lo": [0, 0, 0], "hi": [1, 1, 0]}}, "value": [0, 0, 0]},
      {"name": "lift", "selector": {"box": {"lo": [0, 0, 1], "hi": [0, 1, 1]}}, "value": [null, 0.5, null]}
    ]
  })");
  std::vector<long> fixed;
  std::vector<double> values;
  xfem::dirichlet_data(em, xfem::parse_problem(j, "p.json"), fixed, values);
  REQUIRE(fixed.size() == 4 * 3 + 2);
  CHECK(std::is_sorted(fixed.begin(), fixed.end()));
  for (long dof : fixed) CHECK(dof < 3 * em.np);
  // Nodes 8 and 10 are (0, 0, 1) and (0, 1, 1): only their y component is fixed.
  CHECK(fixed.back() == 3 * 10 + 1);
  CHECK(values.back() == 0.5);
  j["dirichlet"][1]["selector"]["box"]["lo"] = {0, 0, 0};
  j["dirichlet"][1]["selector"]["box"]["hi"] = {0, 0, 0};
  CHECK_THROWS_WITH(xfem::dirichlet_data(em, xfem::parse_problem(j, "p.json"), fixed, values),
                    "p.json: dirichlet[1] ('lift') and dirichlet[0] ('base') prescribe different values for node 0 "
                    "component y");
  j["dirichlet"][1]["selector"]["box"]["lo"] = {5, 5, 5};
  j["dirichlet"][1]["selector"]["box"]["hi"] = {6, 6, 6};
  CHECK_THROWS_WITH(xfem::dirichlet_data(em, xfem::parse_problem(j, "p.json"), fixed, values),
                    "p.json: dirichlet[1] ('lift') selects no node");
}

TEST_CASE("assembly: the whole system of a cut box", "[assembly]") {
  const xfem::EnrichedMesh em = cut_box();
  const xfem::Problem p = xfem::parse_problem(xfem::Json::parse(R"({
    "material": {"E": 1e3, "nu": 0.3},
    "dirichlet": [{"selector": {"box": {"lo": [0, 0, 0], "hi": [1, 1, 0]}}, "value": [0, 0, 0]}]
  })"), "p.json");
  xfem::AssemblyStats stats;
  const xfem::LinearSystem sys = xfem::assemble_system(em, p, 30, 0, &stats);
  CHECK(sys.n == 20);
  CHECK(sys.ns == 8);
  CHECK(sys.K.rows() == 60);
  CHECK(sys.f.size() == 60);
  CHECK(sys.fixed.size() == 12);
  CHECK(stats.enriched_tets == 6);
  CHECK(stats.standard_tets == 6);
  // Fixed at z = 0, the part above z = 0.3 is free: two pieces, the second unconstrained.
  REQUIRE(sys.pieces.size() == 2);
  CHECK(sys.pieces[0].constrained != sys.pieces[1].constrained);
  CHECK(sys.coordinates.rows() == 12);
}

TEST_CASE("assembly: throughput on the reference beam of 466560 tets", "[assembly][.slow]") {
  const xfem::EnrichedMesh em = plain(xfem::box_mesh({18, 36, 120}, {0, 0, 0}, {0.03, 0.06, 0.2}));
  const xfem::Lame material = xfem::lame(300e3, 0.35);
  xfem::AssemblyStats s;
  const auto t0 = std::chrono::steady_clock::now();
  const xfem::SparseMatrix K = xfem::stiffness_matrix(em, material, xfem::oversampling_quadrature(30), &s);
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Baseline: the same element matrices through triplets and setFromTriplets.
  const auto t1 = std::chrono::steady_clock::now();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(em.tets()) * 78);
  for (int t = 0; t < em.tets(); ++t) {
    const auto k = xfem::tet_stiffness(xfem::tet_shape(em.mesh, t), material);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            const int r = 3 * em.mesh.tets(t, a) + i, c = 3 * em.mesh.tets(t, b) + j;
            if (r >= c) entries.emplace_back(r, c, k(3 * a + i, 3 * b + j));
          }
  }
  xfem::SparseMatrix ref(K.rows(), K.cols());
  ref.setFromTriplets(entries.begin(), entries.end());
  const double baseline = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  const auto t2 = std::chrono::steady_clock::now();
  const std::string path = "assembly_benchmark_K.mtx";
  xfem::write_symmetric_matrix(K, path);
  const double write = std::chrono::duration<double>(std::chrono::steady_clock::now() - t2).count();
  std::remove(path.c_str());
  char line[400];
  std::snprintf(line, sizeof line,
                "tets %d, nnz(lower) %ld: pattern %.3f s, numeric %.3f s (%.2f M tets/s), total %.3f s "
                "(%.2f M tets/s); triplets baseline %.3f s (%.2f M tets/s); write K.mtx %.3f s",
                em.tets(), static_cast<long>(K.nonZeros()), s.pattern_seconds, s.standard_seconds,
                em.tets() / s.standard_seconds / 1e6, total, em.tets() / total / 1e6, baseline,
                em.tets() / baseline / 1e6, write);
  WARN(line);
  CHECK((Eigen::MatrixXd::Zero(1, 1)).size() == 1);
  const xfem::SparseMatrix diff = K - ref;
  CHECK(diff.coeffs().cwiseAbs().maxCoeff() <= 1e-9 * K.coeffs().cwiseAbs().maxCoeff());
}
