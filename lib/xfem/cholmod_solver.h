// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <string>

#include "xfem/error.h"
#include "xfem/matrix_market.h"

namespace xfem {

/// Fill-reducing ordering of the Cholesky factorization.
enum class Ordering { Metis, Amd };

/// What a CHOLMOD solve did, for the report.
struct CholmodResult {
  Eigen::VectorXd x;           ///< the solution, size of b
  std::string ordering;        ///< "metis" or "amd": the one actually used
  bool supernodal = true;      ///< supernodal (BLAS) or simplicial factorization
  double factor_nonzeros = 0;  ///< entries of L
  double flops = 0;            ///< floating-point operations of the factorization
  double rcond = 0;            ///< CHOLMOD's estimate (min diag L / max diag L)^2
  double analyze_seconds = 0, factor_seconds = 0, solve_seconds = 0;
};

/// A failed Cholesky factorization: the matrix is not positive definite. `column` is the
/// column of A (not of the permuted matrix) at which the factorization broke down.
class NotPositiveDefinite : public Error {
 public:
  NotPositiveDefinite(const std::string& what, long column) : Error(what), column(column) {}
  long column;
};

/// Solves A x = b with CHOLMOD's supernodal Cholesky factorization, A symmetric positive
/// definite; only the lower triangle of `A` is read, in place (no copy of A). With
/// Ordering::Metis, falls back to AMD (result.ordering says so) if CHOLMOD lacks METIS.
/// Throws NotPositiveDefinite when the factorization breaks down, xfem::Error on other CHOLMOD
/// failures (out of memory) or a non-finite solution.
CholmodResult cholmod_solve(const SparseMatrix& A, const Eigen::VectorXd& b, Ordering ordering = Ordering::Metis);

}  // namespace xfem
