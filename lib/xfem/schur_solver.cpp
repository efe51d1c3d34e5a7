// SPDX-License-Identifier: MIT
#include "xfem/schur_solver.h"

#include <cholmod.h>

#include <Eigen/Cholesky>
#include <chrono>
#include <cmath>

#include "xfem/error.h"

namespace xfem {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

struct CholeskyFactor::Impl {
  cholmod_common c;
  cholmod_factor* L = nullptr;
  Impl() { cholmod_start(&c); }
  ~Impl() {
    if (L) cholmod_free_factor(&L, &c);
    cholmod_finish(&c);
  }
};

CholeskyFactor::CholeskyFactor(const SparseMatrix& A_in, Ordering order) : impl_(std::make_unique<Impl>()) {
  if (A_in.rows() != A_in.cols()) throw Error("CholeskyFactor: the matrix is not square");
  if (!A_in.isCompressed()) throw Error("CholeskyFactor: the matrix must be in compressed storage");
  // A view of Eigen's compressed columns, as in cholmod_solve: CHOLMOD reads the lower triangle.
  SparseMatrix& A = const_cast<SparseMatrix&>(A_in);
  cholmod_sparse a{};
  a.nrow = a.ncol = static_cast<size_t>(A.rows());
  a.nzmax = static_cast<size_t>(A.nonZeros());
  a.p = A.outerIndexPtr();
  a.i = A.innerIndexPtr();
  a.x = A.valuePtr();
  a.stype = -1;
  a.itype = CHOLMOD_INT;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;
  a.packed = 1;
  Impl& s = *impl_;
  s.c.print = 0;
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
  t0 = std::chrono::steady_clock::now();
  cholmod_factorize(&a, s.L, &s.c);
  factor_seconds = seconds_since(t0);
  if (s.c.status == CHOLMOD_NOT_POSDEF || s.L->minor < s.L->n) {
    const long minor = static_cast<long>(s.L->minor);
    const long column = s.L->Perm ? static_cast<const int*>(s.L->Perm)[minor] : minor;
    throw NotPositiveDefinite("the matrix is not positive definite: the Cholesky factorization broke down at column " +
                                  std::to_string(column),
                              column);
  }
  if (s.c.status < CHOLMOD_OK)
    throw Error("CHOLMOD factorization failed (status " + std::to_string(s.c.status) +
                (s.c.status == CHOLMOD_OUT_OF_MEMORY ? ": out of memory)" : ")"));
}

CholeskyFactor::~CholeskyFactor() = default;

long CholeskyFactor::size() const { return static_cast<long>(impl_->L->n); }

Eigen::MatrixXd CholeskyFactor::solve(const Eigen::MatrixXd& B) const {
  if (B.rows() != size()) throw Error("CholeskyFactor::solve: right-hand side of the wrong size");
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
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, impl_->L, &rhs, &impl_->c);
  if (!x) throw Error("CHOLMOD solve failed (status " + std::to_string(impl_->c.status) + ")");
  Eigen::MatrixXd X = Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(x->x), B.rows(), B.cols());
  cholmod_free_dense(&x, &impl_->c);
  return X;
}

Eigen::VectorXd schur_solve(const CholeskyFactor& A, const Eigen::VectorXd& w_s, const SparseMatrix& K_se,
                            const SparseMatrix& K_ee, const Eigen::VectorXd& g_e, SchurStats* stats, int block) {
  const long ns = A.size(), ne = K_ee.rows();
  if (w_s.size() != ns || K_se.rows() != ns || K_se.cols() != ne || K_ee.cols() != ne || g_e.size() != ne)
    throw Error("schur_solve: block sizes do not match");
  SchurStats local;
  SchurStats& st = stats ? *stats : local;
  st.enriched = ne;
  Eigen::VectorXd u(ns + ne);
  if (ne == 0) {
    u = w_s;
    return u;
  }
  auto t0 = std::chrono::steady_clock::now();
  // S = K_ee - K_es A^-1 K_se, lower triangle: column block j of Y = A^-1 K_se gives columns j of S.
  const SparseMatrix K_es = K_se.transpose();
  Eigen::MatrixXd S = Eigen::MatrixXd(SparseMatrix(K_ee.selfadjointView<Eigen::Lower>()));
  for (long j0 = 0; j0 < ne; j0 += block) {
    const long nb = std::min<long>(block, ne - j0);
    const Eigen::MatrixXd B = Eigen::MatrixXd(K_se.middleCols(j0, nb));
    const Eigen::MatrixXd Y = A.solve(B);
    S.middleCols(j0, nb) -= K_es * Y;
  }
  st.schur_seconds = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  const Eigen::LLT<Eigen::MatrixXd> llt(S.selfadjointView<Eigen::Lower>());
  if (llt.info() != Eigen::Success)
    throw Error("the enriched block's Schur complement is not positive definite: a piece of the cut body can move "
                "freely (no Dirichlet condition on it) or an enrichment is degenerate");
  const Eigen::VectorXd u_e = llt.solve(g_e - K_es * w_s);
  u.head(ns) = w_s - A.solve(Eigen::MatrixXd(K_se * u_e)).col(0);
  u.tail(ne) = u_e;
  st.dense_seconds = seconds_since(t0);
  if (!u.allFinite()) throw Error("the Schur complement solve gave a non-finite solution (numerically singular)");
  return u;
}

}  // namespace xfem
