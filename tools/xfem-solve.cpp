// SPDX-License-Identifier: MIT
// Solves the assembled system K u = f with its Dirichlet conditions (issue 5; DESIGN.md stages).
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <mutex>
#include <thread>

#include "xfem/solve/cholmod_solver.h"
#include "xfem/core/cli.h"
#include "xfem/system/dirichlet.h"
#include "xfem/core/error.h"
#include "xfem/core/fingerprint.h"
#include "xfem/system/linear_system.h"
#include "xfem/io/petsc_binary.h"
#include "xfem/solve/petsc_solver.h"
#include "xfem/system/reactions.h"
#include "xfem/core/version.h"

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

// Prints "<tool>: <what>: 12 s" on stderr every few seconds while a long library call runs (from
// 3 s on), so a user sees that a factorization of a minute is alive. Nothing when quiet.
class Ticker {
 public:
  Ticker(std::string what, bool enabled) : what_(std::move(what)) {
    if (enabled) thread_ = std::thread([this] { run(); });
  }
  ~Ticker() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
  }

 private:
  void run() {
    const auto start = std::chrono::steady_clock::now();
    std::unique_lock<std::mutex> lock(mutex_);
    for (int seconds = 3;; seconds += seconds < 10 ? 3 : 10) {
      if (wake_.wait_until(lock, start + std::chrono::seconds(seconds), [this] { return done_; })) return;
      xfem::cli::info(what_ + ": " + std::to_string(seconds) + " s so far");
    }
  }
  std::string what_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::thread thread_;
};

bool under_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

// PETSc and Open MPI take ~40 ms to load on a quiet machine (more than a small CHOLMOD solve), so
// xfem-solve does not link them: the PETSc backend is the same program built with PETSc,
// xfem-solve-petsc, next to it (XFEM_SOLVE_LINKS_PETSC). The path of that program, or of this one.
#ifndef XFEM_SOLVE_LINKS_PETSC
#define XFEM_SOLVE_LINKS_PETSC 0
#endif
std::string petsc_program(char** argv) {
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path me = ec ? std::filesystem::path(argv[0]) : self;
  if (XFEM_SOLVE_LINKS_PETSC) return me.string();
  const auto helper = me.parent_path() / "xfem-solve-petsc";
  if (!xfem::have_petsc || !std::filesystem::exists(helper))
    throw xfem::Error("the PETSc backend needs " + helper.string() + (xfem::have_petsc ? ", which is missing" :
                      ": this build has no PETSc (CMake did not find it)") +
                      ": use --backend cholmod, or install libpetsc-real-dev and rebuild");
  return helper.string();
}

// Replaces this process by `program` with this process's arguments, optionally under
// `mpirun -np P` (the ranks see the MPI environment and do not restart again). Returns only if
// the program cannot be started.
void exec_with_arguments(const std::string& program, int processes, int argc, char** argv) {
  std::vector<std::string> args;
  if (processes > 1) {
    // --quiet: no banner of mpirun's own when a rank exits with an error (the rank's one line says it).
    args = {"mpirun", "--quiet", "-np", std::to_string(processes), "--oversubscribe", "--bind-to", "none"};
    // Waiting ranks yield the core instead of busy-polling (unless the user chose otherwise): on
    // a machine whose cores other jobs share, polling ranks took 1.7x the wall time (256k
    // reference, 2 ranks, load 9: 25.8 and 36.3 s polling against 14.1 and 22.3 s yielding).
    ::setenv("OMPI_MCA_mpi_yield_when_idle", "1", 0);
    if (::geteuid() == 0) {  // Open MPI refuses root unless told twice
      args.push_back("--allow-run-as-root");
      ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
      ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    }
  }
  args.push_back(program);
  for (int k = 1; k < argc; ++k) args.emplace_back(argv[k]);
  std::vector<char*> cargs;
  for (auto& a : args) cargs.push_back(a.data());
  cargs.push_back(nullptr);
  ::setenv("XFEM_OPTIONS_SHOWN", "1", 1);  // -v: this process has printed them (cli.cpp)
  std::fflush(stderr);
  if (processes > 1)
    ::execvp("mpirun", cargs.data());
  else
    ::execv(program.c_str(), cargs.data());
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
  return xfem::cli::run(*tool, argc, argv, [&] {
    xfem::cli::check_output(output, {".mtx"}, true);
    if (!report_path.empty()) xfem::cli::check_output(report_path, {".json"}, true);
    const bool mpi_child = under_mpirun();
    if (backend == "auto" || (backend == "petsc" && !mpi_child)) {
      // The choice from the system without K (cheap), the same in every rank of a restart.
      const xfem::LinearSystem head = xfem::read_linear_system(dir, false);
      const long dofs = 3 * head.n;
      if (backend == "auto") backend = processes > 1 ? "petsc" : xfem::automatic_backend(dofs, head.n > head.np);
      if (backend == "petsc" && !mpi_child) {
        const int wanted = processes > 0 ? processes
                                         : xfem::automatic_processes(dofs, static_cast<int>(std::thread::hardware_concurrency()));
        if (wanted > 1) {
          const std::string program = petsc_program(argv);
          // The checks a rank would fail on, here once: one error line instead of one per rank.
          const std::string k_path = xfem::system_matrix_file(dir, xfem::system_format(dir));
          if (xfem::system_format(dir) == xfem::SystemFormat::Petsc) {
            const xfem::PetscMatrixHeader h = xfem::read_petsc_matrix_header(k_path);
            if (h.rows != dofs || h.cols != dofs)
              throw xfem::Error(k_path + ": " + std::to_string(h.rows) + " x " + std::to_string(h.cols) +
                                ", expected 3N x 3N = " + std::to_string(dofs) + " x " + std::to_string(dofs));
          }
          xfem::cli::detail("starting " + std::to_string(wanted) + " PETSc processes under mpirun");
          exec_with_arguments(program, wanted, argc, argv);
          xfem::cli::warn("cannot start mpirun (Open MPI's launcher not on PATH?): solving on 1 process");
        }
      }
    }
#if XFEM_SOLVE_LINKS_PETSC
    std::unique_ptr<xfem::PetscSession> mpi;
    if (backend == "petsc") mpi = std::make_unique<xfem::PetscSession>();
    const bool root = !mpi || mpi->rank() == 0;
#else
    // One process (or one rank of a user's mpirun): the PETSc program takes over with the same
    // arguments; it decides again from the same files, so it comes to the same choice.
    if (backend == "petsc") {
      exec_with_arguments(petsc_program(argv), 1, argc, argv);
      throw xfem::Error("cannot start " + petsc_program(argv) + ": " + std::strerror(errno));
    }
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
    // The PETSc backend loads K from a binary system itself, each rank only its rows; the checks
    // of enriched DOFs below need only K's diagonal then (a zero diagonal of the positive
    // semi-definite K is a zero row), which stands in for K in `s`.
    const bool distributed_load = backend == "petsc" && xfem::system_format(dir) == xfem::SystemFormat::Petsc;
    xfem::LinearSystem s = xfem::read_linear_system(dir, !distributed_load);
    long nonzeros = 0;
#if XFEM_SOLVE_LINKS_PETSC
    xfem::PetscMatrix distributed;
    if (distributed_load) {
      const std::string k_path = xfem::system_matrix_file(dir, xfem::SystemFormat::Petsc);
      distributed = xfem::petsc_load_matrix(k_path, 3 * s.n);
      nonzeros = (xfem::read_petsc_matrix_header(k_path).nonzeros + 3 * s.n) / 2;
      const Eigen::VectorXd diag = xfem::petsc_diagonal(distributed);
      s.K.resize(3 * s.n, 3 * s.n);
      s.K.reserve(Eigen::VectorXi::Ones(3 * s.n));
      for (long d = 0; d < 3 * s.n; ++d) s.K.insert(d, d) = diag[d];
      s.K.makeCompressed();
    } else {
      nonzeros = (s.K.nonZeros() + s.K.rows()) / 2;  // stored triangle (K is symmetric)
      if (backend == "petsc") distributed = xfem::petsc_matrix(s.K);
    }
#else
    nonzeros = (s.K.nonZeros() + s.K.rows()) / 2;  // stored triangle (K is symmetric)
#endif
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
    Eigen::VectorXd u;
    double residual = 0;
    if (backend == "cholmod") {
      const xfem::ReducedSystem reduced = xfem::eliminate_dirichlet(s.K, s.f, s.fixed, s.fixed_values);
      xfem::CholmodResult c;
      try {
        const Ticker ticker("CHOLMOD analyse + factorization", !tool->quiet);
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
      report["factor_flops"] = c.flops;
      report["rcond_estimate"] = c.rcond;
      report["setup_seconds"] = c.analyze_seconds + c.factor_seconds;
      report["solve_seconds"] = c.solve_seconds;
      residual = xfem::relative_residual(s.K, s.f, u, reduced);
    } else {
#if XFEM_SOLVE_LINKS_PETSC
      const std::string block = enriched_block != "auto" ? enriched_block : s.n > s.np ? "direct" : "gamg";
      xfem::PetscSolveOptions options{rtol, max_iterations, near_null, block, {}};
      const double t_start = xfem::cli::now();
      double first = 0;
      if (tool->verbose && root)
        options.monitor = [&](long iteration, double norm) {
          if (iteration == 0) first = norm;
          xfem::cli::detail("CG iteration " + std::to_string(iteration) + ": residual " + g(norm) + " N (" +
                            g(first > 0 ? norm / first : norm) + " of the first), " + g(xfem::cli::now() - t_start) +
                            " s");
        };
      const Ticker ticker("PETSc setup + CG", root && !tool->quiet);
      const xfem::PetscResult p = xfem::petsc_solve(std::move(distributed), s, options);
      u = p.u;
      residual = p.relative_residual;
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
#endif
    }
    info("relative residual ||K u - f|| / ||f|| on the free DOFs: " + g(residual));
    report["relative_residual"] = residual;
    const double limit = backend == "cholmod" ? 1e-8 : 10 * rtol;
    if (!(residual <= limit))
      throw xfem::Error("the solution is inaccurate (relative residual " + g(residual) +
                        "): K is numerically singular; no output written");
    if (root) {
      // r = K u - f on the constrained DOFs. Each PETSc rank loaded only its rows of K, and `s` holds
      // its diagonal only: the root reads the rows of the constrained DOFs from K again (not all of K:
      // at 1.14M DOFs that took seconds and a gigabyte) for the reactions.
      xfem::LinearSystem full;
      if (distributed_load) {
        full = xfem::read_linear_system(dir, false);
        full.K = xfem::read_petsc_symmetric_matrix_rows(xfem::system_matrix_file(dir, xfem::SystemFormat::Petsc), full.fixed);
      }
      const xfem::Reactions reactions = xfem::reactions(dir, distributed_load ? full : s, u);
      for (const auto& r : reactions.conditions) info(xfem::describe_reaction(r, reactions.moments));
      report["reactions"] = xfem::reactions_json(reactions.conditions, reactions.applied, reactions.moments);
      if (!reactions_path.empty()) xfem::write_vector(reactions.r, reactions_path);
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
