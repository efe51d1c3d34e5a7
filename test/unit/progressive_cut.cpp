// SPDX-License-Identifier: MIT
// Progressive cutting: the standard block does not change with the cut, and the block elimination
// on the enriched DOFs gives the whole system's solution.
#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "xfem/assembly.h"
#include "xfem/box_mesh.h"
#include "xfem/cholmod_solver.h"
#include "xfem/cut_generation.h"
#include "xfem/cut_sweep.h"
#include "xfem/cut_surface.h"
#include "xfem/dirichlet.h"
#include "xfem/error.h"
#include "xfem/paraview_collection.h"
#include "xfem/progressive_cut.h"
#include "xfem/schur_solver.h"

namespace {

xfem::TetMesh box() { return xfem::box_mesh({3, 3, 6}, {0, 0, 0}, {1, 1, 2}); }

// A plane z = 0.93 entering the box from x < 0 and ending at x = `front` (inside: partially cut
// tets and branch nodes), reaching out of the box in y.
std::shared_ptr<xfem::CutSurface> partial_cut(double front) {
  return std::make_shared<xfem::CutSurface>(
      xfem::cut_parallelogram({-0.2, -0.2, 0.93}, {front, -0.2, 0.93}, {-0.2, 1.2, 0.93}, {3, 3}));
}

xfem::Problem problem() {
  return xfem::parse_problem(xfem::Json::parse(R"({
    "material": {"E": 1e3, "nu": 0.3},
    "dirichlet": [{"name": "bottom", "selector": {"box": {"lo": [-1, -1, -1], "hi": [2, 2, 0]}}, "value": [0, 0, 0]},
                  {"name": "lid", "selector": {"box": {"lo": [-1, -1, 2], "hi": [2, 2, 3]}}, "value": [0, 0.01, 0.05]}],
    "neumann": [{"name": "side", "selector": {"box": {"lo": [1, -1, -1], "hi": [2, 2, 3]}}, "traction": [-3, 0, 1]}],
    "body_force": [0, 0, -10]
  })"), "p.json");
}

// The system of `em` as the tools make it, Dirichlet DOFs eliminated.
xfem::ReducedSystem reduced(const xfem::EnrichedMesh& em, xfem::LinearSystem& s) {
  const xfem::Problem p = problem();
  s = xfem::assemble_system(em, p, p.points, p.refine);
  const xfem::SparseMatrix K = xfem::SparseMatrix(s.K.selfadjointView<Eigen::Lower>());
  return xfem::eliminate_dirichlet(K, s.f, s.fixed, s.fixed_values);
}

}  // namespace

TEST_CASE("progressive cut: the original-original block of K, f and the Dirichlet data do not depend on the cut",
          "[progressive_cut]") {
  const xfem::TetMesh mesh = box();
  const auto cut = partial_cut(0.55);
  const xfem::EnrichedMesh uncut = xfem::enriched_mesh(mesh, xfem::classify_without_cut(mesh), nullptr);
  const xfem::EnrichedMesh em = xfem::enriched_mesh(mesh, xfem::classify(mesh, *cut), cut);
  REQUIRE(em.ns > 0);
  REQUIRE(em.nb > 0);  // a front inside: branch enrichment and blending tets too
  xfem::LinearSystem s0, s1;
  const xfem::ReducedSystem r0 = reduced(uncut, s0), r1 = reduced(em, s1);
  CHECK(s0.fixed == s1.fixed);
  CHECK(s0.fixed_values == s1.fixed_values);
  CHECK((s1.f.head(3 * em.np) - s0.f).norm() == 0.0);
  CHECK(s1.f.tail(3 * (em.n - em.np)).norm() == 0.0);
  // The reduced systems list the free original DOFs first, in the same order.
  const long nf = static_cast<long>(r0.free_dofs.size());
  for (long i = 0; i < nf; ++i) REQUIRE(r1.free_dofs[i] == r0.free_dofs[i]);
  const Eigen::MatrixXd A0 = Eigen::MatrixXd(r0.K), A1 = Eigen::MatrixXd(r1.K).topLeftCorner(nf, nf);
  const double scale = A0.cwiseAbs().maxCoeff();
  INFO("max |K_ss(cut) - K_ss(uncut)| / max |K_ss| = " << (A1 - A0).cwiseAbs().maxCoeff() / scale);
  CHECK((A1 - A0).cwiseAbs().maxCoeff() <= 1e-14 * scale);
  CHECK((r1.f.head(nf) - r0.f).norm() <= 1e-14 * r0.f.norm());
  // ... while the enriched block is not empty: the cut does change K, elsewhere.
  CHECK(Eigen::MatrixXd(r1.K).bottomRightCorner(r1.K.rows() - nf, r1.K.rows() - nf).norm() > 0);
}

TEST_CASE("progressive cut: the block elimination on the enriched DOFs equals the whole system's solution",
          "[progressive_cut]") {
  const xfem::TetMesh mesh = box();
  const xfem::UncutBody body = xfem::factorize_uncut(mesh, problem());
  for (double front : {-0.1, 0.3, 0.55, 1.2}) {  // no tet cut, partial cuts, a cut through
    INFO("front at x = " << front);
    const auto cut = partial_cut(front);
    const xfem::CutSolution step = xfem::solve_cut(body, cut, {}, xfem::CutSolver::Schur);
    const xfem::CutSolution again = xfem::solve_cut(body, cut, {}, xfem::CutSolver::Refactor);
    CHECK(step.schur_used);
    CHECK(!again.schur_used);
    // The whole system as xfem-assemble and xfem-solve make it.
    xfem::LinearSystem s;
    const xfem::EnrichedMesh em = xfem::enriched_mesh(mesh, xfem::classify(mesh, *cut), cut);
    const xfem::Problem p = problem();
    s = xfem::assemble_system(em, p, p.points, p.refine);
    s.K = xfem::SparseMatrix(s.K.selfadjointView<Eigen::Lower>());
    const auto unsupported = xfem::fix_unsupported_enrichment(s);
    CHECK(step.unsupported_dofs == static_cast<long>(unsupported.size()));
    const xfem::ReducedSystem r = xfem::eliminate_dirichlet(s.K, s.f, s.fixed, s.fixed_values);
    const Eigen::VectorXd u = xfem::expand_solution(r, xfem::cholmod_solve(r.K, r.f).x, s.fixed, s.fixed_values);
    REQUIRE(step.u.size() == u.size());
    CHECK(step.enriched_dofs == 3 * (em.n - em.np) - static_cast<long>(unsupported.size()));
    CHECK((step.u - u).norm() <= 1e-10 * u.norm());
    CHECK((again.u - u).norm() <= 1e-10 * u.norm());
    if (front > 0) CHECK(step.enriched_dofs > 0);
  }
}

TEST_CASE("progressive cut: exact Dirichlet fields and unconstrained pieces are refused", "[progressive_cut]") {
  const xfem::TetMesh mesh = box();
  xfem::Problem p = problem();
  p.dirichlet[1].exact = xfem::parse_exact_field(xfem::Json::parse(R"({"rigid": {"above": {"translation": [0, 0, 1]}}})"),
                                                 "p.json", "dirichlet[1].exact");
  CHECK_THROWS_WITH(xfem::factorize_uncut(mesh, p),
                    Catch::Contains("p.json: dirichlet[1] ('lid') prescribes an exact field"));
  p = problem();
  p.dirichlet.pop_back();  // only the bottom is held: a cut through the box frees the top
  const xfem::UncutBody body = xfem::factorize_uncut(mesh, p);
  CHECK_THROWS_WITH(xfem::solve_cut(body, partial_cut(1.2)), Catch::Contains("has no Dirichlet condition"));
  CHECK_THROWS_WITH(xfem::solve_cut(body, partial_cut(1.2), {}, xfem::CutSolver::Refactor),
                    Catch::Contains("has no Dirichlet condition"));
}

TEST_CASE("schur solve: the block elimination solves the block system", "[progressive_cut]") {
  // A = tridiagonal SPD (n = 9), K_ee 3 x 3, coupling in a few places.
  const int n = 9, m = 3;
  std::vector<Eigen::Triplet<double, int>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 4.0);
    if (i + 1 < n) t.emplace_back(i + 1, i, -1.0), t.emplace_back(i, i + 1, -1.0);
  }
  xfem::SparseMatrix A(n, n), K_se(n, m), K_ee(m, m);
  A.setFromTriplets(t.begin(), t.end());
  K_se.insert(0, 0) = 0.5;
  K_se.insert(4, 1) = -0.7;
  K_se.insert(5, 1) = 0.2;
  K_se.insert(8, 2) = 0.3;
  K_ee.insert(0, 0) = 3;
  K_ee.insert(1, 1) = 2;
  K_ee.insert(2, 2) = 5;
  K_ee.insert(2, 0) = 1;  // lower triangle only
  Eigen::VectorXd g(n + m);
  for (int i = 0; i < n + m; ++i) g[i] = 1.0 + 0.1 * i;
  const xfem::CholeskyFactor factor(A);
  const Eigen::VectorXd w = factor.solve(g.head(n)).col(0);
  const Eigen::VectorXd u = xfem::schur_solve(factor, w, K_se, K_ee, g.tail(m), nullptr, 2);  // 2 blocks
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + m, n + m);
  K.topLeftCorner(n, n) = Eigen::MatrixXd(A);
  K.topRightCorner(n, m) = Eigen::MatrixXd(K_se);
  K.bottomLeftCorner(m, n) = Eigen::MatrixXd(K_se).transpose();
  K.bottomRightCorner(m, m) = Eigen::MatrixXd(K_ee).selfadjointView<Eigen::Lower>();
  CHECK((K * u - g).norm() <= 1e-13 * g.norm());
  K_ee.coeffRef(1, 1) = -2;  // S not positive definite
  CHECK_THROWS_WITH(xfem::schur_solve(factor, w, K_se, K_ee, g.tail(m)), Catch::Contains("not positive definite"));
}

TEST_CASE("cut sweep: times, the cut at a time, step times", "[cut_sweep]") {
  xfem::BladePath path;
  path.polyline = {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}};
  const xfem::TriangleMesh s = xfem::cut_sweep(path, 0.5, {0, 0, -1}, 0, 0.25, 2.0);
  CHECK(s.triangles.rows() == 2 * 8 * 2);  // 4 + 4 samples along, 2 across
  const std::vector<double> times = xfem::cut_times(s, "s.vtp");
  CHECK(times.front() == Approx(0.25));
  CHECK(times.back() == Approx(2.0));
  // Normals: tangent x blade; the first leg runs along +x with the blade along -z: normal +y.
  const Eigen::Vector3d a = s.points.row(s.triangles(0, 0)), b = s.points.row(s.triangles(0, 1)),
                        c = s.points.row(s.triangles(0, 2));
  CHECK((b - a).cross(c - a).normalized().isApprox(Eigen::Vector3d(0, 1, 0)));
  const xfem::TriangleMesh half = xfem::cut_until(s, times, 1.0);
  CHECK(half.triangles.rows() == 16);
  CHECK(half.points.rows() == 5 * 3);
  CHECK(half.cell_data.at("time").values.size() == 16);
  CHECK(half.points.col(0).maxCoeff() == Approx(1.0));
  CHECK(half.points.col(1).maxCoeff() == Approx(0.0));
  CHECK(xfem::cut_until(s, times, 0.1).triangles.rows() == 0);
  const auto t = xfem::step_times(times, 4);
  REQUIRE(t.size() == 4);
  CHECK(t[0] == Approx(0.25 + 1.75 / 4));
  CHECK(t[3] == 2.0);
  CHECK_THROWS_WITH(xfem::step_times(times, 0), "the number of steps must be at least 1, got 0");
  xfem::TriangleMesh no_time = s;
  no_time.cell_data.clear();
  CHECK_THROWS_WITH(xfem::cut_times(no_time, "c.vtp"), Catch::StartsWith("c.vtp: no cell array 'time'"));
  no_time.cell_data["time"] = s.cell_data.at("time");
  no_time.cell_data["time"].values[3] = std::nan("");
  CHECK_THROWS_WITH(xfem::cut_times(no_time, "c.vtp"), "c.vtp: cell array 'time' of triangle 3 is not a finite number");
  // An arc: a quarter circle of radius 1 about +z, blade tilted by 90 degrees (pointing outward or inward, horizontal).
  xfem::BladePath arc;
  arc.radius = 1;
  arc.a0 = 0;
  arc.a1 = 90;
  const xfem::TriangleMesh q = xfem::cut_sweep(arc, 0.2, {0, 0, -1}, 0, 0.1, 1.0);
  CHECK(q.points.col(2).minCoeff() == Approx(-0.2));
  CHECK(q.points.rowwise().norm().maxCoeff() <= 1.0 + 0.2 + 1e-12);
  CHECK_THROWS_WITH(xfem::cut_sweep(path, 0.5, {1, 0, 0}, 0, 0.25, 1), Catch::Contains("the blade points along the path"));
  CHECK_THROWS_WITH(xfem::cut_sweep(path, -1, {0, 0, -1}, 0, 0.25, 1), "the blade's depth must be positive");
}

TEST_CASE("paraview collection: one DataSet per entry with its time and part", "[cut_sweep]") {
  const std::string path = "collection_test.pvd";
  xfem::write_paraview_collection({{0.5, 0, "step_001.vtu"}, {0.5, 1, "a&b.vtp"}, {1.0, 0, "step_002.vtu"}}, path);
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text.find("<VTKFile type=\"Collection\"") != std::string::npos);
  CHECK(text.find("<DataSet timestep=\"0.5\" part=\"0\" file=\"step_001.vtu\"/>") != std::string::npos);
  CHECK(text.find("<DataSet timestep=\"0.5\" part=\"1\" file=\"a&amp;b.vtp\"/>") != std::string::npos);
  CHECK(text.find("<DataSet timestep=\"1\" part=\"0\" file=\"step_002.vtu\"/>") != std::string::npos);
  std::remove(path.c_str());
}
