// SPDX-License-Identifier: MIT
#pragma once
#include <memory>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/solve/newton.h"
#include "xfem/solve/petsc_solver.h"

namespace xfem {

/// xfem-newton's PETSc backend (xfem-newton-petsc, under mpirun with --np): every rank runs the
/// whole Newton iteration (the tangent and the residual assembled whole on each rank: they are
/// the same bit for bit, the element sums being added in the tets' order), and each linear solve
/// is xfem-solve's PETSc solve (petsc_solve: CG with GAMG, or the field split when `em` has
/// enriched DOFs, the rigid-body near-null space from em's points) on the tangent distributed
/// over the ranks, each rank taking its rows of its own copy. The update is broadcast from rank
/// 0, so every rank continues from the same u and takes the same decisions (line search, halving,
/// convergence) without further messages. A CG that does not converge (an indefinite tangent)
/// is a NotPositiveDefinite: the iteration projects the tangent, then halves the load step.
/// `options.monitor`, when set, gets the CG iterations (progress). Needs a live PetscSession.
std::unique_ptr<TangentSolver> petsc_tangent_solver(const EnrichedMesh& em, PetscSolveOptions options);

}  // namespace xfem
