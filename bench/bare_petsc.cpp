// SPDX-License-Identifier: MIT
// Baseline for xfem-solve --backend petsc on one process: the same system/ directory read by the
// same reader, the same symmetric in-place Dirichlet elimination (fixed rows and columns -> their
// diagonal), then the bare PETSc calls: SeqAIJ with block size 3, MatNullSpaceCreateRigidBody from
// the coordinates, KSPCG + PCGAMG, unpreconditioned residual norm. PETSC_OPTIONS apply.
// Prints the timings on stdout as one JSON line. Usage: bare_petsc SYSTEM_DIR [RTOL]
// (the rigid-body modes need N = NP: an uncut system such as the reference beam).
#include <petscksp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "xfem/linear_system.h"

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
  const auto t_start = std::chrono::steady_clock::now();
  const xfem::LinearSystem s = xfem::read_linear_system(argv[1]);
  const double read_seconds = since(t_start);
  if (s.n != s.np || s.coordinates.size() == 0) {
    std::fprintf(stderr, "bare_petsc: needs an uncut system with coordinates.mtx\n");
    return 1;
  }

  const auto t_setup = std::chrono::steady_clock::now();
  const PetscInt n = static_cast<PetscInt>(3 * s.n);
  std::vector<char> fixed(n, 0);
  std::vector<double> value(n, 0.0);
  for (std::size_t k = 0; k < s.fixed.size(); ++k) fixed[s.fixed[k]] = 1, value[s.fixed[k]] = s.fixed_values[k];
  std::vector<PetscInt> nnz(n, 1);
  for (PetscInt d = 0; d < n; ++d)
    if (!fixed[d]) {
      nnz[d] = 0;
      for (xfem::SparseMatrix::InnerIterator it(s.K, d); it; ++it) nnz[d] += !fixed[it.row()];
    }
  Mat A;
  Vec x, b, coords;
  MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 0, nnz.data(), &A);
  MatSetBlockSize(A, 3);
  MatCreateVecs(A, &x, &b);
  std::vector<PetscInt> cols;
  std::vector<PetscScalar> vals;
  for (PetscInt d = 0; d < n; ++d) {
    cols.clear();
    vals.clear();
    double rhs = s.f[d];
    if (fixed[d]) {
      const double k = s.K.coeff(d, d) > 0 ? s.K.coeff(d, d) : 1.0;
      cols.push_back(d);
      vals.push_back(k);
      rhs = k * value[d];
    } else {
      for (xfem::SparseMatrix::InnerIterator it(s.K, d); it; ++it) {
        if (fixed[it.row()]) {
          rhs -= it.value() * value[it.row()];
        } else {
          cols.push_back(static_cast<PetscInt>(it.row()));
          vals.push_back(it.value());
        }
      }
    }
    VecSetValue(b, d, rhs, INSERT_VALUES);
    MatSetValues(A, 1, &d, static_cast<PetscInt>(cols.size()), cols.data(), vals.data(), INSERT_VALUES);
  }
  VecAssemblyBegin(b);
  VecAssemblyEnd(b);
  MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
  MatSetOption(A, MAT_SPD, PETSC_TRUE);

  VecCreateSeq(PETSC_COMM_SELF, n, &coords);
  VecSetBlockSize(coords, 3);
  PetscScalar* c = nullptr;
  VecGetArray(coords, &c);
  for (long k = 0; k < s.np; ++k)
    for (int i = 0; i < 3; ++i) c[3 * k + i] = s.coordinates(k, i);
  VecRestoreArray(coords, &c);
  MatNullSpace rigid;
  MatNullSpaceCreateRigidBody(coords, &rigid);
  MatSetNearNullSpace(A, rigid);

  KSP ksp;
  PC pc;
  KSPCreate(PETSC_COMM_SELF, &ksp);
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
  std::printf("{\"read_seconds\": %.4g, \"setup_seconds\": %.4g, \"solve_seconds\": %.4g, \"iterations\": %d, "
              "\"reason\": \"%s\", \"total_seconds\": %.4g}\n",
              read_seconds, setup, solve, static_cast<int>(iterations), KSPConvergedReasons[reason], since(t_start));
  KSPDestroy(&ksp);
  MatNullSpaceDestroy(&rigid);
  VecDestroy(&coords);
  VecDestroy(&x);
  VecDestroy(&b);
  MatDestroy(&A);
  PetscFinalize();
  return reason > 0 ? 0 : 1;
}
