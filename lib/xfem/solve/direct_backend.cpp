// SPDX-License-Identifier: MIT
#include "xfem/solve/direct_backend.h"

#include "xfem/core/cli.h"
#include "xfem/core/progress_ticker.h"
#include "xfem/solve/cholmod_solver.h"
#include "xfem/system/dirichlet.h"

namespace xfem {

Eigen::VectorXd solve_with_cholmod(const LinearSystem& s, const std::string& ordering, bool ticking, Json& report,
                                   double* residual) {
  using cli::three_digits;
  const ReducedSystem reduced = eliminate_dirichlet(s.K, s.f, s.fixed, s.fixed_values);
  CholmodResult c;
  try {
    const cli::ProgressTicker ticker("CHOLMOD analyse + factorization", ticking);
    c = cholmod_solve(reduced.K, reduced.f, ordering == "amd" ? Ordering::Amd : Ordering::Metis);
  } catch (const NotPositiveDefinite& e) {
    throw Error("K is not positive definite at " + describe_dof(s, reduced.free_dofs[e.column]) +
                ": a rigid motion is left free (too few Dirichlet conditions?) or the enrichment there is "
                "degenerate (try --drop-tiny-enrichment 1e-6)");
  }
  if (c.ordering != ordering) cli::warn("CHOLMOD has no METIS: ordering with AMD instead");
  if (c.rcond < 1e-14)
    cli::warn("K is near-singular (CHOLMOD reciprocal condition estimate " + three_digits(c.rcond) + ")");
  Eigen::VectorXd u = expand_solution(reduced, c.x, s.fixed, s.fixed_values);
  cli::info("CHOLMOD " + std::string(c.supernodal ? "supernodal" : "simplicial") + " Cholesky, " + c.ordering +
            " ordering: " + std::to_string(static_cast<long>(c.factor_nonzeros)) + " non-zeros in L; analyse " +
            three_digits(c.analyze_seconds) + " s, factor " + three_digits(c.factor_seconds) + " s, solve " +
            three_digits(c.solve_seconds) + " s");
  report["ordering"] = c.ordering;
  report["factor_nonzeros"] = static_cast<long>(c.factor_nonzeros);
  report["factor_flops"] = c.flops;
  report["rcond_estimate"] = c.rcond;
  report["setup_seconds"] = c.analyze_seconds + c.factor_seconds;
  report["solve_seconds"] = c.solve_seconds;
  *residual = relative_residual(s.K, s.f, u, reduced);
  return u;
}

}  // namespace xfem
