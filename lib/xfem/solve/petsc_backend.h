// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <string>

#include "xfem/core/json_io.h"
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

}  // namespace xfem
