// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "xfem/system/linear_system.h"

namespace xfem {

/// K u = f with the Dirichlet conditions eliminated: only the free DOFs remain, so the reduced
/// matrix is the principal submatrix K_ff of K and stays symmetric positive definite whenever
/// the conditions remove the rigid-body modes (DESIGN.md: Dirichlet values act on original DOFs).
struct ReducedSystem {
  SparseMatrix K;               ///< nf x nf, K_ff, both triangles
  Eigen::VectorXd f;            ///< nf, f_f - K_fc u_c (newtons)
  std::vector<int> free_dofs;   ///< nf: reduced index -> scalar DOF of the full system
  std::vector<int> reduced;     ///< 3N: scalar DOF -> reduced index, -1 when constrained
};

/// Eliminates the DOFs `fixed` (strictly increasing, < K.rows()) with prescribed `values`
/// (metres): f_f -= K_fc u_c. `K` is the full symmetric 3N x 3N matrix, `f` 3N newtons.
/// Throws xfem::Error when no DOF is left free.
ReducedSystem eliminate_dirichlet(const SparseMatrix& K, const Eigen::VectorXd& f, const std::vector<long>& fixed,
                                  const std::vector<double>& values);

/// The full 3N solution: free DOFs from `u_free` (nf), constrained DOFs at their prescribed values.
Eigen::VectorXd expand_solution(const ReducedSystem& r, const Eigen::VectorXd& u_free, const std::vector<long>& fixed,
                                const std::vector<double>& values);

/// Relative residual of the full solution `u` (3N) on the equations of the free DOFs:
/// ||(K u - f)_f|| / ||f_f - K_fc u_c|| (the rows of constrained DOFs hold reaction forces, not
/// equations). Returns ||(K u - f)_f|| itself when the reduced right-hand side is zero.
double relative_residual(const SparseMatrix& K, const Eigen::VectorXd& f, const Eigen::VectorXd& u,
                         const ReducedSystem& r);

/// Throws xfem::Error when the Dirichlet data cannot make K non-singular: no condition at all
/// ("no Dirichlet condition: ..."), or a piece of the body without one ("the body falls apart
/// into 2 pieces; piece 2 (1234 tets) has no Dirichlet condition"; pieces numbered from 1).
void require_constrained(const LinearSystem& system);

/// Human-readable name of scalar DOF `dof` of `system` for error messages, e.g.
/// "DOF 40 (vector 13 = sign-enriched vector 1 of 4, component y)" (paper 3.3 numbering).
std::string describe_dof(const LinearSystem& system, long dof);

/// Scalar DOFs whose row of K (= column, K symmetric) holds no non-zero value (explicit zeros
/// of the pattern count as zero): DOFs whose basis function has no support. Strictly increasing.
std::vector<long> zero_rows(const LinearSystem& system);

/// Fixes to 0 the free enriched DOFs (k >= NP) whose row of K is exactly zero and returns them,
/// strictly increasing. Such a DOF's shifted Heaviside or branch function vanishes (with its
/// gradient) on every integration point of its elements: the cut passes through the node or
/// along a face so that the node's support has zero volume on one side (DESIGN.md, "known X-FEM
/// weaknesses"). The DOF is then absent from the energy, so fixing it to 0 leaves every other
/// value of the solution unchanged, while leaving it free makes K singular.
/// Throws xfem::Error naming the DOF when a free ORIGINAL DOF has a zero row (a mesh point in
/// no tet, or only in zero-volume tets): that is a broken mesh, not an enrichment artefact.
std::vector<long> fix_unsupported_enrichment(LinearSystem& system);

/// Free enriched scalar DOFs (3k + i with k >= NP, not in `system.fixed`) whose diagonal K_dd is
/// below `tolerance` times the mean diagonal of the original DOFs: the sign/branch DOFs with
/// negligible support on one side of the cut (paper, end of 5.2). K_dd is the energy of the
/// DOF's unit mode, which scales with the volume of the part of its support where the
/// enrichment function is non-zero, so `tolerance` is roughly the admitted fraction of a node's
/// support (1e-6: a sliver of a millionth of the element volume). Strictly increasing.
std::vector<long> tiny_enriched_dofs(const LinearSystem& system, double tolerance);

/// Adds `extra` DOFs (fixed to 0) to the constrained set of `system`, keeping `fixed` sorted.
void fix_to_zero(LinearSystem& system, const std::vector<long>& extra);

}  // namespace xfem
