// SPDX-License-Identifier: MIT
// Baseline for xfem-solve --backend petsc, on as many processes as it is started on (mpirun -np P):
// the bare PETSc calls on the same system/ directory (PETSc binary format): MatLoad of K.petsc
// (AIJ, block size 3, each rank its block of whole 3-vectors, as the tool), the Dirichlet DOFs
// eliminated by MatZeroRowsColumns (their diagonal kept, as the tool), MatNullSpaceCreateRigidBody
// from the coordinates, KSPCG + PCGAMG, unpreconditioned residual norm. PETSC_OPTIONS apply.
// Prints the timings on stdout (rank 0) as one JSON line. Usage: bare_petsc SYSTEM_DIR [RTOL]
// (the rigid-body modes need N = NP: an uncut system such as the reference beam).
#include <petscksp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "xfem/system/linear_system.h"

namespace {
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bare_petsc SYSTEM_DIR [RTOL]\n");
    return 2;
  }
  const double rtol = argc > 2 ? std::atof(argv[2]) : 1e-10;
  PetscInitializeNoArguments();
  int rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  const auto t_start = std::chrono::steady_clock::now();
  const xfem::LinearSystem s = xfem::read_linear_system(argv[1], false);  // all but K
  if (s.n != s.np || s.coordinates.size() == 0 || xfem::system_format(argv[1]) != xfem::SystemFormat::Petsc) {
    std::fprintf(stderr, "bare_petsc: needs an uncut system with coordinates in the PETSc binary format\n");
    return 1;
  }
  const PetscInt n = static_cast<PetscInt>(3 * s.n), blocks = static_cast<PetscInt>(s.n);
  const PetscInt mine = 3 * (blocks / size + (rank < blocks % size ? 1 : 0));
  Mat A;
  PetscViewer viewer;
  PetscViewerBinaryOpen(PETSC_COMM_WORLD, xfem::system_matrix_file(argv[1], xfem::SystemFormat::Petsc).c_str(),
                        FILE_MODE_READ, &viewer);
  MatCreate(PETSC_COMM_WORLD, &A);
  MatSetSizes(A, mine, mine, n, n);
  MatSetType(A, MATAIJ);
  MatSetBlockSize(A, 3);
  MatLoad(A, viewer);
  PetscViewerDestroy(&viewer);
  const double read_seconds = since(t_start);

  const auto t_setup = std::chrono::steady_clock::now();
  PetscInt r0 = 0, r1 = 0;
  MatGetOwnershipRange(A, &r0, &r1);
  Vec x, b, diag, coords;
  MatCreateVecs(A, &x, &b);
  VecDuplicate(x, &diag);
  MatGetDiagonal(A, diag);
  std::vector<PetscInt> rows;
  for (std::size_t k = 0; k < s.fixed.size(); ++k)
    if (s.fixed[k] >= r0 && s.fixed[k] < r1) {
      rows.push_back(static_cast<PetscInt>(s.fixed[k]));
      VecSetValue(x, static_cast<PetscInt>(s.fixed[k]), s.fixed_values[k], INSERT_VALUES);
    }
  VecAssemblyBegin(x);
  VecAssemblyEnd(x);
  PetscScalar* bb = nullptr;
  VecGetArray(b, &bb);
  for (PetscInt d = r0; d < r1; ++d) bb[d - r0] = s.f[d];
  VecRestoreArray(b, &bb);
  MatZeroRowsColumns(A, static_cast<PetscInt>(rows.size()), rows.data(), 1.0, x, b);
  PetscScalar* dd = nullptr;
  VecGetArray(diag, &dd);
  VecGetArray(b, &bb);
  for (PetscInt d : rows) {
    if (!(dd[d - r0] > 0)) dd[d - r0] = 1.0;
    bb[d - r0] *= dd[d - r0];
  }
  VecRestoreArray(b, &bb);
  VecRestoreArray(diag, &dd);
  MatDiagonalSet(A, diag, INSERT_VALUES);
  MatSetOption(A, MAT_SPD, PETSC_TRUE);

  VecDuplicate(x, &coords);
  VecSetBlockSize(coords, 3);
  PetscScalar* c = nullptr;
  VecGetArray(coords, &c);
  for (PetscInt d = r0; d < r1; ++d) c[d - r0] = s.coordinates(d / 3, d % 3);
  VecRestoreArray(coords, &c);
  MatNullSpace rigid;
  MatNullSpaceCreateRigidBody(coords, &rigid);
  MatSetNearNullSpace(A, rigid);

  KSP ksp;
  PC pc;
  KSPCreate(PETSC_COMM_WORLD, &ksp);
  KSPSetOperators(ksp, A, A);
  KSPSetType(ksp, KSPCG);
  KSPGetPC(ksp, &pc);
  PCSetType(pc, PCGAMG);
  KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED);
  KSPSetTolerances(ksp, rtol, 0.0, PETSC_DEFAULT, 10000);
  KSPSetFromOptions(ksp);
  KSPSetUp(ksp);
  const double setup = since(t_setup);
  const auto t_solve = std::chrono::steady_clock::now();
  KSPSolve(ksp, b, x);
  const double solve = since(t_solve);
  PetscInt iterations = 0;
  KSPConvergedReason reason;
  KSPGetIterationNumber(ksp, &iterations);
  KSPGetConvergedReason(ksp, &reason);
  if (rank == 0)
    std::printf("{\"read_seconds\": %.4g, \"setup_seconds\": %.4g, \"solve_seconds\": %.4g, \"iterations\": %d, "
                "\"reason\": \"%s\", \"processes\": %d, \"total_seconds\": %.4g}\n",
                read_seconds, setup, solve, static_cast<int>(iterations), KSPConvergedReasons[reason], size,
                since(t_start));
  KSPDestroy(&ksp);
  MatNullSpaceDestroy(&rigid);
  VecDestroy(&coords);
  VecDestroy(&diag);
  VecDestroy(&x);
  VecDestroy(&b);
  MatDestroy(&A);
  PetscFinalize();
  return reason > 0 ? 0 : 1;
}
