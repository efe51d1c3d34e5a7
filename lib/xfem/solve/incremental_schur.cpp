// SPDX-License-Identifier: MIT
#include "xfem/solve/incremental_schur.h"

#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>

#include "xfem/core/blas_threads.h"
#include "xfem/core/error.h"
#include "xfem/core/parallel_for.h"
#include "xfem/core/seconds_since.h"

// LAPACK / BLAS (OpenBLAS behind CHOLMOD): the bordered Cholesky update is O(p^2 k) for p kept
// and k new rows, which wants an optimised triangular solve.
extern "C" {
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m, const int* n,
            const double* alpha, const double* a, const int* lda, double* b, const int* ldb);
void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha, const double* a,
            const int* lda, const double* beta, double* c, const int* ldc);
void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k, const double* alpha,
            const double* a, const int* lda, const double* b, const int* ldb, const double* beta, double* c,
            const int* ldc);
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
}

namespace xfem {
void IncrementalSchur::extend_region(const std::vector<int>& free_dofs, const std::function<void(double)>& progress,
                                     int block) {
  const long nf = A_.size();
  if (in_region_.empty()) in_region_.assign(static_cast<std::size_t>(nf), -1);
  std::vector<int> fresh;
  for (int f : free_dofs) {
    if (f < 0 || f >= nf) throw Error("IncrementalSchur: free DOF " + std::to_string(f) + " out of range");
    if (in_region_[f] >= 0) continue;
    in_region_[f] = static_cast<int>(region_.size() + fresh.size());
    fresh.push_back(f);
  }
  if (fresh.empty()) return;
  const long r0 = static_cast<long>(region_.size()), r1 = r0 + static_cast<long>(fresh.size());
  region_.insert(region_.end(), fresh.begin(), fresh.end());
  Eigen::MatrixXd G(r1, r1);
  G.topLeftCorner(r0, r0) = G_.topLeftCorner(r0, r0);
  G_.resize(0, 0);
  const long k = static_cast<long>(fresh.size());
  for (long j0 = 0; j0 < k; j0 += block) {
    const long nb = std::min<long>(block, k - j0);
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(nf, nb);
    for (long j = 0; j < nb; ++j) B(fresh[j0 + j], j) = 1.0;
    const Eigen::MatrixXd X = A_.solve(B);
    for (long j = 0; j < nb; ++j) {
      const long c = r0 + j0 + j;
      for (long i = 0; i < r1; ++i) G(i, c) = X(region_[i], j);
      for (long i = 0; i < r0; ++i) G(c, i) = G(i, c);  // the old rows of the new columns, by symmetry
    }
    if (progress) progress(double(j0 + nb) / k);
  }
  G_ = std::move(G);
}

namespace {
// A B for a dense A and a sparse B, neighbouring columns of B with the same rows (an enriched
// node's 3 components, a branch node's 4 functions: one support) multiplied together with A's
// columns gathered once for them: A (G, 5,436^2 doubles on the organ) is too large for the caches,
// and reading a column of it per non-zero of B dominated. The groups in threads: each writes its
// own columns of the result, computed alike on any thread, so the bits do not depend on the count.
Eigen::MatrixXd times_sparse(const Eigen::Ref<const Eigen::MatrixXd>& A, const SparseMatrix& B) {
  const long r = A.rows(), k = B.cols();
  const int* outer = B.outerIndexPtr();
  const int* inner = B.innerIndexPtr();
  std::vector<long> group_begin;  // first column of each group, then k
  for (long j = 0; j < k;) {
    group_begin.push_back(j);
    long j2 = j + 1;
    while (j2 < k && std::equal(inner + outer[j], inner + outer[j + 1], inner + outer[j2], inner + outer[j2 + 1])) ++j2;
    j = j2;
  }
  group_begin.push_back(k);
  Eigen::MatrixXd V(r, k);
  parallel_for(static_cast<long>(group_begin.size()) - 1, [&](long begin, long end) {
    Eigen::MatrixXd Ap, D;
    for (long gi = begin; gi < end; ++gi) {
      const long j = group_begin[gi], g = group_begin[gi + 1] - j, p = outer[j + 1] - outer[j];
      Ap.resize(r, p);
      for (long i = 0; i < p; ++i) Ap.col(i) = A.col(inner[outer[j] + i]);
      D.resize(p, g);
      for (long c = 0; c < g; ++c)
        for (long i = 0; i < p; ++i) D(i, c) = B.valuePtr()[outer[j + c] + i];
      V.middleCols(j, g).noalias() = Ap * D;
    }
  }, {}, 8);
  return V;
}
}  // namespace

void IncrementalSchur::reserve(long m) {
  if (m <= S_.rows()) return;
  const long cap = std::max<long>(m, S_.rows() + S_.rows() / 2);
  Eigen::MatrixXd S(cap, cap), L(cap, cap);
  S.topLeftCorner(m_, m_) = S_.topLeftCorner(m_, m_);
  L.topLeftCorner(m_, m_) = L_.topLeftCorner(m_, m_);
  S_ = std::move(S);
  L_ = std::move(L);
}

void IncrementalSchur::update(const std::vector<EnrichedColumn>& cols, IncrementalSchurStats* stats) {
  IncrementalSchurStats local;
  IncrementalSchurStats& st = stats ? *stats : local;
  st = IncrementalSchurStats();
  const long n = static_cast<long>(cols.size());
  // Which of the previous columns are kept (bitwise the same), which are new or changed.
  std::vector<char> kept(static_cast<std::size_t>(m_), 0);
  std::vector<long> added;
  for (long c = 0; c < n; ++c) {
    const auto it = position_.find(cols[c].key);
    if (it != position_.end() && columns_[it->second] == cols[c]) kept[it->second] = 1;
    else added.push_back(c);
  }
  long p = m_;  // the first S row that changes: the factor's rows before it stay
  for (long q = 0; q < m_; ++q)
    if (!kept[q]) {
      p = q;
      break;
    }
  auto t0 = std::chrono::steady_clock::now();
  {
    std::vector<int> reach;
    for (long c : added)
      for (const auto& e : cols[c].se) reach.push_back(e.first);
    const long before = region_size();
    extend_region(reach);
    st.region_added = region_size() - before;
  }
  st.region_seconds = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  // The new order: rows 0..p-1 as they were, the kept ones after p moved up, the new ones last.
  long m_kept = p;
  for (long q = p; q < m_; ++q) m_kept += kept[q];
  const long m = m_kept + static_cast<long>(added.size());
  st.kept = m_kept;
  st.added = static_cast<long>(added.size());
  st.removed = m_ - m_kept;
  reserve(m);
  {
    long w = p;
    for (long q = p; q < m_; ++q)
      if (kept[q]) {
        if (w != q) S_.col(w).head(m_) = S_.col(q).head(m_);
        ++w;
      }
    // The rows, column by column (contiguous in memory; a row of S spans m columns of stride
    // capacity: moved row by row, every element was a cache miss).
    std::vector<std::pair<long, long>> moves;  // (to, from), to < from, increasing
    w = p;
    for (long q = p; q < m_; ++q)
      if (kept[q]) {
        if (w != q) moves.emplace_back(w, q);
        ++w;
      }
    // Every column on its own: in threads, the same copies.
    if (!moves.empty()) {
      parallel_for(m_kept + p, [&](long begin, long end) {
        for (long c = begin; c < end; ++c) {
          double* x = c < m_kept ? S_.col(c).data() : L_.col(c - m_kept).data();
          for (const auto& [to, from] : moves) x[to] = x[from];
        }
      }, {}, 64);
    }
  }
  std::vector<EnrichedColumn> order;
  order.reserve(static_cast<std::size_t>(m));
  for (long q = 0; q < m_; ++q)
    if (kept[q]) order.push_back(std::move(columns_[q]));
  for (long c : added) order.push_back(cols[c]);
  columns_ = std::move(order);
  position_.clear();
  for (long q = 0; q < m; ++q) position_[columns_[q].key] = q;
  caller_.assign(static_cast<std::size_t>(n), 0);
  for (long c = 0; c < n; ++c) caller_[c] = position_.at(cols[c].key);
  m_ = m;

  // The new columns of S: K_ee - K_eR G K_Re, one product with G for all of them.
  const long k = m - m_kept;
  if (k > 0) {
    // Only G's rows up to the last region DOF these columns reach are read: a region ordered by the
    // step that first reaches a DOF (ProgressiveCut::prepare) puts a sweep's early steps in a small
    // corner of G.
    long r = 0;
    std::vector<Eigen::Triplet<double, int>> trip;
    for (long q = 0; q < m; ++q)
      for (const auto& e : columns_[q].se) {
        trip.emplace_back(in_region_[e.first], static_cast<int>(q), e.second);
        r = std::max<long>(r, in_region_[e.first] + 1);
      }
    SparseMatrix Kr(static_cast<int>(r), static_cast<int>(m));
    Kr.setFromTriplets(trip.begin(), trip.end());
    const SparseMatrix Kr_new = Kr.middleCols(static_cast<int>(m_kept), static_cast<int>(k));
    // The new rows of S, (K_eR G K_Re)(new, all) = (G K_R,new)^T K_Re: dense times sparse twice,
    // both on contiguous columns (the transposed sparse product would gather rows).
    const Eigen::MatrixXd Vt = times_sparse(G_.topRows(r), Kr_new).transpose();  // k x r
    const Eigen::MatrixXd Wt = times_sparse(Vt, Kr);                    // k x m: row j = new row m_kept + j
    for (long q = 0; q < m; ++q) S_.col(q).segment(m_kept, k) = -Wt.col(q);
    for (long j = 0; j < k; ++j) {
      const long a = m_kept + j;
      for (const auto& e : columns_[a].ee) {
        const auto it = position_.find(e.first);
        if (it != position_.end()) S_(a, it->second) += e.second;
      }
    }
  }
  st.columns_seconds = seconds_since(t0);

  // The factor: rows 0..p-1 kept; the new rows' part left of p by a triangular solve; the trailing
  // block S(p:, p:) - L(p:, :p) L(p:, :p)^T factorized.
  t0 = std::chrono::steady_clock::now();
  const int ld = static_cast<int>(L_.rows());
  // The two O(p^2 k) and O(t^2 p) products in a few threads of ours, each block on one BLAS
  // thread: OpenBLAS's own threads would have its caller spin on sched_yield while it waits for
  // them (the core the frames want, xfem-sweep). The blocks do not depend on the thread count, so
  // neither do the bits.
  const BlasThreads one_blas_thread(1);
  if (k > 0 && p > 0) {
    // L(new, :p) = S(new, :p) L(:p, :p)^-T, in place, by blocks of rows.
    L_.block(m_kept, 0, k, p) = S_.block(m_kept, 0, k, p);
    const int pi = static_cast<int>(p);
    const long block = std::max<long>(64, (k + 1) / 2);  // rows per triangular solve: two wide ones
    parallel_for((k + block - 1) / block, [&](long begin, long end) {
      for (long b = begin; b < end; ++b) {
        const int rows = static_cast<int>(std::min(block, k - b * block));
        const double one = 1.0;
        dtrsm_("R", "L", "T", "N", &rows, &pi, &one, L_.data(), &ld, &L_(m_kept + b * block, 0), &ld);
      }
    }, {}, 1);
  }
  const long t = m - p;
  st.refactored = t;
  if (t > 0) {
    L_.block(p, p, t, t) = S_.block(p, p, t, t);
    if (p > 0) {
      // L(p:, p:) -= L(p:, :p) L(p:, :p)^T, lower triangle, with the rows split in halves a, b:
      // [aa; ba bb] -= [A A^T; B A^T, B B^T]: the two triangles in one thread, the square in the other.
      const int pi = static_cast<int>(p), ha = static_cast<int>(t / 2), hb = static_cast<int>(t - t / 2);
      double* A = &L_(p, 0);
      double* B = &L_(p + ha, 0);
      parallel_for(2, [&](long begin, long end) {
        const double minus = -1.0, one = 1.0;
        for (long task = begin; task < end; ++task) {
          if (task == 0) {
            if (ha > 0) dsyrk_("L", "N", &ha, &pi, &minus, A, &ld, &one, &L_(p, p), &ld);
            dsyrk_("L", "N", &hb, &pi, &minus, B, &ld, &one, &L_(p + ha, p + ha), &ld);
          } else if (ha > 0) {
            dgemm_("N", "T", &hb, &ha, &pi, &minus, B, &ld, A, &ld, &one, &L_(p + ha, p), &ld);
          }
        }
      }, {}, 1);
    }
    const int ti = static_cast<int>(t);
    int info = 0;
    dpotrf_("L", &ti, &L_(p, p), &ld, &info);
    if (info != 0)
      throw Error("the enriched block's Schur complement is not positive definite: a piece of the cut body can move "
                  "freely (no Dirichlet condition on it) or an enrichment is degenerate");
  }
  st.factor_seconds = seconds_since(t0);
}

Eigen::VectorXd IncrementalSchur::solve(const Eigen::VectorXd& r) const {
  if (r.size() != static_cast<long>(caller_.size())) throw Error("IncrementalSchur::solve: right-hand side of the wrong size");
  Eigen::VectorXd y(m_);
  for (long c = 0; c < r.size(); ++c) y[caller_[c]] = r[c];
  const auto L = L_.topLeftCorner(m_, m_).triangularView<Eigen::Lower>();
  L.solveInPlace(y);
  L.transpose().solveInPlace(y);
  Eigen::VectorXd x(r.size());
  for (long c = 0; c < r.size(); ++c) x[c] = y[caller_[c]];
  if (!x.allFinite()) throw Error("the Schur complement solve gave a non-finite solution (numerically singular)");
  return x;
}

}  // namespace xfem
