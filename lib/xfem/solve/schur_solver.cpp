// SPDX-License-Identifier: MIT
#include "xfem/solve/schur_solver.h"

#include <Eigen/Cholesky>
#include <chrono>
#include <cmath>

#include "xfem/core/error.h"
#include "xfem/core/seconds_since.h"

namespace xfem {
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
