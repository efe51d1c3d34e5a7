// SPDX-License-Identifier: MIT
// Progressive cutting: the standard block does not change with the cut, and the block elimination
// on the enriched DOFs gives the whole system's solution.
#include <catch2/catch.hpp>
#include <tuple>
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <memory>
#include <random>
#include <string>

#include "xfem/system/assembly.h"
#include "xfem/generate/box_mesh.h"
#include "xfem/solve/cholmod_solver.h"
#include "xfem/generate/cut_generation.h"
#include "xfem/generate/cut_sweep.h"
#include "xfem/geometry/cut_surface.h"
#include "xfem/system/dirichlet.h"
#include "xfem/core/error.h"
#include "xfem/core/regions.h"
#include "xfem/enrich/classification.h"
#include "xfem/solve/incremental_schur.h"
#include "xfem/io/paraview_collection.h"
#include "xfem/progressive/box_grid.h"
#include "xfem/progressive/progressive_cut.h"
#include "xfem/solve/schur_solver.h"
#include "enriched_test_meshes.h"

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

// The whole system's solution of `em` under `p`, as xfem-assemble and xfem-solve give it (the
// reference each sweep step must equal).
Eigen::VectorXd whole_system_solution(const xfem::EnrichedMesh& em, const xfem::Problem& p) {
  xfem::LinearSystem s = xfem::assemble_system(em, p, p.points, p.refine);
  s.K = xfem::SparseMatrix(s.K.selfadjointView<Eigen::Lower>());
  xfem::fix_unsupported_enrichment(s);
  const xfem::ReducedSystem r = xfem::eliminate_dirichlet(s.K, s.f, s.fixed, s.fixed_values);
  return xfem::expand_solution(r, xfem::cholmod_solve(r.K, r.f).x, s.fixed, s.fixed_values);
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
  // The linear exact field is the same on both sides: accepted, and a step's solution is the whole
  // system's with the same problem (whose Dirichlet data take each node's side).
  p = problem();
  p.dirichlet[1].exact = xfem::parse_exact_field(
      xfem::Json::parse(R"({"linear": {"gradient": [[0, 0, 0], [0.02, 0, 0], [0.03, -0.01, 0]], "translation": [0, 0.01, 0]}})"),
      "p.json", "dirichlet[1].exact");
  p.dirichlet[1].value = {};
  const xfem::UncutBody linear = xfem::factorize_uncut(mesh, p);
  const auto cut = partial_cut(0.55);
  const xfem::CutSolution step = xfem::solve_cut(linear, cut);
  const xfem::EnrichedMesh em = xfem::enriched_mesh(mesh, xfem::classify(mesh, *cut), cut);
  const Eigen::VectorXd u = whole_system_solution(em, p);
  REQUIRE(step.u.size() == u.size());
  CHECK((step.u - u).norm() <= 1e-10 * u.norm());
  // The lid's node at (1, 0, 2) (id 3 + 4 (0 + 4 6)) moved by the field: (0, 0.02 + 0.01, 0.03).
  CHECK((linear.constrained.segment<3>(3 * (3 + 4 * 4 * 6)) - Eigen::Vector3d(0, 0.03, 0.03)).norm() < 1e-15);
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

TEST_CASE("progressive cut: every step of a sweep equals the whole system's solution, in any order",
          "[progressive_cut]") {
  // A blade 0.3 deep from z = 0.6 moving along y through a 8 x 8 x 4 box of height 0.5: its front
  // (bottom edge and leading edge) inside the box all along, tets far behind the leading edge kept.
  const xfem::TetMesh mesh = xfem::box_mesh({8, 8, 4}, {0, 0, 0}, {1, 1, 0.5});
  xfem::BladePath path;
  path.polyline = {{0.43, -0.05, 0.6}, {0.43, 0.95, 0.6}};
  const xfem::TriangleMesh sweep = xfem::cut_sweep(path, 0.3, {0, 0, -1}, 0, 0.06, 1.0);
  const std::vector<double> times = xfem::cut_times(sweep, "sweep");
  const std::string conditions = R"(
    "material": {"E": 1e3, "nu": 0.3},
    "dirichlet": [{"name": "bottom", "selector": {"box": {"lo": [-1, -1, -1], "hi": [2, 2, 0]}}, "value": [0, 0, 0]}],
    "neumann": [{"name": "left", "selector": {"box": {"lo": [-1, -1, -1], "hi": [0, 2, 3]}}, "traction": [-10, 0, 0]},
                {"name": "right", "selector": {"box": {"lo": [1, -1, -1], "hi": [2, 2, 3]}}, "traction": [10, 0, 3]}])";
  const std::vector<double> t = xfem::step_times(times, 6);
  // The default (conforming) rule with steps in order, then backwards and out of order (the answer
  // must not depend on the history), with and without the region prepared for the whole sweep (as
  // xfem-sweep does: its response computed once, the region ordered by step); the oversampling rule
  // (its points' sides from the cut) in order.
  std::vector<std::shared_ptr<const xfem::CutSurface>> all;
  for (double tk : t) all.push_back(std::make_shared<const xfem::CutSurface>(xfem::cut_until(sweep, times, tk)));
  for (const auto& [integration, order, prepared] :
       {std::tuple<std::string, std::vector<int>, bool>{"", {0, 1, 2, 3, 4, 5, 2, 5, 0, 4}, false},
        std::tuple<std::string, std::vector<int>, bool>{"", {0, 1, 2, 3, 4, 5, 2, 5, 0, 4}, true},
        std::tuple<std::string, std::vector<int>, bool>{R"(, "integration": {"rule": "oversampling"})", {1, 2, 3, 4}, false}}) {
    INFO("integration '" << integration << "', region prepared " << prepared);
    const xfem::Problem p = xfem::parse_problem(xfem::Json::parse("{" + conditions + integration + "}"), "p.json");
    const xfem::UncutBody body = xfem::factorize_uncut(mesh, p);
    // `sweeping` leaves the last solve to complete_solution (as xfem-sweep, which completes it with
    // the frame in another thread); `twin`, with the same history, completes every step itself.
    xfem::ProgressiveCut sweeping(body), twin(body);
    if (prepared) {
      // `twin` classifies the sweep's cuts from one another (GrowingCutClassifier), `sweeping` each
      // from scratch: the same region in the same order, or the steps' bits below would differ.
      std::vector<std::vector<int>> ids;
      for (double tk : t) ids.push_back(xfem::cut_until_ids(times, tk));
      const std::vector<std::vector<int>> none;  // not one list per cut: refused before any work
      CHECK_THROWS_WITH(twin.prepare(all, {}, &none), Catch::Contains("0 triangle id lists for"));
      sweeping.prepare(all);
      twin.prepare(all, {}, &ids);
      CHECK(sweeping.region_size() > 0);
      CHECK(twin.region_size() == sweeping.region_size());
    }
    long reused_tets = 0, kept_dofs = 0;
    for (int k : order) {
      INFO("step " << k + 1);
      const auto cut = std::make_shared<const xfem::CutSurface>(xfem::cut_until(sweep, times, t[k]));
      // Left incomplete, then completed: the same bits as the complete step.
      xfem::CutSolution step = sweeping.step(cut, xfem::cut_until_ids(times, t[k]), false);
      CHECK(step.pending.size() == static_cast<long>(body.free_dofs.size()));
      const Eigen::VectorXd before = step.u;
      xfem::complete_solution(body, step);
      CHECK(step.pending.size() == 0);
      CHECK(step.u != before);
      const xfem::CutSolution complete = twin.step(cut, xfem::cut_until_ids(times, t[k]));
      CHECK(complete.pending.size() == 0);
      CHECK(step.u == complete.u);
      const xfem::CutSolution whole = xfem::solve_cut(body, cut, {}, xfem::CutSolver::Refactor);
      REQUIRE(step.u.size() == whole.u.size());
      CHECK(step.enriched_dofs == whole.enriched_dofs);
      CHECK(step.unsupported_dofs == whole.unsupported_dofs);
      CHECK((step.u - whole.u).norm() <= 1e-10 * whole.u.norm());
      CHECK(step.enriched_dofs > 0);
      reused_tets += step.enriched_tets - step.recomputed_tets;
      kept_dofs += step.incremental.kept;
    }
    // The point of it: element matrices and Schur columns were reused.
    CHECK(reused_tets > 0);
    CHECK(kept_dofs > 0);
  }
}

TEST_CASE("incremental Schur: kept, changed, new and removed columns give the Schur complement of the current ones",
          "[progressive_cut]") {
  // A: 1D Laplacian-like SPD (n = 30); enriched DOFs couple to a few free DOFs each.
  const int n = 30;
  std::vector<Eigen::Triplet<double, int>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 4.0);
    if (i + 1 < n) t.emplace_back(i + 1, i, -1.0), t.emplace_back(i, i + 1, -1.0);
  }
  xfem::SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  const xfem::CholeskyFactor factor(A);
  const Eigen::MatrixXd Ainv = Eigen::MatrixXd(A).inverse();
  // Column of DOF `key`: couples to free DOFs key % n and (3 key) % n; K_ee diagonal 5 + `bump`,
  // and -0.5 with key + 1 (when present).
  const auto column = [&](long key, double bump, const std::vector<long>& present) {
    xfem::EnrichedColumn c;
    c.key = key;
    const int a = static_cast<int>(key % n), b = static_cast<int>((3 * key) % n);
    if (a == b) c.se = {{a, 1.0}};
    else c.se = {{std::min(a, b), 0.7}, {std::max(a, b), -0.4}};
    for (long other : present)
      if (other == key - 1 || other == key + 1) c.ee.emplace_back(other, -0.5);
    c.ee.emplace_back(key, 5.0 + bump);
    std::sort(c.ee.begin(), c.ee.end());
    return c;
  };
  xfem::IncrementalSchur schur(factor);
  schur.extend_region({0, 1, 2});
  const std::vector<std::vector<long>> steps = {{1, 2, 3, 4}, {1, 2, 3, 4, 5, 6}, {2, 3, 4, 5, 6, 7, 9}, {9, 2, 3, 4, 11}, {3}};
  for (std::size_t s = 0; s < steps.size(); ++s) {
    INFO("update " << s);
    std::vector<xfem::EnrichedColumn> cols;
    for (long key : steps[s]) cols.push_back(column(key, s == 2 && key == 4 ? 1.0 : 0.0, steps[s]));  // 4 changes once
    xfem::IncrementalSchurStats st;
    schur.update(cols, &st);
    const long m = static_cast<long>(cols.size());
    Eigen::MatrixXd K_se = Eigen::MatrixXd::Zero(n, m), S = Eigen::MatrixXd::Zero(m, m);
    for (long j = 0; j < m; ++j) {
      for (const auto& e : cols[j].se) K_se(e.first, j) = e.second;
      for (const auto& e : cols[j].ee)
        for (long i = 0; i < m; ++i)
          if (cols[i].key == e.first) S(i, j) = e.second;
    }
    S -= K_se.transpose() * Ainv * K_se;
    Eigen::VectorXd r(m);
    for (long i = 0; i < m; ++i) r[i] = 1.0 + 0.3 * i;
    const Eigen::VectorXd x = schur.solve(r);
    CHECK((S * x - r).norm() <= 1e-12 * r.norm());
    if (s == 1) CHECK(st.kept == 3);  // 1, 2 and 3 kept; 4 gained the neighbour 5
    if (s == 4) CHECK(st.added == 1);
  }
  CHECK(schur.region_size() >= 3);
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

TEST_CASE("progressive cut: with two materials, the Schur step and the sweep's step equal the whole system assembled "
          "with them", "[progressive_cut][materials]") {
  // Region 2 above z = 1 (a grid plane) 7 times stiffer: the tets with enriched DOFs around the cut
  // z = 0.93 lie in both regions.
  xfem::TetMesh mesh = box();
  xfem_test::split_regions(mesh, 2, 1.0, 1, 2);
  xfem::Problem p = problem();
  xfem::RegionMaterial stiff;
  stiff.id = 2;
  stiff.E = 7e3;
  stiff.nu = 0.2;
  p.materials.push_back(stiff);
  const xfem::UncutBody body = xfem::factorize_uncut(mesh, p);
  const xfem::UncutBody one = xfem::factorize_uncut(mesh, problem());
  xfem::ProgressiveCut sweeping(body);
  int generation = 0;
  for (double front : {0.3, 0.55, 1.2}) {
    INFO("front at x = " << front);
    const auto cut = partial_cut(front);
    const xfem::CutSolution step = xfem::solve_cut(body, cut, {}, xfem::CutSolver::Schur);
    std::vector<int> ids(static_cast<std::size_t>(cut->mesh().triangles.rows()));  // new triangles every step
    for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = 1000 * generation + static_cast<int>(i);
    ++generation;
    const xfem::CutSolution swept = sweeping.step(cut, ids);
    const xfem::EnrichedMesh em = xfem::enriched_mesh(mesh, xfem::classify(mesh, *cut), cut);
    const Eigen::VectorXd u = whole_system_solution(em, p);
    CHECK((step.u - u).norm() <= 1e-10 * u.norm());
    CHECK((swept.u - u).norm() <= 1e-10 * u.norm());
    // And it is not the one-material answer.
    const xfem::CutSolution single = xfem::solve_cut(one, cut, {}, xfem::CutSolver::Schur);
    CHECK((single.u - u).norm() > 1e-3 * u.norm());
  }
}

TEST_CASE("box grid: the boxes meeting a box are those a test of every box finds", "[progressive_cut]") {
  // Random thin and flat boxes (a cut's triangles), queries of every size, touching ones (closed
  // boxes) and queries outside the grid; cells finer and coarser than the boxes.
  std::mt19937 rng(35);
  std::uniform_real_distribution<double> at(-1, 1), size(0, 0.2);
  std::vector<xfem::BoxGrid::Box> boxes(300);
  for (auto& b : boxes) {
    b.col(0) = Eigen::Vector3d(at(rng), at(rng), 0.1 * at(rng));
    b.col(1) = b.col(0) + Eigen::Vector3d(size(rng), size(rng), 0.1 * size(rng));
  }
  for (double cell : {0.01, 0.1, 0.5, 5.0}) {
    INFO("cell " << cell);
    const xfem::BoxGrid grid(boxes, cell);
    std::vector<int> found;
    long hits = 0;
    for (int q = 0; q < 400; ++q) {
      Eigen::Vector3d lo(1.5 * at(rng), 1.5 * at(rng), 0.3 * at(rng));
      Eigen::Vector3d hi = lo + Eigen::Vector3d::Constant(q % 4 == 0 ? 0.0 : size(rng) * (q % 3 + 1));
      if (q % 7 == 0) {  // exactly touching box q % 300 at its corner
        lo = boxes[q % 300].col(1);
        hi = lo + Eigen::Vector3d::Constant(0.05);
      }
      grid.meeting(lo, hi, found);
      std::vector<int> expected;
      for (int k = 0; k < static_cast<int>(boxes.size()); ++k)
        if ((boxes[k].col(0).array() <= hi.array()).all() && (boxes[k].col(1).array() >= lo.array()).all())
          expected.push_back(k);
      CHECK(found == expected);
      hits += static_cast<long>(expected.size());
    }
    CHECK(hits > 100);  // the queries do meet boxes
  }
  std::vector<int> found{1, 2};
  xfem::BoxGrid({}, 1.0).meeting(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), found);
  CHECK(found.empty());
}
