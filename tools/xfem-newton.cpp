// SPDX-License-Identifier: MIT
// The large-deformation solve: reads what xfem-assemble reads, writes what xfem-solve writes.
#include <fcntl.h>
#include <unistd.h>

#include <memory>
#include <string>
#include <vector>

#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/core/version.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/solve/backend_launch.h"
#include "xfem/solve/newton_run.h"
#include "xfem/solve/petsc_solver.h"
#include "xfem/system/problem.h"

// The PETSc backend is this program built with PETSc, xfem-newton-petsc (backend_launch.h).
#ifndef XFEM_NEWTON_LINKS_PETSC
#define XFEM_NEWTON_LINKS_PETSC 0
#endif
#if XFEM_NEWTON_LINKS_PETSC
#include "xfem/solve/newton_petsc.h"
#endif

int main(int argc, char** argv) {
  auto tool = xfem::cli::make_tool(
      "xfem-newton",
      "Solve the elastic problem of problem.json at large deformation: total Lagrangian, the material of\n"
      "material.model (linear, corotational or neo-hookean; docs/METHOD.md \"Material models\"), each side of a\n"
      "cut deforming on its own, Newton's method with a line search that refuses inverted elements, in\n"
      "load_steps load steps (halved when Newton fails). The linear solves on xfem-solve's backends: CHOLMOD with one\n"
      "analysis for every factorization, or PETSc CG + GAMG on --np MPI processes (mpirun, started by itself; every\n"
      "process assembles the whole tangent, the solves are distributed; the program xfem-newton-petsc next to this one).\n"
      "Reads what xfem-assemble reads and writes what xfem-solve writes: u.mtx with the fingerprints of mesh,\n"
      "cuts and problem (xfem-visualize, xfem-probe and xfem-rmserror take it unchanged), the reactions and a\n"
      "JSON report with every load step's residual history (docs/FORMATS.md).",
      "xfem-newton out/enriched.vtu --cut cut.vtp --problem problem.json -o out/u.mtx --report out/newton.json\n"
      "  xfem-newton out/enriched.vtu --cut cut.vtp --problem problem.json -o out/u.mtx --backend petsc --np 2");
  std::string input, problem_path, backend = "cholmod";
  int processes = 0;
  xfem::PetscSolveOptions cg;
  std::vector<std::string> cut_paths;
  xfem::NewtonRun run;
  auto& app = tool->app;
  app.add_option("enriched", input, "xfem-enrich output (.vtu)")->required();
  app.add_option("-c,--cut", cut_paths, "the cut surface given to xfem-classify; several cuts: once per cut, as given "
                                        "to xfem-classify")
      ->allow_extra_args(false);
  app.add_option("-p,--problem", problem_path, "problem description (problem.json: material with model, load_steps, "
                                               "dirichlet, neumann, body_force, cut_loads: pressures follow the deformed "
                                               "faces, contact: the gap in the reference configuration)")->required();
  app.add_option("-o,--output", run.output, "the solution u (.mtx, 3N values)")->required();
  app.add_option("--reactions", run.reactions_path, "nodal reaction forces r(u) - f on the constrained DOFs (.mtx)");
  app.add_option("--report", run.report_path, "JSON report: load steps, Newton iterations and residuals, reactions");
  app.add_option("--rtol", run.rtol, "a load step has converged when the residual on the free DOFs is below RTOL times "
                                     "the larger of the loads and the reactions (default 1e-8)")
      ->check(xfem::cli::range(1e-15, 1e-2));
  app.add_option("--max-iterations", run.max_iterations, "Newton iterations per load step before it is halved "
                                                         "(default 25)")
      ->check(xfem::cli::range(1, 1000));
  app.add_option("--backend", backend, "the linear solves: cholmod (default; one analysis, a factorization per "
                                       "iteration), petsc (CG + GAMG, on --np processes) or auto (as xfem-solve: petsc from " +
                                       std::to_string(xfem::kPetscFromDofsEnriched) + " DOFs with enriched DOFs, " +
                                       std::to_string(xfem::kPetscFromDofs) + " without)")
      ->check(CLI::IsMember({"auto", "cholmod", "petsc"}));
  app.add_option("--np", processes, "PETSc: MPI processes; xfem-newton starts itself under mpirun for more than 1 "
                                    "(default: 1 per " + std::to_string(xfem::kDofsPerProcess) +
                                    " DOFs, at most the number of cores). Under mpirun: ignored")
      ->check(CLI::Range(1, 1024));
  app.add_option("--cg-rtol", cg.rtol, "PETSc: each linear solve's relative residual (default 1e-10; Newton's own "
                                       "--rtol decides convergence)")
      ->check(xfem::cli::range(1e-15, 1e-2));
  cg.enriched_block = "auto";  // the field split on cut meshes, as xfem-solve (contact's penalty needs it)
  app.add_option("--enriched-block", cg.enriched_block, "PETSc: the enriched DOFs' preconditioner, as xfem-solve's: "
                 "direct (their block factorized), gamg (one GAMG on the whole tangent) or auto (default: direct "
                 "when the mesh has enriched DOFs)")
      ->check(CLI::IsMember({"auto", "direct", "gamg"}));
  app.add_option("--contact-tol", run.contact.tolerance, "contact (problem.json \"contact\"): the largest penetration "
                 "accepted at each load step, metres (default 1e-8 of max |u| at that step)")
      ->check(CLI::PositiveNumber);
  app.add_option("--contact-updates", run.contact.max_updates, "contact: multiplier updates per load step at most "
                 "(default 50)")
      ->check(CLI::Range(1, 10000));
  app.add_option("--contact-pressure", run.contact_pressure_path, "contact: also write the contact pressure of each "
                 "contact node (Matrix Market, NP x cuts, Pa; as xfem-solve's) for xfem-visualize --contact-pressure");
  app.add_option("--ordering", run.ordering, "CHOLMOD's fill-reducing ordering: metis (default) or amd")
      ->check(CLI::IsMember({"metis", "amd"}));
  xfem::cli::add_threads_option(*tool);
#if XFEM_NEWTON_LINKS_PETSC
  std::unique_ptr<xfem::PetscSession> mpi;  // outlives cli::run: rank 0 prints a failure before MPI ends
#endif
  return xfem::cli::run(*tool, argc, argv, [&] {
    xfem::cli::check_output(run.output, {".mtx"}, true);
    if (!run.reactions_path.empty()) xfem::cli::check_output(run.reactions_path, {".mtx"}, true);
    if (!run.report_path.empty()) xfem::cli::check_output(run.report_path, {".json"}, true);
    run.problem_path = problem_path;
    const xfem::Problem problem = xfem::read_problem(problem_path);
    xfem::refuse_friction(problem, "xfem-newton solves frictionless contact");
    if (!run.contact_pressure_path.empty()) {
      xfem::cli::check_output(run.contact_pressure_path, {".mtx"}, true);
      if (!problem.contact.on)
        throw xfem::Error(problem_path + ": --contact-pressure: problem.json has no \"contact\"");
    }
    const xfem::EnrichedMesh em = xfem::read_enriched_mesh_to_solve(input, cut_paths);
    // Each tet's law (problem.json `materials`, checked against the mesh's regions); none: one law.
    const xfem::TetMaterials materials = xfem::tet_materials(problem, em.mesh, input);
    if (!materials.of_tet.empty()) run.materials = &materials;
    // PETSc: restarted under mpirun (or as xfem-newton-petsc) here, after the input's checks.
    run.backend = xfem::launch_program_backend(backend, 3 * em.n, em.n > em.np, processes, XFEM_NEWTON_LINKS_PETSC,
                                               "xfem-newton-petsc", "xfem-newton: ", argc, argv, run.output);
#if XFEM_NEWTON_LINKS_PETSC
    std::unique_ptr<xfem::TangentSolver> solver;
    if (run.backend == "petsc") {
      mpi = std::make_unique<xfem::PetscSession>();
      run.root = mpi->rank() == 0;
      run.processes = mpi->size();
      // Every rank fails alike (the same data, the same decisions): rank 0 alone reports (-v: all).
      if (!run.root && !tool->verbose) {
        const int null = ::open("/dev/null", O_WRONLY);
        if (null >= 0) ::dup2(null, 2), ::close(null);
      }
      if (tool->verbose && run.root)
        cg.monitor = [](long it, double norm) {
          xfem::cli::detail("  CG iteration " + std::to_string(it) + ": residual " + xfem::cli::three_digits(norm) + " N");
        };
      solver = xfem::petsc_tangent_solver(em, cg);
      run.solver = solver.get();
      if (run.root) xfem::cli::info("linear solves: PETSc CG on " + std::to_string(run.processes) + " process(es)");
    }
#endif
    xfem::Json report;
    report["generator"] = std::string("xfem-newton ") + xfem::version;
    report["problem"] = problem_path;
    xfem::run_newton(em, problem, run, report);
  });
}
