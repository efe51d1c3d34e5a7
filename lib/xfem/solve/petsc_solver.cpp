// SPDX-License-Identifier: MIT
#include "xfem/solve/petsc_solver.h"

#include <algorithm>

#include "xfem/core/error.h"
#include "xfem/io/petsc_binary.h"
#include "xfem/core/seconds_since.h"

#if XFEM_HAVE_PETSC
#include <petscksp.h>

#include <Eigen/QR>
#include <chrono>
#include <cmath>
#endif

namespace xfem {

#if XFEM_HAVE_PETSC
namespace {

void check(PetscErrorCode code, const char* what) {
  if (code != 0) throw Error(std::string("PETSc: ") + what + " failed (PETSc error " + std::to_string(code) + ")");
}

// Owned PETSc objects, destroyed on every path.
struct Objects {
  Mat A = nullptr;
  Vec x = nullptr, b = nullptr, all = nullptr, pivot = nullptr, residual = nullptr;
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
    if (pivot) VecDestroy(&pivot);
    if (residual) VecDestroy(&residual);
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

// This rank's rows: a contiguous block of whole 3-vectors [r0, r1).
std::pair<long, long> my_rows(long dofs) {
  int rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  const long blocks = dofs / 3, mine = blocks / size + (rank < blocks % size ? 1 : 0);
  const long first = rank * (blocks / size) + std::min<long>(rank, blocks % size);
  return {3 * first, 3 * (first + mine)};
}

// Sum over the ranks.
double global_sum(double local) {
  double sum = 0;
  MPI_Allreduce(&local, &sum, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  return sum;
}

PetscErrorCode monitor_iteration(KSP, PetscInt iteration, PetscReal residual, void* context) {
  const auto& monitor = *static_cast<const std::function<void(long, double)>*>(context);
  monitor(iteration, residual);
  return 0;
}

}  // namespace

struct PetscMatrix::Impl {
  Mat A = nullptr;
  ~Impl() {
    if (A) MatDestroy(&A);
  }
};

PetscMatrix::PetscMatrix() : impl_(std::make_unique<Impl>()) {}
PetscMatrix::~PetscMatrix() = default;
PetscMatrix::PetscMatrix(PetscMatrix&&) noexcept = default;
PetscMatrix& PetscMatrix::operator=(PetscMatrix&&) noexcept = default;

PetscSession::PetscSession() {
  check(PetscInitializeNoArguments(), "PetscInitialize");
  // Failures reach the user as one line from the caller (check() above), not as PETSc's traceback.
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
  MPI_Comm_size(PETSC_COMM_WORLD, &size_);
}

PetscSession::~PetscSession() { PetscFinalize(); }

PetscMatrix petsc_load_matrix(const std::string& path, long dofs) {
  // Every rank checks the header and the size (16 bytes and a seek): MatLoad's own failures
  // would come without the file's name.
  const PetscMatrixHeader h = read_petsc_matrix_header(path);
  if (h.rows != dofs || h.cols != dofs)
    throw Error(path + ": " + std::to_string(h.rows) + " x " + std::to_string(h.cols) + ", expected 3N x 3N = " +
                std::to_string(dofs) + " x " + std::to_string(dofs) + " (is this xfem-assemble output?)");
  PetscMatrix K;
  Mat& A = K.impl().A;
  const auto [r0, r1] = my_rows(dofs);
  PetscViewer viewer = nullptr;
  struct ViewerGuard {
    PetscViewer* v;
    ~ViewerGuard() { if (*v) PetscViewerDestroy(v); }
  } guard{&viewer};
  const MPI_Comm comm = PETSC_COMM_WORLD;
  check(PetscViewerCreate(comm, &viewer), "PetscViewerCreate");
  check(PetscViewerSetType(viewer, PETSCVIEWERBINARY), "PetscViewerSetType");
  check(PetscViewerFileSetMode(viewer, FILE_MODE_READ), "PetscViewerFileSetMode");
  check(PetscViewerBinarySetSkipInfo(viewer, PETSC_TRUE), "PetscViewerBinarySetSkipInfo");
  check(PetscViewerFileSetName(viewer, path.c_str()), ("opening " + path).c_str());
  check(MatCreate(comm, &A), "MatCreate");
  check(MatSetSizes(A, r1 - r0, r1 - r0, dofs, dofs), "MatSetSizes");
  check(MatSetType(A, MATAIJ), "MatSetType");
  check(MatSetBlockSize(A, 3), "MatSetBlockSize");
  if (MatLoad(A, viewer) != 0) throw Error(path + ": PETSc's MatLoad failed (corrupt row lengths or column indices?)");
  PetscReal norm = 0;
  check(MatNorm(A, NORM_FROBENIUS, &norm), "MatNorm");
  if (!std::isfinite(norm)) throw Error(path + ": K holds a non-finite value (is this xfem-assemble output?)");
  return K;
}

PetscMatrix petsc_matrix(const SparseMatrix& K_full) {
  const long dofs = K_full.rows();
  const auto [r0, r1] = my_rows(dofs);
  std::vector<PetscInt> d_nnz(r1 - r0, 0), o_nnz(r1 - r0, 0);
  for (long row = r0; row < r1; ++row)
    for (SparseMatrix::InnerIterator it(K_full, static_cast<int>(row)); it; ++it)  // column = row (symmetric)
      ++(it.row() >= r0 && it.row() < r1 ? d_nnz : o_nnz)[row - r0];
  PetscMatrix K;
  Mat& A = K.impl().A;
  check(MatCreate(PETSC_COMM_WORLD, &A), "MatCreate");
  check(MatSetSizes(A, r1 - r0, r1 - r0, dofs, dofs), "MatSetSizes");
  check(MatSetType(A, MATAIJ), "MatSetType");
  check(MatSetBlockSize(A, 3), "MatSetBlockSize");
  check(MatSeqAIJSetPreallocation(A, 0, d_nnz.data()), "MatSeqAIJSetPreallocation");
  check(MatMPIAIJSetPreallocation(A, 0, d_nnz.data(), 0, o_nnz.data()), "MatMPIAIJSetPreallocation");
  std::vector<PetscInt> cols;
  for (long row = r0; row < r1; ++row) {
    const int begin = K_full.outerIndexPtr()[row], end = K_full.outerIndexPtr()[row + 1];
    cols.assign(K_full.innerIndexPtr() + begin, K_full.innerIndexPtr() + end);
    const PetscInt prow = static_cast<PetscInt>(row);
    check(MatSetValues(A, 1, &prow, end - begin, cols.data(), K_full.valuePtr() + begin, INSERT_VALUES),
          "MatSetValues");
  }
  check(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  return K;
}

Eigen::VectorXd petsc_diagonal(PetscMatrix& K) {
  Vec d = nullptr, all = nullptr;
  VecScatter scatter = nullptr;
  struct Guard {
    Vec *d, *all;
    VecScatter* s;
    ~Guard() {
      if (*s) VecScatterDestroy(s);
      if (*all) VecDestroy(all);
      if (*d) VecDestroy(d);
    }
  } guard{&d, &all, &scatter};
  check(MatCreateVecs(K.impl().A, nullptr, &d), "MatCreateVecs");
  check(MatGetDiagonal(K.impl().A, d), "MatGetDiagonal");
  check(VecScatterCreateToAll(d, &scatter, &all), "VecScatterCreateToAll");
  check(VecScatterBegin(scatter, d, all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  check(VecScatterEnd(scatter, d, all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  PetscInt n = 0;
  check(VecGetSize(all, &n), "VecGetSize");
  const PetscScalar* a = nullptr;
  check(VecGetArrayRead(all, &a), "VecGetArrayRead");
  Eigen::VectorXd diag = Eigen::Map<const Eigen::VectorXd>(a, n);
  check(VecRestoreArrayRead(all, &a), "VecRestoreArrayRead");
  return diag;
}

Eigen::VectorXd petsc_broadcast(const Eigen::VectorXd& v, long size) {
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  Eigen::VectorXd out = rank == 0 ? v : Eigen::VectorXd(size);
  if (out.size() != size) throw Error("petsc_broadcast: " + std::to_string(out.size()) + " values, expected " +
                                      std::to_string(size));
  MPI_Bcast(out.data(), static_cast<int>(size), MPI_DOUBLE, 0, PETSC_COMM_WORLD);
  return out;
}

PetscResult petsc_solve(const LinearSystem& s, const PetscSolveOptions& options) {
  check_linear_system(s, "petsc_solve");
  return petsc_solve(petsc_matrix(s.K), s, options);
}

PetscResult petsc_solve(PetscMatrix&& K, const LinearSystem& s, const PetscSolveOptions& options) {
  PetscResult r;
  MPI_Comm_size(PETSC_COMM_WORLD, &r.processes);
  const auto t_setup = std::chrono::steady_clock::now();
  Objects o;
  o.A = K.impl().A;  // taken over: the elimination below changes it
  K.impl().A = nullptr;
  const long n = 3 * s.n;
  PetscInt global_rows = 0;
  check(MatGetSize(o.A, &global_rows, nullptr), "MatGetSize");
  if (global_rows != n || s.f.size() != n)
    throw Error("petsc_solve: K has " + std::to_string(global_rows) + " rows and f " + std::to_string(s.f.size()) +
                ", expected 3N = " + std::to_string(n));
  const auto [r0, r1] = my_rows(n);
  const MPI_Comm comm = PETSC_COMM_WORLD;

  // 1. Symmetric elimination in place: rows and columns of fixed DOFs -> their diagonal K_dd
  //    (1 where K_dd <= 0), b = f_f - K_fc u_c on the free rows, K_dd u_d on the fixed ones.
  std::vector<char> is_fixed(r1 - r0, 0);
  std::vector<PetscInt> my_fixed;
  check(MatCreateVecs(o.A, &o.x, &o.b), "MatCreateVecs");
  Vec& pivot = o.pivot;
  check(VecDuplicate(o.x, &pivot), "VecDuplicate");
  check(MatGetDiagonal(o.A, pivot), "MatGetDiagonal");
  PetscScalar *xx = nullptr, *bb = nullptr, *pp = nullptr;
  check(VecGetArray(o.x, &xx), "VecGetArray");
  check(VecGetArray(o.b, &bb), "VecGetArray");
  for (long row = r0; row < r1; ++row) xx[row - r0] = 0, bb[row - r0] = s.f[row];
  for (std::size_t k = 0; k < s.fixed.size(); ++k)
    if (s.fixed[k] >= r0 && s.fixed[k] < r1) {
      my_fixed.push_back(static_cast<PetscInt>(s.fixed[k]));
      is_fixed[s.fixed[k] - r0] = 1;
      xx[s.fixed[k] - r0] = s.fixed_values[k];
    }
  check(VecRestoreArray(o.x, &xx), "VecRestoreArray");
  check(VecRestoreArray(o.b, &bb), "VecRestoreArray");
  check(MatSetOption(o.A, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE), "MatSetOption");
  check(MatZeroRowsColumns(o.A, static_cast<PetscInt>(my_fixed.size()), my_fixed.data(), 1.0, o.x, o.b),
        "MatZeroRowsColumns");
  check(VecGetArray(pivot, &pp), "VecGetArray");
  check(VecGetArray(o.b, &bb), "VecGetArray");
  double b_free = 0;  // ||f_f - K_fc u_c||^2 on this rank, the residual's scale
  for (long row = r0; row < r1; ++row) {
    if (is_fixed[row - r0]) {
      if (!(pp[row - r0] > 0)) pp[row - r0] = 1.0;
      bb[row - r0] *= pp[row - r0];  // MatZeroRowsColumns put 1 * u_d there
    } else {
      b_free += bb[row - r0] * bb[row - r0];
    }
  }
  check(VecRestoreArray(o.b, &bb), "VecRestoreArray");
  check(VecRestoreArray(pivot, &pp), "VecRestoreArray");
  check(MatDiagonalSet(o.A, pivot, INSERT_VALUES), "MatDiagonalSet");
  check(MatSetOption(o.A, MAT_SPD, PETSC_TRUE), "MatSetOption");
  b_free = global_sum(b_free);

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
      throw Error("the PETSc backend's rigid-body near-null space needs the mesh coordinates (coordinates.petsc or "
                  "coordinates.mtx in the system directory); use --near-null-space none to go without");
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
    // The enriched block first: symmetric multiplicative then applies enriched, original,
    // enriched (block symmetric Gauss-Seidel), one GAMG V-cycle and two cheap Cholesky solves per
    // iteration, where original-first costs two V-cycles. On the 1M-tet beam (532k DOFs, 1 rank)
    // CG took 101 iterations and 21.7 s against 86 and 52.4 s (docs/PERFORMANCE.md).
    check(PCFieldSplitSetIS(pc, "enriched", is_enriched), "PCFieldSplitSetIS (enriched DOFs)");
    check(PCFieldSplitSetIS(pc, "original", is_orig), "PCFieldSplitSetIS (original DOFs)");
    check(PCFieldSplitSetType(pc, PC_COMPOSITE_SYMMETRIC_MULTIPLICATIVE), "PCFieldSplitSetType");
    r.preconditioner = "fieldsplit (Cholesky | GAMG | Cholesky)";
  } else {
    check(PCSetType(pc, PCGAMG), "PCSetType");
    r.preconditioner = "GAMG";
  }
  check(KSPSetNormType(o.ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  check(KSPSetTolerances(o.ksp, options.rtol, 0.0, PETSC_DEFAULT, options.max_iterations), "KSPSetTolerances");
  if (options.monitor)
    check(KSPMonitorSet(o.ksp, monitor_iteration, const_cast<std::function<void(long, double)>*>(&options.monitor),
                        nullptr),
          "KSPMonitorSet");
  check(KSPSetFromOptions(o.ksp), "KSPSetFromOptions");
  check(KSPSetUp(o.ksp), split ? "KSPSetUp (field split)" : "KSPSetUp (GAMG setup)");
  if (split) {  // the splits' own setup (GAMG hierarchy, factorization) belongs to the setup time too
    PetscInt count = 0;
    KSP* sub = nullptr;
    check(PCFieldSplitGetSubKSP(pc, &count, &sub), "PCFieldSplitGetSubKSP");
    for (PetscInt k = 0; k < count; ++k)
      check(KSPSetUp(sub[k]),
            k == 0 ? "KSPSetUp (enriched block: factorization)" : "KSPSetUp (original block: GAMG setup)");
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
    throw PetscNotConverged("PETSc CG + " + r.preconditioner + " did not converge (" + r.converged_reason + " after " +
                std::to_string(iterations) +
                " iterations): the system may be singular (a loose piece, tiny enriched support) or need more "
                "iterations (--max-iterations)");

  // 5. The residual of the free equations: A x - b there is (K u - f)_f, the fixed columns
  //    having moved into b.
  check(VecDuplicate(o.b, &o.residual), "VecDuplicate");
  check(MatMult(o.A, o.x, o.residual), "MatMult");
  check(VecAXPY(o.residual, -1.0, o.b), "VecAXPY");
  const PetscScalar* ra = nullptr;
  check(VecGetArrayRead(o.residual, &ra), "VecGetArrayRead");
  double res_free = 0;
  for (long row = r0; row < r1; ++row)
    if (!is_fixed[row - r0]) res_free += ra[row - r0] * ra[row - r0];
  check(VecRestoreArrayRead(o.residual, &ra), "VecRestoreArrayRead");
  res_free = global_sum(res_free);
  r.relative_residual = b_free > 0 ? std::sqrt(res_free / b_free) : std::sqrt(res_free);

  // 6. Rank 0 gets the whole solution; the fixed DOFs carry their values exactly.
  check(VecScatterCreateToZero(o.x, &o.scatter, &o.all), "VecScatterCreateToZero");
  check(VecScatterBegin(o.scatter, o.x, o.all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  check(VecScatterEnd(o.scatter, o.x, o.all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int finite = 1;
  if (rank == 0) {
    const PetscScalar* xa = nullptr;
    check(VecGetArrayRead(o.all, &xa), "VecGetArrayRead");
    r.u = Eigen::Map<const Eigen::VectorXd>(xa, n);
    check(VecRestoreArrayRead(o.all, &xa), "VecRestoreArrayRead");
    for (std::size_t k = 0; k < s.fixed.size(); ++k) r.u[s.fixed[k]] = s.fixed_values[k];
    finite = r.u.allFinite() && std::isfinite(r.relative_residual);
  }
  MPI_Bcast(&finite, 1, MPI_INT, 0, comm);
  if (!finite) throw Error("PETSc returned a non-finite solution (the system is singular)");
  return r;
}

#else

PetscSession::PetscSession() {
  throw Error("this build has no PETSc (CMake did not find it): use --backend cholmod, or install libpetsc-real-dev "
              "and rebuild");
}
PetscSession::~PetscSession() = default;
struct PetscMatrix::Impl {};
PetscMatrix::PetscMatrix() = default;
PetscMatrix::~PetscMatrix() = default;
PetscMatrix::PetscMatrix(PetscMatrix&&) noexcept = default;
PetscMatrix& PetscMatrix::operator=(PetscMatrix&&) noexcept = default;
PetscMatrix petsc_load_matrix(const std::string&, long) { throw Error("this build has no PETSc: use --backend cholmod"); }
PetscMatrix petsc_matrix(const SparseMatrix&) { throw Error("this build has no PETSc: use --backend cholmod"); }
Eigen::VectorXd petsc_diagonal(PetscMatrix&) { throw Error("this build has no PETSc: use --backend cholmod"); }
Eigen::VectorXd petsc_broadcast(const Eigen::VectorXd&, long) { throw Error("this build has no PETSc"); }
PetscResult petsc_solve(PetscMatrix&&, const LinearSystem&, const PetscSolveOptions&) {
  throw Error("this build has no PETSc: use --backend cholmod");
}
PetscResult petsc_solve(const LinearSystem&, const PetscSolveOptions&) {
  throw Error("this build has no PETSc: use --backend cholmod");
}

#endif

}  // namespace xfem
