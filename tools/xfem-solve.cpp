// SPDX-License-Identifier: MIT
// Solves the assembled system K u = f with its Dirichlet conditions (issue 5; DESIGN.md stages).
#include <fcntl.h>
#include <unistd.h>

#include <memory>

#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/core/version.h"
#include "xfem/solve/backend_launch.h"
#include "xfem/solve/contact_pressure_file.h"
#include "xfem/solve/contact_solve.h"
#include "xfem/solve/direct_backend.h"
#include "xfem/solve/enriched_dof_fixes.h"
#include "xfem/solve/friction_solve.h"
#include "xfem/solve/petsc_backend.h"
#include "xfem/solve/solution_output.h"
#include "xfem/solve/solve_options.h"
#include "xfem/system/dirichlet.h"

// The PETSc backend is this program built with PETSc, xfem-solve-petsc (backend_launch.h).
#ifndef XFEM_SOLVE_LINKS_PETSC
#define XFEM_SOLVE_LINKS_PETSC 0
#endif

int main(int argc, char** argv) {
  auto tool = xfem::cli::make_tool(
      "xfem-solve",
      "Solves K u = f of an xfem-assemble system directory with its Dirichlet conditions (eliminated, K stays SPD).\n"
      "Writes the full solution (3N values in metres: original, sign and branch DOFs; constrained DOFs at their\n"
      "values) and reports the reaction force (N) and moment (N m, about the origin) of each Dirichlet condition.\n"
      "The backend is chosen from the system unless given: CHOLMOD (direct) for small systems, PETSc CG + GAMG\n"
      "for large ones, started on several MPI processes by itself (mpirun; --np) when the system is large. The PETSc\n"
      "backend is the program xfem-solve-petsc next to this one (PETSc and MPI are loaded only when it runs).",
      "xfem-solve out/system -o out/u.mtx --report out/solve.json\n"
      "  xfem-solve out/system -o out/u.mtx --backend petsc --np 2 --rtol 1e-8");
  xfem::SolveOptions o;
  xfem::add_solve_options(tool->app, o);
  xfem::cli::add_threads_option(*tool);
#if XFEM_SOLVE_LINKS_PETSC
  // Outlives cli::run, so that rank 0 prints a failure before MPI is finalized: finalizing first
  // let mpirun stop rank 0 before its error line, once another rank had exited.
  std::unique_ptr<xfem::PetscSession> mpi;
#endif
  return xfem::cli::run(*tool, argc, argv, [&] {
    using xfem::cli::three_digits;
    const bool with_contact = xfem::check_solve_options(o);
    o.backend = xfem::launch_backend(o.dir, o.backend, o.processes, XFEM_SOLVE_LINKS_PETSC, argc, argv, o.output);
#if XFEM_SOLVE_LINKS_PETSC
    if (o.backend == "petsc") mpi = std::make_unique<xfem::PetscSession>();
    const bool root = !mpi || mpi->rank() == 0;
#else
    const bool root = true;  // no PETSc session, no ranks here
#endif
    // Failures are collective (every rank reads the same files and fails alike): rank 0 alone
    // reports, so a bad input gives one error line, not one per rank (-v keeps them all).
    if (!root && !tool->verbose) {
      const int null = ::open("/dev/null", O_WRONLY);
      if (null >= 0) ::dup2(null, 2), ::close(null);
    }
    const auto info = [&](const std::string& m) { if (root) xfem::cli::info(m); };
    const auto warn = [&](const std::string& m) { if (root) xfem::cli::warn(m); };

    const double t_read = xfem::cli::now();
    // The PETSc backend loads K from a binary system itself, each rank only its rows (petsc_backend.h);
    // with contact every rank iterates on the whole K (contact_solve.h).
    const bool distributed_load =
        o.backend == "petsc" && !with_contact && xfem::system_format(o.dir) == xfem::SystemFormat::Petsc;
    xfem::LinearSystem s = xfem::read_linear_system(o.dir, !distributed_load);
    long nonzeros = (s.K.nonZeros() + s.K.rows()) / 2;  // stored triangle (K is symmetric)
#if XFEM_SOLVE_LINKS_PETSC
    xfem::PetscMatrix distributed;
    if (o.backend == "petsc" && !with_contact) distributed = xfem::distribute_system_matrix(o.dir, s, &nonzeros);
#endif
    info(o.dir + ": N = " + std::to_string(s.n) + " (NP " + std::to_string(s.np) + ", NS " + std::to_string(s.ns) +
         ", NB " + std::to_string(s.nb) + "), " + std::to_string(3 * s.n) + " DOFs, " + std::to_string(nonzeros) +
         " non-zeros in the lower triangle, " + std::to_string(s.fixed.size()) + " fixed; read in " +
         three_digits(xfem::cli::now() - t_read) + " s");
    xfem::require_constrained(s);
    const xfem::EnrichedDofFixes fixes = xfem::fix_degenerate_enrichment(s, o.drop_tol, info, warn);

    xfem::Json report;
    report["generator"] = std::string("xfem-solve ") + xfem::version;
    report["system"] = o.dir;
    report["n"] = s.n;
    report["dofs"] = 3 * s.n;
    report["fixed_dofs"] = static_cast<long>(s.fixed.size());
    report["nonzeros"] = nonzeros;
    report["unsupported_enriched_dofs"] = fixes.unsupported;
    report["dropped_enriched_dofs"] = fixes.dropped;
    report["backend"] = o.backend;
    Eigen::VectorXd u;
    double residual = 0;
    xfem::ContactOperator contact;
    xfem::ContactOutcome touching;
    const xfem::PetscSolveOptions petsc_options{o.rtol, o.max_iterations, o.near_null, o.enriched_block, {}};
    if (with_contact) {
      contact = xfem::read_contact_operator(o.dir, 3 * s.n);
      std::unique_ptr<xfem::PenalisedSolver> solver;
      if (o.backend == "cholmod") solver = std::make_unique<xfem::CholmodPenalisedSolver>(o.ordering, !tool->quiet);
#if XFEM_SOLVE_LINKS_PETSC
      else solver = std::make_unique<xfem::PetscPenalisedSolver>(petsc_options, root, tool->verbose, root && !tool->quiet);
#endif
      u = contact.has_friction()  // problem.json "contact": {"friction": mu}: Coulomb friction between the faces
              ? xfem::solve_with_friction(s, contact, o.contact, *solver, report, &residual, &touching)
              : xfem::solve_with_contact(s, contact, o.contact, *solver, report, &residual, &touching);
#if XFEM_SOLVE_LINKS_PETSC
      if (o.backend == "petsc")
        report["contact"]["cg_iterations"] = static_cast<const xfem::PetscPenalisedSolver&>(*solver).iterations();
#endif
    }
    else if (o.backend == "cholmod") u = xfem::solve_with_cholmod(s, o.ordering, !tool->quiet, report, &residual);
#if XFEM_SOLVE_LINKS_PETSC
    else
      u = xfem::solve_with_petsc(std::move(distributed), s, petsc_options, root, tool->verbose, root && !tool->quiet,
                                 report, &residual);
#endif
    info("relative residual ||K u - f|| / ||f|| on the free DOFs: " + three_digits(residual));
    report["relative_residual"] = residual;
    const double limit = o.backend == "cholmod" ? 1e-8 : 10 * o.rtol;
    if (!(residual <= limit))
      throw xfem::Error("the solution is inaccurate (relative residual " + three_digits(residual) +
                        "): K is numerically singular; no output written");
    if (root) xfem::write_solution(o.dir, s, distributed_load, u, o.output, o.reactions_path, report, o.report_path);
    if (root && !o.contact_pressure_path.empty()) xfem::write_contact_pressure(contact, touching.pressure, s.np, o.contact_pressure_path);
  });
}
