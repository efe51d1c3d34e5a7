// SPDX-License-Identifier: MIT
#include "xfem/solve/cholmod_solver.h"

#include <cholmod.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>

#include "xfem/core/blas_threads.h"
#include "xfem/core/seconds_since.h"
#include "xfem/solve/cholmod_view.h"

namespace xfem {
namespace {

// Below this many floating-point operations (~0.1-0.2 s on one core) the factorization runs its BLAS
// on one thread: OpenBLAS's worker threads then cost more in waking and waiting than they save,
// most of all on a busy machine (the organ example's 1,740-DOF solve: 0.11 s wall with the threads,
// 0.06 s without, docs/PERFORMANCE.md).
constexpr double kThreadedBlasFlops = 1e9;

}  // namespace

// cholmod_start / cholmod_finish and the factor, released on every path (exceptions included).
struct CholeskyFactor::Impl {
  cholmod_common c;
  cholmod_factor* L = nullptr;
  std::mutex solving;  // a solve uses c's workspace: one at a time
  Impl() { cholmod_start(&c); }
  ~Impl() {
    if (L) cholmod_free_factor(&L, &c);
    cholmod_finish(&c);
  }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
};

CholeskyFactor::CholeskyFactor(const SparseMatrix& A_in, Ordering order) : impl_(std::make_unique<Impl>()) {
  if (A_in.rows() != A_in.cols())
    throw Error("Cholesky factorization: the matrix is " + std::to_string(A_in.rows()) + " x " +
                std::to_string(A_in.cols()) + ", not square");
  if (!A_in.isCompressed()) throw Error("Cholesky factorization: the matrix must be in compressed storage");
  cholmod_sparse a = lower_triangle_view(A_in);

  Impl& s = *impl_;
  s.c.print = 0;  // the caller reports failures in its own words
  s.c.supernodal = CHOLMOD_SUPERNODAL;
  s.c.nmethods = 1;
  s.c.method[0].ordering = order == Ordering::Metis ? CHOLMOD_METIS : CHOLMOD_AMD;
  s.c.postorder = 1;
  ordering = order == Ordering::Metis ? "metis" : "amd";
  auto t0 = std::chrono::steady_clock::now();
  s.L = cholmod_analyze(&a, &s.c);
  if (!s.L && order == Ordering::Metis && s.c.status == CHOLMOD_NOT_INSTALLED) {
    s.c.status = CHOLMOD_OK;
    s.c.method[0].ordering = CHOLMOD_AMD;
    ordering = "amd";
    s.L = cholmod_analyze(&a, &s.c);
  }
  if (!s.L || s.c.status < CHOLMOD_OK)
    throw Error("CHOLMOD analysis failed (status " + std::to_string(s.c.status) +
                (s.c.status == CHOLMOD_OUT_OF_MEMORY ? ": out of memory)" : ")"));
  analyze_seconds = seconds_since(t0);
  factor_nonzeros = s.c.lnz;
  flops = s.c.fl;

  factorize_numeric(&a);
}

void CholeskyFactor::refactor(const SparseMatrix& A_in) {
  if (A_in.rows() != size() || A_in.cols() != size() || !A_in.isCompressed())
    throw Error("Cholesky refactorization: the matrix is " + std::to_string(A_in.rows()) + " x " +
                std::to_string(A_in.cols()) + ", the factor's size is " + std::to_string(size()));
  cholmod_sparse a = lower_triangle_view(A_in);
  factorize_numeric(&a);
}

void CholeskyFactor::factorize_numeric(void* matrix) {
  cholmod_sparse& a = *static_cast<cholmod_sparse*>(matrix);
  Impl& s = *impl_;
  auto t0 = std::chrono::steady_clock::now();
  {
    std::unique_ptr<BlasThreads> one_thread;
    if (flops < kThreadedBlasFlops) one_thread = std::make_unique<BlasThreads>(1);
    cholmod_factorize(&a, s.L, &s.c);
  }
  factor_seconds = seconds_since(t0);
  if (s.c.status == CHOLMOD_NOT_POSDEF || s.L->minor < s.L->n) {
    const long minor = static_cast<long>(s.L->minor);
    const long column = s.L->Perm ? static_cast<const int*>(s.L->Perm)[minor] : minor;
    throw NotPositiveDefinite("the matrix is not positive definite: the Cholesky factorization broke down at column " +
                                  std::to_string(column) + " (step " + std::to_string(minor) + " of " +
                                  std::to_string(s.L->n) + ")",
                              column);
  }
  if (s.c.status < CHOLMOD_OK)
    throw Error("CHOLMOD factorization failed (status " + std::to_string(s.c.status) +
                (s.c.status == CHOLMOD_OUT_OF_MEMORY ? ": out of memory)" : ")"));
  supernodal = s.L->is_super != 0;
  rcond = cholmod_rcond(s.L, &s.c);
}

CholeskyFactor::~CholeskyFactor() = default;

long CholeskyFactor::size() const { return static_cast<long>(impl_->L->n); }

Eigen::MatrixXd CholeskyFactor::solve(const Eigen::MatrixXd& B) const {
  if (B.rows() != size())
    throw Error("Cholesky solve: right-hand side of size " + std::to_string(B.rows()) + " for a matrix of size " +
                std::to_string(size()));
  if (B.cols() == 0) return Eigen::MatrixXd(B.rows(), 0);
  cholmod_dense rhs{};
  rhs.nrow = static_cast<size_t>(B.rows());
  rhs.ncol = static_cast<size_t>(B.cols());
  rhs.nzmax = rhs.nrow * rhs.ncol;
  rhs.d = rhs.nrow;
  rhs.x = const_cast<double*>(B.data());
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  // The factor is not modified by a solve, but CHOLMOD's workspace lives in the common.
  const std::lock_guard<std::mutex> lock(impl_->solving);
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, impl_->L, &rhs, &impl_->c);
  if (!x) throw Error("CHOLMOD solve failed (status " + std::to_string(impl_->c.status) + ")");
  Eigen::MatrixXd X = Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(x->x), B.rows(), B.cols());
  cholmod_free_dense(&x, &impl_->c);
  return X;
}

CholmodResult cholmod_solve(const SparseMatrix& A, const Eigen::VectorXd& b, Ordering ordering) {
  if (A.rows() != A.cols() || A.rows() != b.size())
    throw Error("cholmod_solve: matrix " + std::to_string(A.rows()) + " x " + std::to_string(A.cols()) +
                " and right-hand side of size " + std::to_string(b.size()) + " do not match");
  if (!A.isCompressed()) throw Error("cholmod_solve: the matrix must be in compressed storage");
  const CholeskyFactor factor(A, ordering);
  CholmodResult r;
  r.ordering = factor.ordering;
  r.supernodal = factor.supernodal;
  r.factor_nonzeros = factor.factor_nonzeros;
  r.flops = factor.flops;
  r.rcond = factor.rcond;
  r.analyze_seconds = factor.analyze_seconds;
  r.factor_seconds = factor.factor_seconds;
  const auto t0 = std::chrono::steady_clock::now();
  r.x = factor.solve(b).col(0);
  r.solve_seconds = seconds_since(t0);
  if (!r.x.allFinite()) throw Error("CHOLMOD returned a non-finite solution (the matrix is numerically singular)");
  return r;
}

}  // namespace xfem
