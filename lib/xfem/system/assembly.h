// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "xfem/integrate/element_stiffness.h"
#include "xfem/integrate/tet_materials.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/system/linear_system.h"
#include "xfem/io/matrix_market.h"
#include "xfem/integrate/oversampling_quadrature.h"
#include "xfem/system/problem.h"
#include "xfem/system/dirichlet_data.h"

namespace xfem {

/// Where the assembly's time went (seconds) and how many tets took which path.
struct AssemblyStats {
  double pattern_seconds = 0.0;    ///< sparsity pattern from the extended connectivity
  double standard_seconds = 0.0;   ///< closed-form stiffness + scatter of tets without enriched DOFs
  double enriched_seconds = 0.0;   ///< oversampled stiffness + scatter of tets with enriched DOFs
  double load_seconds = 0.0;       ///< f and the Dirichlet data
  long standard_tets = 0, enriched_tets = 0;
};

/// The global stiffness matrix K (paper formula (8)), 3N x 3N, LOWER TRIANGLE ONLY (row >= column),
/// N/m, in compressed column form with sorted rows. The pattern is precomputed from the extended
/// connectivity (every pair of DOFs sharing a tet, explicit zeros included, so the pattern does not
/// depend on the values) and element matrices are scattered straight into it: tets with |C| = 4
/// plain DOFs use the closed-form linear-tet stiffness, the others the oversampling `rule`, or, with
/// conforming_order n > 0, the cut-conforming rule of order n (conforming_quadrature.h; `rule` unused),
/// with `closed_form` the blocks without branch functions in closed form (closed_form_stiffness.h),
/// else every block from the points (element_stiffness_at_points: integration.rule "pieces"); with
/// `graded` (and closed_form) the branch functions' points by TetRuleLayout::graded() instead of the rule
/// of order n (TetRuleLayout::of_order), with `uniform` by TetRuleLayout::uniform(n) with the shift on n
/// face points (the rule of order n before issue 35; n >= 2), with `fast` by TetRuleLayout::fast().
/// `progress` (optional) gets the fraction of tets done.
SparseMatrix stiffness_matrix(const EnrichedMesh& em, const Lame& material, const Quadrature& rule,
                              AssemblyStats* stats = nullptr, const std::function<void(double)>& progress = {},
                              int conforming_order = 0, bool closed_form = true, bool graded = false,
                              bool uniform = false, bool fast = false);
/// The same with each tet's own material (materials.lame(t); problem.json `materials`).
SparseMatrix stiffness_matrix(const EnrichedMesh& em, const TetMaterials& materials, const Quadrature& rule,
                              AssemblyStats* stats = nullptr, const std::function<void(double)>& progress = {},
                              int conforming_order = 0, bool closed_form = true, bool graded = false,
                              bool uniform = false, bool fast = false);

/// The load vector f (3N, newtons; paper formula (7)) on the ORIGINAL DOFs only (DESIGN.md):
/// body force b V/4 to each node of each tet (exact for linear N), traction t A/3 to each node of
/// each boundary face (a face of exactly one tet) whose three nodes the condition selects.
/// Throws xfem::Error naming the condition when it selects no node or no boundary face.
Eigen::VectorXd load_vector(const EnrichedMesh& em, const Problem& problem);

/// The 3-vector DOFs k >= `first` whose diagonal block of K (from stiffness_matrix: lower
/// triangle, diagonal first in each column) is exactly zero: enriched functions without support,
/// e.g. a sign DOF whose elements have no volume on the far side of the cut (a cut through a node).
std::vector<long> unsupported_dofs(const SparseMatrix& K, long first);

/// Everything xfem-assemble writes: K, f, Dirichlet data, counts, the connected pieces
/// (find_pieces of pieces.h) and the point coordinates. `points` and `refine` are the
/// oversampling request and its refinement levels at the cut (problem.points / problem.refine
/// unless the caller overrides them); problem.rule = Conforming uses the conforming rule of
/// order problem.order instead.
LinearSystem assemble_system(const EnrichedMesh& em, const Problem& problem, int points, int refine,
                             AssemblyStats* stats = nullptr, const std::function<void(double)>& progress = {});
/// The same with each tet's material given (tet_materials() of problem.h, which the overload
/// above calls, naming the mesh "the mesh" in its errors).
LinearSystem assemble_system(const EnrichedMesh& em, const Problem& problem, const TetMaterials& materials, int points,
                             int refine, AssemblyStats* stats = nullptr,
                             const std::function<void(double)>& progress = {});

}  // namespace xfem
