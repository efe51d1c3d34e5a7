// SPDX-License-Identifier: MIT
// Solves the assembled system K u = f with its Dirichlet conditions (issue 5; DESIGN.md stages).
#include <cstdio>
#include <filesystem>
#include <memory>

#include "xfem/cholmod_solver.h"
#include "xfem/cli.h"
#include "xfem/dirichlet.h"
#include "xfem/error.h"
#include "xfem/fingerprint.h"
#include "xfem/linear_system.h"
#include "xfem/petsc_solver.h"
#include "xfem/version.h"

namespace {

// Enriched DOFs whose diagonal is below this fraction of the mean original diagonal make K
// near-singular (sign nodes with tiny support, paper end of 5.2): warned about, never dropped
// unless asked.
constexpr double kTinyWarn = 1e-8;

std::string g(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// The enriched.vtu point array and value that find the mesh point of enriched vector k (FORMATS.md).
std::string enriched_point_key(const xfem::LinearSystem& s, long k) {
  if (k < s.np + s.ns) return "sign_dof = " + std::to_string(k);
  return "branch_dof = " + std::to_string(s.np + s.ns + 4 * ((k - s.np - s.ns) / 4));
}

}  // namespace

int main(int argc, char** argv) {
  auto tool = xfem::cli::make_tool(
      "xfem-solve",
      "Solves K u = f of an xfem-assemble system directory with its Dirichlet conditions (eliminated, K stays SPD).\n"
      "Writes the full solution (3N values: original, sign and branch DOFs; constrained DOFs at their values).",
      "xfem-solve out/system -o out/u.mtx --report out/solve.json\n"
      "  mpirun -np 2 xfem-solve out/system -o out/u.mtx --backend petsc --rtol 1e-8");
  std::string dir, output, report_path, backend = "cholmod", ordering = "metis", near_null = "rigid",
              enriched_block = "auto";
  double rtol = 1e-10, drop_tol = 0;
  int max_iterations = 10000;
  auto& app = tool->app;
  app.add_option("system", dir, "system directory written by xfem-assemble (K.mtx, f.mtx, dirichlet.mtx, system.json)")
      ->required();
  app.add_option("-o,--output", output, "solution vector u (Matrix Market, 3N x 1)")->required();
  app.add_option("--report", report_path, "JSON report (sizes, backend, timings, residual)");
  app.add_option("--backend", backend, "cholmod (direct, default) or petsc (CG + GAMG; run under mpirun for MPI)")
      ->check(CLI::IsMember({"cholmod", "petsc"}));
  app.add_option("--ordering", ordering, "CHOLMOD fill-reducing ordering: metis (default) or amd")
      ->check(CLI::IsMember({"metis", "amd"}));
  app.add_option("--rtol", rtol, "PETSc: relative residual ||f - K u|| / ||f|| to reach (default 1e-10)")
      ->check(xfem::cli::positive());
  app.add_option("--max-iterations", max_iterations, "PETSc: CG iteration limit (default 10000)")
      ->check(xfem::cli::range(1, 1e9));
  app.add_option("--near-null-space", near_null, "PETSc: GAMG near-null space: rigid (rigid-body modes of the original "
                                                 "DOFs, needs coordinates.mtx; default), rigid-enriched (also the "
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
  return xfem::cli::run(*tool, argc, argv, [&] {
    xfem::cli::check_output(output, {".mtx"}, true);
    if (!report_path.empty()) xfem::cli::check_output(report_path, {".json"}, true);
    std::unique_ptr<xfem::PetscSession> mpi;
    if (backend == "petsc") mpi = std::make_unique<xfem::PetscSession>();
    const bool root = !mpi || mpi->rank() == 0;
    const auto info = [&](const std::string& m) { if (root) xfem::cli::info(m); };
    const auto warn = [&](const std::string& m) { if (root) xfem::cli::warn(m); };

    const double t_read = xfem::cli::now();
    xfem::LinearSystem s = xfem::read_linear_system(dir);
    const long nonzeros = (s.K.nonZeros() + s.K.rows()) / 2;  // stored triangle (K is symmetric)
    info(dir + ": N = " + std::to_string(s.n) + " (NP " + std::to_string(s.np) + ", NS " + std::to_string(s.ns) +
         ", NB " + std::to_string(s.nb) + "), " + std::to_string(3 * s.n) + " DOFs, " + std::to_string(nonzeros) +
         " non-zeros in the lower triangle, " + std::to_string(s.fixed.size()) + " fixed; read in " +
         g(xfem::cli::now() - t_read) + " s");
    xfem::require_constrained(s);

    // Enriched DOFs without support make K singular whatever the threshold: always eliminated.
    const auto unsupported = xfem::fix_unsupported_enrichment(s);
    if (!unsupported.empty()) {
      std::vector<long> vectors;
      for (long d : unsupported)
        if (vectors.empty() || vectors.back() != d / 3) vectors.push_back(d / 3);
      warn(std::to_string(unsupported.size()) + " enriched DOFs (" + std::to_string(vectors.size()) +
           (vectors.size() == 1 ? " vector" : " vectors") +
           ") have an exactly zero row in K (no support on one side of the cut): fixed to 0; first " +
           xfem::describe_dof(s, unsupported.front()) + " (its mesh point: the one with " + enriched_point_key(s, vectors.front()) +
           " in enriched.vtu)");
    }
    const auto tiny = xfem::tiny_enriched_dofs(s, drop_tol > 0 ? drop_tol : kTinyWarn);  // drop what was asked, warn below 1e-8
    if (drop_tol > 0) {
      xfem::fix_to_zero(s, tiny);
      info("dropped " + std::to_string(tiny.size()) + " enriched DOFs (diagonal < " + g(drop_tol) +
           " x mean original diagonal): fixed to 0");
    } else if (!tiny.empty()) {
      warn(std::to_string(tiny.size()) + " enriched DOFs have a diagonal below " + g(kTinyWarn) +
           " x the mean original diagonal, first " + xfem::describe_dof(s, tiny.front()) +
           ": sign/branch nodes with tiny support make K near-singular (try --drop-tiny-enrichment 1e-6)");
    }

    xfem::Json report;
    report["generator"] = std::string("xfem-solve ") + xfem::version;
    report["system"] = dir;
    report["n"] = s.n;
    report["dofs"] = 3 * s.n;
    report["fixed_dofs"] = static_cast<long>(s.fixed.size());
    report["nonzeros"] = nonzeros;
    report["unsupported_enriched_dofs"] = static_cast<long>(unsupported.size());
    report["dropped_enriched_dofs"] = drop_tol > 0 ? static_cast<long>(tiny.size()) : 0L;
    report["backend"] = backend;
    const xfem::ReducedSystem reduced = xfem::eliminate_dirichlet(s.K, s.f, s.fixed, s.fixed_values);
    Eigen::VectorXd u;
    if (backend == "cholmod") {
      xfem::CholmodResult c;
      try {
        c = xfem::cholmod_solve(reduced.K, reduced.f, ordering == "amd" ? xfem::Ordering::Amd : xfem::Ordering::Metis);
      } catch (const xfem::NotPositiveDefinite& e) {
        throw xfem::Error("K is not positive definite at " + xfem::describe_dof(s, reduced.free_dofs[e.column]) +
                          ": a rigid motion is left free (too few Dirichlet conditions?) or the enrichment there is "
                          "degenerate (try --drop-tiny-enrichment 1e-6)");
      }
      if (c.ordering != ordering) warn("CHOLMOD has no METIS: ordering with AMD instead");
      if (c.rcond < 1e-14)
        warn("K is near-singular (CHOLMOD reciprocal condition estimate " + g(c.rcond) + ")");
      u = xfem::expand_solution(reduced, c.x, s.fixed, s.fixed_values);
      info("CHOLMOD " + std::string(c.supernodal ? "supernodal" : "simplicial") + " Cholesky, " + c.ordering +
           " ordering: " + std::to_string(static_cast<long>(c.factor_nonzeros)) + " non-zeros in L; analyse " +
           g(c.analyze_seconds) + " s, factor " + g(c.factor_seconds) + " s, solve " +
           g(c.solve_seconds) + " s");
      report["ordering"] = c.ordering;
      report["factor_nonzeros"] = static_cast<long>(c.factor_nonzeros);
      report["rcond_estimate"] = c.rcond;
      report["setup_seconds"] = c.analyze_seconds + c.factor_seconds;
      report["solve_seconds"] = c.solve_seconds;
    } else {
      const std::string block = enriched_block != "auto" ? enriched_block : s.n > s.np ? "direct" : "gamg";
      const xfem::PetscResult p = xfem::petsc_solve(s, {rtol, max_iterations, near_null, block});
      u = p.u;
      info("PETSc CG + " + p.preconditioner + " on " + std::to_string(p.processes) + " process(es), near-null space " +
           near_null + ": " + std::to_string(p.iterations) + " iterations (" + p.converged_reason + "); setup " +
           g(p.setup_seconds) + " s, solve " + g(p.solve_seconds) + " s");
      report["enriched_block"] = block;
      report["preconditioner"] = p.preconditioner;
      report["processes"] = p.processes;
      report["near_null_space"] = near_null;
      report["iterations"] = p.iterations;
      report["rtol"] = rtol;
      report["setup_seconds"] = p.setup_seconds;
      report["solve_seconds"] = p.solve_seconds;
    }
    const double residual = xfem::relative_residual(s.K, s.f, u, reduced);
    info("relative residual ||K u - f|| / ||f|| on the free DOFs: " + g(residual));
    report["relative_residual"] = residual;
    const double limit = backend == "cholmod" ? 1e-8 : 10 * rtol;
    if (!(residual <= limit))
      throw xfem::Error("the solution is inaccurate (relative residual " + g(residual) +
                        "): K is numerically singular; no output written");
    if (root) {
      // The fingerprints of the system's inputs (recorded by xfem-assemble) travel with u.
      xfem::Provenance provenance;
      const std::string provenance_path = (std::filesystem::path(dir) / "provenance.json").string();
      if (std::filesystem::exists(provenance_path))
        provenance = xfem::provenance_from_json(xfem::read_json(provenance_path), provenance_path);
      xfem::write_vector(u, output, xfem::provenance_comments(provenance));
      if (!report_path.empty()) xfem::write_json(report, report_path);
    }
  });
}
