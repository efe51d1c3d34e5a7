// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <memory>
#include <string>

#include "xfem/core/error.h"
#include "xfem/io/matrix_market.h"

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

/// One CHOLMOD supernodal Cholesky factorization of a symmetric positive definite matrix A, kept
/// for many solves (progressive cutting reuses the uncut body's for every step of a sweep: cutting
/// changes only the enriched rows and columns of K, never A). Only the lower triangle of A is read,
/// in place. With Ordering::Metis, falls back to AMD (`ordering` says so) if CHOLMOD lacks METIS.
/// A small factorization (below 1e9 flops) runs its BLAS on one thread.
class CholeskyFactor {
 public:
  /// Analyses and factorizes A. Throws NotPositiveDefinite when the factorization breaks down,
  /// xfem::Error on other CHOLMOD failures (out of memory).
  explicit CholeskyFactor(const SparseMatrix& A, Ordering ordering = Ordering::Metis);
  ~CholeskyFactor();
  CholeskyFactor(const CholeskyFactor&) = delete;
  CholeskyFactor& operator=(const CholeskyFactor&) = delete;

  long size() const;
  /// Factorizes A again with the first matrix's analysis (ordering and symbolic factor): A must
  /// have the same size and pattern, e.g. the next tangent of a Newton iteration. Throws as the
  /// constructor does; updates factor_seconds and rcond.
  void refactor(const SparseMatrix& A);
  /// A^-1 B for every column of B at once (one pass over the factor per call). Safe to call from
  /// several threads: the calls take turns (CHOLMOD's workspace is shared).
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;

  std::string ordering;          ///< "metis" or "amd": the one used
  bool supernodal = true;        ///< supernodal (BLAS) or simplicial factorization
  double factor_nonzeros = 0;    ///< entries of L
  double flops = 0;              ///< floating-point operations of the factorization
  double rcond = 0;              ///< CHOLMOD's estimate (min diag L / max diag L)^2
  double analyze_seconds = 0, factor_seconds = 0;

 private:
  void factorize_numeric(void* matrix);  // cholmod_sparse*: CHOLMOD's types stay out of this header
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Solves A x = b with CHOLMOD's supernodal Cholesky factorization (a CholeskyFactor used once), A symmetric positive
/// definite; only the lower triangle of `A` is read, in place (no copy of A). With
/// Ordering::Metis, falls back to AMD (result.ordering says so) if CHOLMOD lacks METIS.
/// Throws NotPositiveDefinite when the factorization breaks down, xfem::Error on other CHOLMOD
/// failures (out of memory) or a non-finite solution.
CholmodResult cholmod_solve(const SparseMatrix& A, const Eigen::VectorXd& b, Ordering ordering = Ordering::Metis);

}  // namespace xfem
