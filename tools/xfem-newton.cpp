// SPDX-License-Identifier: MIT
// The large-deformation solve: reads what xfem-assemble reads, writes what xfem-solve writes.
#include <string>
#include <vector>

#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/core/version.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/solve/newton_run.h"
#include "xfem/system/problem.h"

int main(int argc, char** argv) {
  auto tool = xfem::cli::make_tool(
      "xfem-newton",
      "Solve the elastic problem of problem.json at large deformation: total Lagrangian, the material of\n"
      "material.model (linear, corotational or neo-hookean; docs/METHOD.md \"Material models\"), each side of a\n"
      "cut deforming on its own, Newton's method with a line search that refuses inverted elements, in\n"
      "load_steps load steps (halved when Newton fails), CHOLMOD with one analysis for every factorization.\n"
      "Reads what xfem-assemble reads and writes what xfem-solve writes: u.mtx with the fingerprints of mesh,\n"
      "cuts and problem (xfem-visualize, xfem-probe and xfem-rmserror take it unchanged), the reactions and a\n"
      "JSON report with every load step's residual history (docs/FORMATS.md).",
      "xfem-newton out/enriched.vtu --cut cut.vtp --problem problem.json -o out/u.mtx --report out/newton.json");
  std::string input, problem_path;
  std::vector<std::string> cut_paths;
  xfem::NewtonRun run;
  auto& app = tool->app;
  app.add_option("enriched", input, "xfem-enrich output (.vtu)")->required();
  app.add_option("-c,--cut", cut_paths, "the cut surface given to xfem-classify; several cuts: once per cut, as given "
                                        "to xfem-classify")
      ->allow_extra_args(false);
  app.add_option("-p,--problem", problem_path, "problem description (problem.json: material with model, load_steps, "
                                               "dirichlet, neumann, body_force)")->required();
  app.add_option("-o,--output", run.output, "the solution u (.mtx, 3N values)")->required();
  app.add_option("--reactions", run.reactions_path, "nodal reaction forces r(u) - f on the constrained DOFs (.mtx)");
  app.add_option("--report", run.report_path, "JSON report: load steps, Newton iterations and residuals, reactions");
  app.add_option("--rtol", run.rtol, "a load step has converged when the residual on the free DOFs is below RTOL times "
                                     "the larger of the loads and the reactions (default 1e-8)")
      ->check(xfem::cli::range(1e-15, 1e-2));
  app.add_option("--max-iterations", run.max_iterations, "Newton iterations per load step before it is halved "
                                                         "(default 25)")
      ->check(xfem::cli::range(1, 1000));
  app.add_option("--ordering", run.ordering, "CHOLMOD's fill-reducing ordering: metis (default) or amd")
      ->check(CLI::IsMember({"metis", "amd"}));
  return xfem::cli::run(*tool, argc, argv, [&] {
    xfem::cli::check_output(run.output, {".mtx"}, true);
    if (!run.reactions_path.empty()) xfem::cli::check_output(run.reactions_path, {".mtx"}, true);
    if (!run.report_path.empty()) xfem::cli::check_output(run.report_path, {".json"}, true);
    run.problem_path = problem_path;
    const xfem::Problem problem = xfem::read_problem(problem_path);
    const xfem::EnrichedMesh em = xfem::read_enriched_mesh_to_solve(input, cut_paths);
    // Several materials reach the nonlinear forces through BodyIntegration::materials, which the
    // Newton driver (solve/newton_run) does not set yet: refuse rather than use one law for all.
    if (!xfem::tet_materials(problem, em.mesh, input).of_tet.empty())
      throw xfem::Error(problem_path + ": materials: xfem-newton solves a body of one material (give every region "
                        "the same material, or solve the linear model with xfem-assemble and xfem-solve)");
    xfem::Json report;
    report["generator"] = std::string("xfem-newton ") + xfem::version;
    report["problem"] = problem_path;
    xfem::run_newton(em, problem, run, report);
  });
}
