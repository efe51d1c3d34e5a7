// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>

#include "xfem/solve/cholmod_solver.h"
#include "xfem/io/matrix_market.h"

namespace xfem {

/// What schur_solve did.
struct SchurStats {
  double schur_seconds = 0;   ///< forming S (the sparse right-hand sides K_se through the factor)
  double dense_seconds = 0;   ///< factorizing S and the back substitution
  long enriched = 0;          ///< size of S
};

/// Solves the block system
///     [ A    K_se ] [u_s]   [g_s]
///     [ K_es K_ee ] [u_e] = [g_e]
/// by eliminating u_s: S = K_ee - K_es A^-1 K_se (formed `block` columns of K_se at a time with
/// the one factorization of A), S u_e = g_e - K_es w_s, u_s = w_s - A^-1 K_se u_e, where
/// w_s = A^-1 g_s is given (the uncut body's solution, computed once). `K_ee` holds at least its
/// lower triangle. Returns (u_s; u_e). Throws xfem::Error when S is not positive definite (the
/// enriched DOFs let a piece of the body move freely) or a value is not finite.
Eigen::VectorXd schur_solve(const CholeskyFactor& A, const Eigen::VectorXd& w_s, const SparseMatrix& K_se,
                            const SparseMatrix& K_ee, const Eigen::VectorXd& g_e, SchurStats* stats = nullptr,
                            int block = 64);

}  // namespace xfem
