// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "xfem/linear_system.h"

namespace xfem {

/// PETSc and MPI for the lifetime of the object (PetscInitialize / PetscFinalize), so that
/// `mpirun -np P xfem-solve --backend petsc` runs one process per rank. PETSc options come from
/// the environment (PETSC_OPTIONS="-ksp_view ..."), not the command line. Throws xfem::Error if
/// the library was built without PETSc (xfem::have_petsc in xfem/version.h says which).
class PetscSession {
 public:
  PetscSession();
  ~PetscSession();
  PetscSession(const PetscSession&) = delete;
  PetscSession& operator=(const PetscSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0, size_ = 1;
};

struct PetscSolveOptions {
  double rtol = 1e-10;        ///< stop when ||b - A x|| <= rtol ||b|| (unpreconditioned norm)
  int max_iterations = 10000;
  /// Near-null space for GAMG: "rigid" = the 6 rigid-body modes on the original DOFs (needs
  /// coordinates; enriched DOFs 0 in every mode), "rigid-enriched" = also the 3 translations on every
  /// enriched 3-vector (as "rigid" with enriched_block "direct", where GAMG sees only the original
  /// DOFs), "none" = GAMG's default (constants per component).
  std::string near_null_space = "rigid";
  /// How the preconditioner treats the enriched DOFs (3 NP .. 3N-1; docs/PERFORMANCE.md, "Solve:
  /// PETSc GAMG on cut systems"): "gamg" = one GAMG on the whole matrix; "direct" =
  /// PCFIELDSPLIT, symmetric multiplicative (block symmetric Gauss-Seidel, so CG keeps a symmetric
  /// preconditioner) over two splits: "original" (scalar DOFs 0 .. 3 NP-1, fixed ones included as
  /// their diagonal rows) with one GAMG V-cycle and the near-null space above, "enriched" with a
  /// sparse Cholesky factorization, redundant on every rank (PCREDUNDANT). A system without enriched
  /// DOFs always gets "gamg". Throws xfem::Error on another value. PETSc options in PETSC_OPTIONS (prefixes -fieldsplit_original_,
  /// -fieldsplit_enriched_, -pc_fieldsplit_type) override these choices.
  std::string enriched_block = "gamg";
};

struct PetscResult {
  Eigen::VectorXd u;               ///< 3N, full solution (constrained DOFs at their values), on every rank
  long iterations = 0;
  std::string converged_reason;    ///< PETSc's KSPConvergedReason name
  std::string preconditioner;      ///< "GAMG" or "fieldsplit (GAMG | Cholesky)": what was used
  int processes = 1;
  double setup_seconds = 0;        ///< matrix distribution + GAMG setup
  double solve_seconds = 0;        ///< CG iterations
};

/// Solves `system` (its fixed DOFs at their values) with CG preconditioned by GAMG (or, with
/// options.enriched_block "direct" and enriched DOFs present, GAMG on the original block and a
/// direct solve on the enriched block), every rank
/// holding the whole system and inserting its block of rows (3-row blocks: N 3-vectors). The
/// Dirichlet DOFs are eliminated symmetrically in place: their rows and columns become the
/// diagonal K_dd, the right-hand side K_dd u_d there and f_f - K_fc u_c elsewhere, so A stays
/// SPD with block size 3 (what GAMG's aggregation wants). Needs a live PetscSession.
/// Throws xfem::Error naming the reason when CG does not converge (diverged, indefinite
/// preconditioner or matrix, iteration limit).
PetscResult petsc_solve(const LinearSystem& system, const PetscSolveOptions& options);

}  // namespace xfem
