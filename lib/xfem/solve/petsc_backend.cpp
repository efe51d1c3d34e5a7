// SPDX-License-Identifier: MIT
#include "xfem/solve/petsc_backend.h"

#include "xfem/core/cli.h"
#include "xfem/core/progress_ticker.h"
#include "xfem/io/petsc_binary.h"

namespace xfem {

PetscMatrix distribute_system_matrix(const std::string& dir, LinearSystem& s, long* nonzeros) {
  if (system_format(dir) != SystemFormat::Petsc) {
    *nonzeros = (s.K.nonZeros() + s.K.rows()) / 2;  // stored triangle (K is symmetric)
    return petsc_matrix(s.K);
  }
  const std::string k_path = system_matrix_file(dir, SystemFormat::Petsc);
  PetscMatrix distributed = petsc_load_matrix(k_path, 3 * s.n);
  *nonzeros = (read_petsc_matrix_header(k_path).nonzeros + 3 * s.n) / 2;
  const Eigen::VectorXd diag = petsc_diagonal(distributed);
  s.K.resize(3 * s.n, 3 * s.n);
  s.K.reserve(Eigen::VectorXi::Ones(3 * s.n));
  for (long d = 0; d < 3 * s.n; ++d) s.K.insert(d, d) = diag[d];
  s.K.makeCompressed();
  return distributed;
}

Eigen::VectorXd solve_with_petsc(PetscMatrix&& K, const LinearSystem& s, PetscSolveOptions options, bool root,
                                 bool verbose, bool ticking, Json& report, double* residual) {
  using cli::three_digits;
  if (options.enriched_block == "auto") options.enriched_block = s.n > s.np ? "direct" : "gamg";
  const double t_start = cli::now();
  double first = 0;
  if (verbose && root)
    options.monitor = [&](long iteration, double norm) {
      if (iteration == 0) first = norm;
      cli::detail("CG iteration " + std::to_string(iteration) + ": residual " + three_digits(norm) + " N (" +
                  three_digits(first > 0 ? norm / first : norm) + " of the first), " +
                  three_digits(cli::now() - t_start) + " s");
    };
  const cli::ProgressTicker ticker("PETSc setup + CG", ticking);
  const PetscResult p = petsc_solve(std::move(K), s, options);
  *residual = p.relative_residual;
  if (root)
    cli::info("PETSc CG + " + p.preconditioner + " on " + std::to_string(p.processes) + " process(es), near-null space " +
              options.near_null_space + ": " + std::to_string(p.iterations) + " iterations (" + p.converged_reason +
              "); setup " + three_digits(p.setup_seconds) + " s, solve " + three_digits(p.solve_seconds) + " s");
  report["enriched_block"] = options.enriched_block;
  report["preconditioner"] = p.preconditioner;
  report["processes"] = p.processes;
  report["near_null_space"] = options.near_null_space;
  report["iterations"] = p.iterations;
  report["rtol"] = options.rtol;
  report["setup_seconds"] = p.setup_seconds;
  report["solve_seconds"] = p.solve_seconds;
  return p.u;
}

PetscPenalisedSolver::PetscPenalisedSolver(PetscSolveOptions options, bool root, bool verbose, bool ticking)
    : options_(std::move(options)), root_(root), verbose_(verbose), ticking_(ticking) {}

Eigen::VectorXd PetscPenalisedSolver::solve_unpenalised(const LinearSystem& s, Json& report, double* residual) {
  system_.n = s.n, system_.np = s.np, system_.ns = s.ns, system_.nb = s.nb;
  system_.coordinates = s.coordinates;
  if (options_.enriched_block == "auto") options_.enriched_block = s.n > s.np ? "direct" : "gamg";
  const Eigen::VectorXd u = solve_with_petsc(petsc_matrix(s.K), s, options_, root_, verbose_, ticking_, report, residual);
  iterations_.push_back(report["iterations"].get<long>());
  return petsc_broadcast(u, 3 * s.n);
}

Eigen::VectorXd PetscPenalisedSolver::solve(const LinearSystem& s, const SparseMatrix& K, const Eigen::VectorXd& f,
                                            const char* what, double* residual) {
  system_.f = f;
  system_.fixed = s.fixed;
  system_.fixed_values = s.fixed_values;
  const PetscResult p = petsc_solve(petsc_matrix(K), system_, options_);
  iterations_.push_back(p.iterations);
  if (root_)
    cli::detail(std::string(what) + ": PETSc CG + " + p.preconditioner + ": " + std::to_string(p.iterations) +
                " iterations; setup " + cli::three_digits(p.setup_seconds) + " s, solve " +
                cli::three_digits(p.solve_seconds) + " s");
  *residual = p.relative_residual;
  return petsc_broadcast(p.u, 3 * s.n);
}

}  // namespace xfem
