// SPDX-License-Identifier: MIT
#include "xfem/petsc_solver.h"

#include "xfem/error.h"

#if XFEM_HAVE_PETSC
#include <petscksp.h>

#include <Eigen/QR>
#include <chrono>
#endif

namespace xfem {

#if XFEM_HAVE_PETSC
namespace {

void check(PetscErrorCode code, const char* what) {
  if (code != 0) throw Error(std::string("PETSc: ") + what + " failed (PETSc error " + std::to_string(code) + ")");
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Owned PETSc objects, destroyed on every path.
struct Objects {
  Mat A = nullptr;
  Vec x = nullptr, b = nullptr, all = nullptr;
  KSP ksp = nullptr;
  MatNullSpace near_null = nullptr;
  VecScatter scatter = nullptr;
  std::vector<Vec> modes;
  ~Objects() {
    for (Vec& v : modes) VecDestroy(&v);
    if (near_null) MatNullSpaceDestroy(&near_null);
    if (scatter) VecScatterDestroy(&scatter);
    if (ksp) KSPDestroy(&ksp);
    if (all) VecDestroy(&all);
    if (x) VecDestroy(&x);
    if (b) VecDestroy(&b);
    if (A) MatDestroy(&A);
  }
};

// The 6 rigid-body modes of the original DOFs (translations, rotations about the centroid),
// zero on enriched DOFs, orthonormalised (MatNullSpaceCreate requires it). 3N x 6.
// With `enriched_translations`, each enriched 3-vector also gets the three translations (the
// relative slip of the two sides of the cut, a low-energy motion), so that GAMG's coarse spaces
// represent the enriched DOFs too instead of leaving them to the smoother alone.
Eigen::MatrixXd rigid_modes(const LinearSystem& s, bool enriched_translations) {
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(3 * s.n, 6);
  if (enriched_translations)
    for (long k = s.np; k < s.n; ++k)
      for (int i = 0; i < 3; ++i) R(3 * k + i, i) = 1;
  const Eigen::RowVector3d c = s.coordinates.colwise().mean();
  for (long k = 0; k < s.np; ++k) {
    const Eigen::RowVector3d p = s.coordinates.row(k) - c;
    for (int i = 0; i < 3; ++i) R(3 * k + i, i) = 1;
    R(3 * k + 0, 3) = -p.y(), R(3 * k + 1, 3) = p.x();
    R(3 * k + 1, 4) = -p.z(), R(3 * k + 2, 4) = p.y();
    R(3 * k + 0, 5) = p.z(), R(3 * k + 2, 5) = -p.x();
  }
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(R);
  return qr.householderQ() * Eigen::MatrixXd::Identity(R.rows(), 6);
}

}  // namespace

PetscSession::PetscSession() {
  check(PetscInitializeNoArguments(), "PetscInitialize");
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
  MPI_Comm_size(PETSC_COMM_WORLD, &size_);
}

PetscSession::~PetscSession() { PetscFinalize(); }

PetscResult petsc_solve(const LinearSystem& s, const PetscSolveOptions& options) {
  check_linear_system(s, "petsc_solve");
  PetscResult r;
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &r.processes);
  const auto t_setup = std::chrono::steady_clock::now();

  // 1. Symmetric elimination in place (rows and columns of fixed DOFs -> diagonal).
  const long n = 3 * s.n;
  std::vector<double> fixed_value(n, 0.0);
  std::vector<char> is_fixed(n, 0);
  for (std::size_t k = 0; k < s.fixed.size(); ++k) {
    is_fixed[s.fixed[k]] = 1;
    fixed_value[s.fixed[k]] = s.fixed_values[k];
  }
  const Eigen::VectorXd diag = s.K.diagonal();
  const auto pivot = [&](long d) { return diag[d] > 0 ? diag[d] : 1.0; };

  // 2. This rank's rows: a contiguous block of whole 3-vectors.
  const long blocks = s.n, mine = blocks / r.processes + (rank < blocks % r.processes ? 1 : 0);
  const long first_block = rank * (blocks / r.processes) + std::min<long>(rank, blocks % r.processes);
  const long r0 = 3 * first_block, r1 = r0 + 3 * mine;
  std::vector<PetscInt> d_nnz(r1 - r0, 0), o_nnz(r1 - r0, 0);
  for (long row = r0; row < r1; ++row) {
    if (is_fixed[row]) {
      d_nnz[row - r0] = 1;
      continue;
    }
    for (SparseMatrix::InnerIterator it(s.K, static_cast<int>(row)); it; ++it)  // column = row (symmetric)
      if (!is_fixed[it.row()]) ++(it.row() >= r0 && it.row() < r1 ? d_nnz : o_nnz)[row - r0];
  }
  Objects o;
  const MPI_Comm comm = PETSC_COMM_WORLD;
  check(MatCreate(comm, &o.A), "MatCreate");
  check(MatSetSizes(o.A, r1 - r0, r1 - r0, n, n), "MatSetSizes");
  check(MatSetType(o.A, MATAIJ), "MatSetType");
  check(MatSetBlockSize(o.A, 3), "MatSetBlockSize");
  check(MatSeqAIJSetPreallocation(o.A, 0, d_nnz.data()), "MatSeqAIJSetPreallocation");
  check(MatMPIAIJSetPreallocation(o.A, 0, d_nnz.data(), 0, o_nnz.data()), "MatMPIAIJSetPreallocation");
  std::vector<PetscInt> cols;
  std::vector<PetscScalar> vals;
  check(MatCreateVecs(o.A, &o.x, &o.b), "MatCreateVecs");
  PetscScalar* bb = nullptr;
  check(VecGetArray(o.b, &bb), "VecGetArray");
  for (long row = r0; row < r1; ++row) {
    cols.clear();
    vals.clear();
    double rhs = s.f[row];
    if (is_fixed[row]) {
      cols.push_back(static_cast<PetscInt>(row));
      vals.push_back(pivot(row));
      rhs = pivot(row) * fixed_value[row];
    } else {
      for (SparseMatrix::InnerIterator it(s.K, static_cast<int>(row)); it; ++it) {
        if (is_fixed[it.row()]) {
          rhs -= it.value() * fixed_value[it.row()];
        } else {
          cols.push_back(static_cast<PetscInt>(it.row()));
          vals.push_back(it.value());
        }
      }
    }
    bb[row - r0] = rhs;
    const PetscInt prow = static_cast<PetscInt>(row);
    check(MatSetValues(o.A, 1, &prow, static_cast<PetscInt>(cols.size()), cols.data(), vals.data(), INSERT_VALUES),
          "MatSetValues");
  }
  check(VecRestoreArray(o.b, &bb), "VecRestoreArray");
  check(MatAssemblyBegin(o.A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(o.A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  check(MatSetOption(o.A, MAT_SPD, PETSC_TRUE), "MatSetOption");

  // 3. Near-null space: the rigid-body modes, the coarse space GAMG must represent. With the
  //    field split, GAMG sees only the original block: the modes restricted to it (still
  //    orthonormal, their enriched rows being 0), composed with its index set, where
  //    PCFIELDSPLIT looks for them ("nearnullspace").
  if (options.enriched_block != "gamg" && options.enriched_block != "direct")
    throw Error("unknown enriched-block treatment '" + options.enriched_block + "' (gamg or direct)");
  const bool split = options.enriched_block == "direct" && s.n > s.np;
  const long orig_end = 3 * s.np;  // the original DOFs are 0 .. 3 NP-1 (whole 3-vectors)
  const long o0 = std::min(r0, orig_end), o1 = std::min(r1, orig_end);  // this rank's original rows
  IS is_orig = nullptr, is_enriched = nullptr;
  struct IsGuard {
    IS* a; IS* b;
    ~IsGuard() { if (*a) ISDestroy(a); if (*b) ISDestroy(b); }
  } is_guard{&is_orig, &is_enriched};
  if (split) {
    check(ISCreateStride(comm, o1 - o0, o0, 1, &is_orig), "ISCreateStride (original DOFs)");
    check(ISCreateStride(comm, (r1 - r0) - (o1 - o0), std::max(r0, orig_end), 1, &is_enriched),
          "ISCreateStride (enriched DOFs)");
    check(ISSetBlockSize(is_orig, 3), "ISSetBlockSize");
    check(ISSetBlockSize(is_enriched, 3), "ISSetBlockSize");
  }
  if (options.near_null_space == "rigid" || options.near_null_space == "rigid-enriched") {
    if (s.coordinates.size() == 0)
      throw Error("the PETSc backend's rigid-body near-null space needs the mesh coordinates (coordinates.mtx in the "
                  "system directory); use --near-null-space none to go without");
    const Eigen::MatrixXd R = rigid_modes(s, options.near_null_space == "rigid-enriched" && !split);
    o.modes.resize(6, nullptr);
    for (int m = 0; m < 6; ++m) {
      if (split) {
        check(VecCreateMPI(comm, o1 - o0, orig_end, &o.modes[m]), "VecCreateMPI");
        check(VecSetBlockSize(o.modes[m], 3), "VecSetBlockSize");
      } else {
        check(VecDuplicate(o.x, &o.modes[m]), "VecDuplicate");
      }
      PetscScalar* a = nullptr;
      check(VecGetArray(o.modes[m], &a), "VecGetArray");
      const long end = split ? o1 : r1;
      for (long row = r0; row < end; ++row) a[row - r0] = R(row, m);
      check(VecRestoreArray(o.modes[m], &a), "VecRestoreArray");
    }
    check(MatNullSpaceCreate(comm, PETSC_FALSE, 6, o.modes.data(), &o.near_null), "MatNullSpaceCreate");
    if (split)
      check(PetscObjectCompose(reinterpret_cast<PetscObject>(is_orig), "nearnullspace",
                               reinterpret_cast<PetscObject>(o.near_null)), "PetscObjectCompose");
    else
      check(MatSetNearNullSpace(o.A, o.near_null), "MatSetNearNullSpace");
  } else if (options.near_null_space != "none") {
    throw Error("unknown near-null space '" + options.near_null_space + "' (rigid, rigid-enriched or none)");
  }

  // 4. CG + GAMG (or the field split), the tolerance on the true (unpreconditioned) residual.
  check(KSPCreate(comm, &o.ksp), "KSPCreate");
  check(KSPSetOperators(o.ksp, o.A, o.A), "KSPSetOperators");
  check(KSPSetType(o.ksp, KSPCG), "KSPSetType");
  PC pc = nullptr;
  check(KSPGetPC(o.ksp, &pc), "KSPGetPC");
  if (split) {
    // Sub-solver choices as option defaults, so that PETSC_OPTIONS can still override them.
    const auto default_option = [](const char* name, const char* value) {
      PetscBool set = PETSC_FALSE;
      check(PetscOptionsHasName(nullptr, nullptr, name, &set), "PetscOptionsHasName");
      if (!set) check(PetscOptionsSetValue(nullptr, name, value), "PetscOptionsSetValue");
    };
    default_option("-fieldsplit_original_ksp_type", "preonly");
    default_option("-fieldsplit_original_pc_type", "gamg");
    default_option("-fieldsplit_enriched_ksp_type", "preonly");
    // The enriched block is small (a few % of the DOFs) but badly conditioned: factor it whole,
    // on every rank (PCREDUNDANT; on one rank that is a plain factorization).
    default_option("-fieldsplit_enriched_pc_type", "redundant");
    default_option("-fieldsplit_enriched_redundant_pc_type", "cholesky");
    default_option("-fieldsplit_enriched_redundant_pc_factor_mat_ordering_type", "nd");
    check(PCSetType(pc, PCFIELDSPLIT), "PCSetType");
    check(PCFieldSplitSetIS(pc, "original", is_orig), "PCFieldSplitSetIS (original DOFs)");
    check(PCFieldSplitSetIS(pc, "enriched", is_enriched), "PCFieldSplitSetIS (enriched DOFs)");
    check(PCFieldSplitSetType(pc, PC_COMPOSITE_SYMMETRIC_MULTIPLICATIVE), "PCFieldSplitSetType");
    r.preconditioner = "fieldsplit (GAMG | Cholesky)";
  } else {
    check(PCSetType(pc, PCGAMG), "PCSetType");
    r.preconditioner = "GAMG";
  }
  check(KSPSetNormType(o.ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  check(KSPSetTolerances(o.ksp, options.rtol, 0.0, PETSC_DEFAULT, options.max_iterations), "KSPSetTolerances");
  check(KSPSetFromOptions(o.ksp), "KSPSetFromOptions");
  check(KSPSetUp(o.ksp), split ? "KSPSetUp (field split)" : "KSPSetUp (GAMG setup)");
  if (split) {  // the splits' own setup (GAMG hierarchy, factorization) belongs to the setup time too
    PetscInt count = 0;
    KSP* sub = nullptr;
    check(PCFieldSplitGetSubKSP(pc, &count, &sub), "PCFieldSplitGetSubKSP");
    for (PetscInt k = 0; k < count; ++k)
      check(KSPSetUp(sub[k]),
            k == 0 ? "KSPSetUp (original block: GAMG setup)" : "KSPSetUp (enriched block: factorization)");
    PetscFree(sub);
  }
  r.setup_seconds = seconds_since(t_setup);

  const auto t_solve = std::chrono::steady_clock::now();
  check(KSPSolve(o.ksp, o.b, o.x), "KSPSolve");
  r.solve_seconds = seconds_since(t_solve);
  PetscInt iterations = 0;
  KSPConvergedReason reason;
  check(KSPGetIterationNumber(o.ksp, &iterations), "KSPGetIterationNumber");
  check(KSPGetConvergedReason(o.ksp, &reason), "KSPGetConvergedReason");
  r.iterations = iterations;
  r.converged_reason = KSPConvergedReasons[reason];
  if (reason < 0)
    throw Error("PETSc CG + " + r.preconditioner + " did not converge (" + r.converged_reason + " after " +
                std::to_string(iterations) +
                " iterations): the system may be singular (a loose piece, tiny enriched support) or need more "
                "iterations (--max-iterations)");

  // 5. Every rank gets the whole solution; the fixed DOFs carry their values exactly.
  check(VecScatterCreateToAll(o.x, &o.scatter, &o.all), "VecScatterCreateToAll");
  check(VecScatterBegin(o.scatter, o.x, o.all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  check(VecScatterEnd(o.scatter, o.x, o.all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  const PetscScalar* xa = nullptr;
  check(VecGetArrayRead(o.all, &xa), "VecGetArrayRead");
  r.u = Eigen::Map<const Eigen::VectorXd>(xa, n);
  check(VecRestoreArrayRead(o.all, &xa), "VecRestoreArrayRead");
  for (std::size_t k = 0; k < s.fixed.size(); ++k) r.u[s.fixed[k]] = s.fixed_values[k];
  if (!r.u.allFinite()) throw Error("PETSc returned a non-finite solution (the system is singular)");
  return r;
}

#else

PetscSession::PetscSession() {
  throw Error("this build has no PETSc (CMake did not find it): use --backend cholmod, or install libpetsc-real-dev "
              "and rebuild");
}
PetscSession::~PetscSession() = default;
PetscResult petsc_solve(const LinearSystem&, const PetscSolveOptions&) {
  throw Error("this build has no PETSc: use --backend cholmod");
}

#endif

}  // namespace xfem
