// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "xfem/core/error.h"
#include "xfem/system/linear_system.h"

namespace xfem {

/// The automatic backend of xfem-solve (docs/PERFORMANCE.md, "Choosing the backend"): "cholmod"
/// below a size measured on this problem class, "petsc" above it (CG + GAMG on MPI ranks). Cut
/// systems (with enriched DOFs) need about twice the CG iterations of uncut ones, so CHOLMOD
/// stays the quicker choice up to a larger size there.
constexpr long kPetscFromDofs = 100000;
constexpr long kPetscFromDofsEnriched = 150000;
/// Inline (as automatic_processes): xfem-solve decides without linking PETSc, whose libraries it
/// loads only when the PETSc backend runs (xfem-solve-petsc).
inline std::string automatic_backend(long dofs, bool enriched) {
  return dofs >= (enriched ? kPetscFromDofsEnriched : kPetscFromDofs) ? "petsc" : "cholmod";
}

/// The automatic number of PETSc processes: one per kDofsPerProcess DOFs, at least 1, at most `cores`.
constexpr long kDofsPerProcess = 60000;
inline int automatic_processes(long dofs, int cores) {
  const long wanted = (dofs + kDofsPerProcess - 1) / kDofsPerProcess;
  return static_cast<int>(std::max(1L, std::min<long>(std::max(cores, 1), wanted)));
}

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
  /// Called on every rank after each CG iteration with its number and the residual norm
  /// ||b - A x|| (newtons); for progress reports. May be empty.
  std::function<void(long iteration, double residual)> monitor;
};

struct PetscResult {
  Eigen::VectorXd u;               ///< 3N, full solution (constrained DOFs at their values), on rank 0 only (empty elsewhere)
  long iterations = 0;
  std::string converged_reason;    ///< PETSc's KSPConvergedReason name
  std::string preconditioner;      ///< "GAMG" or "fieldsplit (GAMG | Cholesky)": what was used
  int processes = 1;
  double setup_seconds = 0;        ///< matrix distribution + GAMG setup
  double solve_seconds = 0;        ///< CG iterations
  /// ||(K u - f)_f|| / ||f_f - K_fc u_c|| over the free DOFs (as xfem::relative_residual), on every rank
  double relative_residual = 0;
};

/// K distributed over the ranks of PETSC_COMM_WORLD: each rank holds a contiguous block of rows
/// made of whole 3-vectors (3-row blocks, AIJ with block size 3), the fixed DOFs still in.
class PetscMatrix {
 public:
  PetscMatrix();
  ~PetscMatrix();
  PetscMatrix(PetscMatrix&&) noexcept;
  PetscMatrix& operator=(PetscMatrix&&) noexcept;
  struct Impl;
  Impl& impl() { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

/// Loads K from a PETSc binary file (MatLoad: every rank reads only its rows) of 3N rows. Checks
/// the header and the file size first, and that K holds only finite values; throws xfem::Error
/// naming `path` otherwise. Needs a live PetscSession.
PetscMatrix petsc_load_matrix(const std::string& path, long dofs);

/// Distributes a K every rank holds whole (both triangles), e.g. read from Matrix Market.
PetscMatrix petsc_matrix(const SparseMatrix& K);

/// The diagonal of K, whole, on every rank (for the checks of enriched DOFs without support).
Eigen::VectorXd petsc_diagonal(PetscMatrix& K);

/// CG did not converge (petsc_solve): its message names PETSc's reason. Collective: every rank
/// throws it alike. xfem-newton takes it for a tangent that is not positive definite (projected
/// tangent, then a halved load step); xfem-solve reports it as any Error.
class PetscNotConverged : public Error {
 public:
  using Error::Error;
};

/// Rank 0's `v` (its length `size`; ignored elsewhere) on every rank (MPI_Bcast): the ranks of
/// xfem-newton all continue from the same Newton update. Needs a live PetscSession.
Eigen::VectorXd petsc_broadcast(const Eigen::VectorXd& v, long size);

/// Solves K u = f, K given distributed in `K` (consumed: the elimination works in place), f,
/// the fixed DOFs and coordinates from `system` (its K is not used), with CG preconditioned by
/// GAMG (or, with options.enriched_block "direct" and enriched DOFs present, GAMG on the original
/// block and a direct solve on the enriched block). The Dirichlet DOFs are eliminated
/// symmetrically in place (MatZeroRowsColumns): their rows and columns become the diagonal K_dd,
/// the right-hand side K_dd u_d there and f_f - K_fc u_c elsewhere, so A stays SPD with block
/// size 3 (what GAMG's aggregation wants). Needs a live PetscSession.
/// Throws xfem::Error naming the reason when CG does not converge (diverged, indefinite
/// preconditioner or matrix, iteration limit).
PetscResult petsc_solve(PetscMatrix&& K, const LinearSystem& system, const PetscSolveOptions& options);

/// The same with `system.K` (whole on every rank) distributed first.
PetscResult petsc_solve(const LinearSystem& system, const PetscSolveOptions& options);

}  // namespace xfem
