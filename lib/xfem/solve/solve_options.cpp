// SPDX-License-Identifier: MIT
#include "xfem/solve/solve_options.h"

#include "xfem/core/error.h"
#include "xfem/solve/petsc_solver.h"
#include "xfem/system/contact_operator.h"

namespace xfem {

void add_solve_options(CLI::App& app, SolveOptions& o) {
  app.add_option("system", o.dir, "system directory written by xfem-assemble (system.json, K.petsc or K.mtx, ...)")
      ->required();
  app.add_option("-o,--output", o.output, "solution vector u (Matrix Market, 3N x 1, m)")->required();
  app.add_option("--report", o.report_path, "JSON report (sizes, backend, timings, residual, reaction forces in N and "
                                           "moments in N m per Dirichlet condition)");
  app.add_option("--reactions", o.reactions_path, "also write the nodal reactions r = K u - f (Matrix Market, 3N x 1, N; "
                                                  "non-zero on constrained DOFs only) for xfem-visualize --reactions");
  app.add_option("--backend", o.backend,
                 "auto (default: cholmod below " + std::to_string(kPetscFromDofs) + " DOFs, " +
                     std::to_string(kPetscFromDofsEnriched) +
                     " with enriched DOFs, else petsc), cholmod (direct) or petsc (CG + GAMG, on --np processes)")
      ->check(CLI::IsMember({"auto", "cholmod", "petsc"}));
  app.add_option("--np", o.processes,
                 "PETSc: MPI processes; xfem-solve starts itself under mpirun for more than 1 (default: 1 per " +
                     std::to_string(kDofsPerProcess) + " DOFs, at most the number of cores). Under mpirun: ignored")
      ->check(CLI::Range(1, 1024));
  app.add_option("--ordering", o.ordering, "CHOLMOD fill-reducing ordering: metis (default) or amd")
      ->check(CLI::IsMember({"metis", "amd"}));
  app.add_option("--rtol", o.rtol, "PETSc: relative residual ||f - K u|| / ||f|| to reach (default 1e-10)")
      ->check(cli::positive());
  app.add_option("--max-iterations", o.max_iterations, "PETSc: CG iteration limit (default 10000)")
      ->check(cli::range(1, 1e9));
  app.add_option("--near-null-space", o.near_null, "PETSc: GAMG near-null space: rigid (rigid-body modes of the original "
                                                   "DOFs, needs the coordinates in the system; default), rigid-enriched (also the "
                                                   "translations on enriched DOFs) or none (docs/PERFORMANCE.md)")
      ->check(CLI::IsMember({"rigid", "rigid-enriched", "none"}));
  app.add_option("--enriched-block", o.enriched_block,
                 "PETSc: preconditioner for the enriched DOFs: direct (PCFIELDSPLIT: GAMG on the original DOFs, "
                 "a Cholesky factorization of the enriched block, symmetric multiplicative), gamg (one GAMG on the "
                 "whole K) or auto (default: direct when the system has enriched DOFs, else gamg); "
                 "docs/PERFORMANCE.md")
      ->check(CLI::IsMember({"auto", "direct", "gamg"}));
  app.add_option("--drop-tiny-enrichment", o.drop_tol,
                 "fix to 0 the enriched DOFs whose diagonal of K is below TOL times the mean diagonal of the original "
                 "DOFs: sign/branch DOFs with a tiny but non-zero support on one side of the cut (TOL ~ the volume "
                 "fraction of the support; e.g. 1e-6; default 0: keep all, warn below 1e-8). Enriched DOFs whose row "
                 "of K is exactly zero are always fixed to 0, with a warning")
      ->check(cli::non_negative());
  app.add_option("--contact-tol", o.contact.tolerance, "contact (a system assembled with \"contact\"): the largest "
                 "penetration of the cut's faces accepted, m (default: 1e-8 max |u|); with \"friction\" also the largest "
                 "slip of a sticking node and the friction multipliers' error, in m")->check(cli::positive());
  app.add_option("--contact-iterations", o.contact.max_solves, "contact: linear solves (CHOLMOD: factorizations) at most (default 100)")
      ->check(cli::range(2, 100000));
  app.add_option("--contact-pressure", o.contact_pressure_path, "contact: also write the contact pressure of each "
                 "contact node (Matrix Market, NP x cuts, Pa; docs/FORMATS.md) for xfem-visualize --contact-pressure");
}

bool check_solve_options(SolveOptions& o) {
  cli::check_output(o.output, {".mtx"}, true);
  if (!o.report_path.empty()) cli::check_output(o.report_path, {".json"}, true);
  if (!o.contact_pressure_path.empty()) cli::check_output(o.contact_pressure_path, {".mtx"}, true);
  // Contact is iterated on either backend (contact_solve.h: PenalisedSolver).
  const bool with_contact = has_contact_operator(o.dir);
  if (!with_contact && !o.contact_pressure_path.empty())
    throw Error(o.dir + ": --contact-pressure: the system has no contact operator (problem.json \"contact\" is off)");
  return with_contact;
}

}  // namespace xfem
