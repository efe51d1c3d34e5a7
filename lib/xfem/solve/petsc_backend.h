// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "xfem/core/json_io.h"
#include "xfem/solve/contact_solve.h"
#include "xfem/solve/petsc_solver.h"
#include "xfem/system/linear_system.h"

namespace xfem {

/// K of the system directory `dir` distributed over the ranks for xfem-solve's PETSc backend.
/// From a binary system every rank loads only its rows; `s` (read without K) then gets K's
/// diagonal in K's place, which is all the checks of enriched DOFs need (a zero diagonal of the
/// positive semi-definite K is a zero row). Otherwise `s.K` (read whole) is distributed.
/// `*nonzeros`: the non-zeros of K's lower triangle. Needs a live PetscSession.
PetscMatrix distribute_system_matrix(const std::string& dir, LinearSystem& s, long* nonzeros);

/// xfem-solve's PETSc backend: CG preconditioned by GAMG (`options`; enriched_block "auto":
/// "direct" when `s` has enriched DOFs, else "gamg") on K distributed in `K`, ticking on stderr
/// while it runs when `ticking`, logging each iteration when `verbose`. Only the `root` rank logs.
/// Adds its fields to `report` (preconditioner, processes, iterations, timings) and returns the
/// full 3N solution (on rank 0; empty elsewhere); `*residual` = its relative residual on the free
/// DOFs, on every rank.
Eigen::VectorXd solve_with_petsc(PetscMatrix&& K, const LinearSystem& s, PetscSolveOptions options, bool root,
                                 bool verbose, bool ticking, Json& report, double* residual);

/// xfem-solve's PETSc backend for the contact iterations (solve_with_contact, solve_with_friction):
/// the solve without contact is solve_with_petsc's (its report fields); each penalised solve is
/// petsc_solve with the same options on the penalised K, which every rank holds whole (the
/// iteration runs on every rank alike) and distributes, each rank taking its rows. The penalty
/// terms G^T diag(kappa) G (and friction's T^T D T) act on enriched DOFs only (the gap is the jump
/// of the enriched functions), so with enriched_block "direct" they lie inside the block that is
/// factorized: GAMG sees the original block unchanged. The solution is broadcast from rank 0.
class PetscPenalisedSolver : public PenalisedSolver {
 public:
  PetscPenalisedSolver(PetscSolveOptions options, bool root, bool verbose, bool ticking);
  Eigen::VectorXd solve_unpenalised(const LinearSystem& s, Json& report, double* residual) override;
  Eigen::VectorXd solve(const LinearSystem& s, const SparseMatrix& K, const Eigen::VectorXd& f, const char* what,
                        double* residual) override;
  bool iterative() const override { return true; }
  /// CG iterations of each solve, the first the one without contact.
  const std::vector<long>& iterations() const { return iterations_; }

 private:
  PetscSolveOptions options_;
  bool root_, verbose_, ticking_;
  LinearSystem system_;  // n, coordinates, the Dirichlet data; f of the solve at hand (no K)
  std::vector<long> iterations_;
};

}  // namespace xfem
