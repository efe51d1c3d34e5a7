// SPDX-License-Identifier: MIT
// Solves the assembled system K u = f with its Dirichlet conditions (issue 5; DESIGN.md stages).
#include <fcntl.h>
#include <unistd.h>

#include <memory>

#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/core/version.h"
#include "xfem/solve/backend_launch.h"
#include "xfem/solve/contact_solve.h"
#include "xfem/solve/direct_backend.h"
#include "xfem/solve/enriched_dof_fixes.h"
#include "xfem/solve/petsc_backend.h"
#include "xfem/solve/solution_output.h"
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
  std::string dir, output, report_path, reactions_path, backend = "auto", ordering = "metis", near_null = "rigid",
              enriched_block = "auto";
  double rtol = 1e-10, drop_tol = 0;
  int max_iterations = 10000, processes = 0;
  xfem::ContactIteration contact;
  auto& app = tool->app;
  app.add_option("system", dir, "system directory written by xfem-assemble (system.json, K.petsc or K.mtx, ...)")
      ->required();
  app.add_option("-o,--output", output, "solution vector u (Matrix Market, 3N x 1, m)")->required();
  app.add_option("--report", report_path, "JSON report (sizes, backend, timings, residual, reaction forces in N and "
                                         "moments in N m per Dirichlet condition)");
  app.add_option("--reactions", reactions_path, "also write the nodal reactions r = K u - f (Matrix Market, 3N x 1, N; "
                                                "non-zero on constrained DOFs only) for xfem-visualize --reactions");
  app.add_option("--backend", backend,
                 "auto (default: cholmod below " + std::to_string(xfem::kPetscFromDofs) + " DOFs, " +
                     std::to_string(xfem::kPetscFromDofsEnriched) +
                     " with enriched DOFs, else petsc), cholmod (direct) or petsc (CG + GAMG, on --np processes)")
      ->check(CLI::IsMember({"auto", "cholmod", "petsc"}));
  app.add_option("--np", processes,
                 "PETSc: MPI processes; xfem-solve starts itself under mpirun for more than 1 (default: 1 per " +
                     std::to_string(xfem::kDofsPerProcess) + " DOFs, at most the number of cores). Under mpirun: ignored")
      ->check(CLI::Range(1, 1024));
  app.add_option("--ordering", ordering, "CHOLMOD fill-reducing ordering: metis (default) or amd")
      ->check(CLI::IsMember({"metis", "amd"}));
  app.add_option("--rtol", rtol, "PETSc: relative residual ||f - K u|| / ||f|| to reach (default 1e-10)")
      ->check(xfem::cli::positive());
  app.add_option("--max-iterations", max_iterations, "PETSc: CG iteration limit (default 10000)")
      ->check(xfem::cli::range(1, 1e9));
  app.add_option("--near-null-space", near_null, "PETSc: GAMG near-null space: rigid (rigid-body modes of the original "
                                                 "DOFs, needs the coordinates in the system; default), rigid-enriched (also the "
                                                 "translations on enriched DOFs) or none (docs/PERFORMANCE.md)")
      ->check(CLI::IsMember({"rigid", "rigid-enriched", "none"}));
  app.add_option("--enriched-block", enriched_block,
                 "PETSc: preconditioner for the enriched DOFs: direct (PCFIELDSPLIT: GAMG on the original DOFs, "
                 "a Cholesky factorization of the enriched block, symmetric multiplicative), gamg (one GAMG on the "
                 "whole K) or auto (default: direct when the system has enriched DOFs, else gamg); "
                 "docs/PERFORMANCE.md")
      ->check(CLI::IsMember({"auto", "direct", "gamg"}));
  app.add_option("--drop-tiny-enrichment", drop_tol,
                 "fix to 0 the enriched DOFs whose diagonal of K is below TOL times the mean diagonal of the original "
                 "DOFs: sign/branch DOFs with a tiny but non-zero support on one side of the cut (TOL ~ the volume "
                 "fraction of the support; e.g. 1e-6; default 0: keep all, warn below 1e-8). Enriched DOFs whose row "
                 "of K is exactly zero are always fixed to 0, with a warning")
      ->check(xfem::cli::non_negative());
  app.add_option("--contact-tol", contact.tolerance, "contact (a system assembled with \"contact\"): the largest "
                 "penetration of the cut's faces accepted, m (default: 1e-8 max |u|)")->check(xfem::cli::positive());
  app.add_option("--contact-iterations", contact.max_solves, "contact: factorizations at most (default 100)")
      ->check(xfem::cli::range(2, 100000));
  xfem::cli::add_threads_option(*tool);
#if XFEM_SOLVE_LINKS_PETSC
  // Outlives cli::run, so that rank 0 prints a failure before MPI is finalized: finalizing first
  // let mpirun stop rank 0 before its error line, once another rank had exited.
  std::unique_ptr<xfem::PetscSession> mpi;
#endif
  return xfem::cli::run(*tool, argc, argv, [&] {
    using xfem::cli::three_digits;
    xfem::cli::check_output(output, {".mtx"}, true);
    if (!report_path.empty()) xfem::cli::check_output(report_path, {".json"}, true);
    // Contact is iterated on CHOLMOD factorizations (contact_solve.h).
    const bool with_contact = xfem::has_contact_operator(dir);
    if (with_contact && backend == "petsc") throw xfem::Error(dir + ": contact between the cut's faces is solved by "
                                                              "the cholmod backend only (give --backend cholmod)");
    if (with_contact) backend = "cholmod";
    backend = xfem::launch_backend(dir, backend, processes, XFEM_SOLVE_LINKS_PETSC, argc, argv, output);
#if XFEM_SOLVE_LINKS_PETSC
    if (backend == "petsc") mpi = std::make_unique<xfem::PetscSession>();
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
    // The PETSc backend loads K from a binary system itself, each rank only its rows (petsc_backend.h).
    const bool distributed_load = backend == "petsc" && xfem::system_format(dir) == xfem::SystemFormat::Petsc;
    xfem::LinearSystem s = xfem::read_linear_system(dir, !distributed_load);
    long nonzeros = (s.K.nonZeros() + s.K.rows()) / 2;  // stored triangle (K is symmetric)
#if XFEM_SOLVE_LINKS_PETSC
    xfem::PetscMatrix distributed;
    if (backend == "petsc") distributed = xfem::distribute_system_matrix(dir, s, &nonzeros);
#endif
    info(dir + ": N = " + std::to_string(s.n) + " (NP " + std::to_string(s.np) + ", NS " + std::to_string(s.ns) +
         ", NB " + std::to_string(s.nb) + "), " + std::to_string(3 * s.n) + " DOFs, " + std::to_string(nonzeros) +
         " non-zeros in the lower triangle, " + std::to_string(s.fixed.size()) + " fixed; read in " +
         three_digits(xfem::cli::now() - t_read) + " s");
    xfem::require_constrained(s);
    const xfem::EnrichedDofFixes fixes = xfem::fix_degenerate_enrichment(s, drop_tol, info, warn);

    xfem::Json report;
    report["generator"] = std::string("xfem-solve ") + xfem::version;
    report["system"] = dir;
    report["n"] = s.n;
    report["dofs"] = 3 * s.n;
    report["fixed_dofs"] = static_cast<long>(s.fixed.size());
    report["nonzeros"] = nonzeros;
    report["unsupported_enriched_dofs"] = fixes.unsupported;
    report["dropped_enriched_dofs"] = fixes.dropped;
    report["backend"] = backend;
    Eigen::VectorXd u;
    double residual = 0;
    if (with_contact)
      u = xfem::solve_with_contact(s, xfem::read_contact_operator(dir, 3 * s.n), contact, ordering, !tool->quiet,
                                   report, &residual);
    else if (backend == "cholmod") u = xfem::solve_with_cholmod(s, ordering, !tool->quiet, report, &residual);
#if XFEM_SOLVE_LINKS_PETSC
    else
      u = xfem::solve_with_petsc(std::move(distributed), s, {rtol, max_iterations, near_null, enriched_block, {}}, root,
                                 tool->verbose, root && !tool->quiet, report, &residual);
#endif
    info("relative residual ||K u - f|| / ||f|| on the free DOFs: " + three_digits(residual));
    report["relative_residual"] = residual;
    const double limit = backend == "cholmod" ? 1e-8 : 10 * rtol;
    if (!(residual <= limit))
      throw xfem::Error("the solution is inaccurate (relative residual " + three_digits(residual) +
                        "): K is numerically singular; no output written");
    if (root) xfem::write_solution(dir, s, distributed_load, u, output, reactions_path, report, report_path);
  });
}
