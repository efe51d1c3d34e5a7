// SPDX-License-Identifier: MIT
// The contact iteration with an iterative linear solve (PenalisedSolver::iterative, the PETSc
// backend's CG): its line search must allow for the solve's residual (penalised_step_slack).
#include <catch2/catch.hpp>
#include <cmath>

#include "enriched_test_meshes.h"
#include "xfem/core/error.h"
#include "xfem/solve/contact_solve.h"
#include "xfem/system/assembly.h"
#include "xfem/system/contact_operator.h"
#include "xfem/system/problem.h"

namespace {

// CHOLMOD's solves, each penalised solution then moved off by `relative` of its largest value
// along a fixed direction, with alternating sign: the error of an inexact solve that does not shrink
// as the iteration converges (CG's to its relative residual). Zero on the fixed DOFs.
class InexactSolver : public xfem::PenalisedSolver {
 public:
  InexactSolver(double relative, bool iterative) : exact_("amd", false), relative_(relative), iterative_(iterative) {}
  Eigen::VectorXd solve_unpenalised(const xfem::LinearSystem& s, xfem::Json& report, double* residual) override {
    return exact_.solve_unpenalised(s, report, residual);
  }
  Eigen::VectorXd solve(const xfem::LinearSystem& s, const xfem::SparseMatrix& K, const Eigen::VectorXd& f,
                        const char* what, double* residual) override {
    Eigen::VectorXd x = exact_.solve(s, K, f, what, residual);
    Eigen::VectorXd e(x.size());
    for (long k = 0; k < x.size(); ++k) e[k] = std::sin(0.7 * static_cast<double>(k) + 0.3);
    for (long d : s.fixed) e[d] = 0;
    sign_ = -sign_;
    x += sign_ * relative_ * x.cwiseAbs().maxCoeff() * e;
    *residual = (K * x - f).norm() / f.norm();  // the inexact solve's (free and fixed rows: only a size)
    return x;
  }
  bool iterative() const override { return iterative_; }

 private:
  xfem::CholmodPenalisedSolver exact_;
  double relative_;
  bool iterative_;
  double sign_ = 1;
};

// cut_box (enriched_test_meshes.h): the 1 x 1 x 2 box cut through by z = 0.3, on rollers, its top
// pressed down by 0.01: the cut closes, uniaxial stress everywhere.
xfem::Problem pressed() {
  return xfem::parse_problem(xfem::Json::parse(R"({"material": {"E": 1e3, "nu": 0.3}, "contact": true, "dirichlet": [
      {"selector": {"box": {"lo": [-1, -1, -1], "hi": [2, 2, 0]}}, "value": [null, null, 0]},
      {"selector": {"box": {"lo": [-1, -1, -1], "hi": [0, 2, 2]}}, "value": [0, null, null]},
      {"selector": {"box": {"lo": [-1, -1, -1], "hi": [2, 0, 2]}}, "value": [null, 0, null]},
      {"selector": {"box": {"lo": [-1, -1, 1], "hi": [2, 2, 2]}}, "value": [null, null, -0.01]}]})"), "p.json");
}

}  // namespace

TEST_CASE("contact: an iterative solve's residual does not stall the line search", "[contact]") {
  const xfem::EnrichedMesh em = xfem_test::cut_box(0.3);
  const xfem::Problem p = pressed();
  xfem::LinearSystem s = xfem::assemble_system(em, p, 30, 0);
  s.K = xfem::SparseMatrix(s.K.selfadjointView<Eigen::Lower>());
  const xfem::ContactOperator c = xfem::contact_operator(em, p);
  xfem::ContactIteration settings;
  settings.max_solves = 40;
  xfem::Json report;
  double residual = 0;
  xfem::ContactOutcome exact, inexact;
  xfem::CholmodPenalisedSolver cholmod("amd", false);
  const Eigen::VectorXd u = xfem::solve_with_contact(s, c, settings, cholmod, report, &residual, &exact);
  REQUIRE(exact.solves > 2);
  // An error of 1e-10 of max |u| per solve, far below the contact tolerance (1e-8 max |u|).
  InexactSolver cg(1e-10, true);
  const Eigen::VectorXd v = xfem::solve_with_contact(s, c, settings, cg, report, &residual, &inexact);
  CHECK(inexact.solves <= exact.solves + 1);
  CHECK(inexact.active == exact.active);
  CHECK((v - u).cwiseAbs().maxCoeff() <= 1e-8 * u.cwiseAbs().maxCoeff());
  // The same solves taken as exact: each full step raises the energy by the solve's error along
  // it, the line search shortens it, and the iteration never takes the full step it stops on.
  InexactSolver unaware(1e-10, false);
  CHECK_THROWS_AS(xfem::solve_with_contact(s, c, settings, unaware, report, &residual, &inexact), xfem::Error);
}
