// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <unordered_map>
#include <vector>

#include "xfem/enrich/growing_classification.h"
#include "xfem/system/dirichlet.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/solve/incremental_schur.h"
#include "xfem/integrate/oversampling_quadrature.h"
#include "xfem/system/pieces.h"
#include "xfem/system/problem.h"
#include "xfem/solve/schur_solver.h"

namespace xfem {

/// The enriched mesh of `mesh` classified as `c` against `cut` (null for no cut), in memory: what
/// xfem-classify + xfem-enrich write and read_enriched_mesh reads back, without the files.
EnrichedMesh enriched_mesh(const TetMesh& mesh, const Classification& c, std::shared_ptr<const CutSurface> cut);

/// The uncut body, assembled and factorized once: cutting changes neither K's block of the
/// original DOFs nor f nor the Dirichlet data (DESIGN.md, "Cutting does not touch the standard
/// block"), so every cut of a sweep reuses them.
struct UncutBody {
  TetMesh mesh;                    ///< the body (its arrays kept, for the Dirichlet selectors)
  Problem problem;
  TetMaterials materials;          ///< each tet's material (problem.json `materials`, tet_materials())
  std::vector<long> fixed;         ///< constrained scalar DOFs (original DOFs only)
  std::vector<double> fixed_values;
  Eigen::VectorXd constrained;     ///< 3 NP: the prescribed values at `fixed`, 0 elsewhere
  std::vector<int> free_dofs;      ///< reduced index -> scalar original DOF
  std::vector<int> reduced;        ///< scalar original DOF -> reduced index, -1 when constrained
  std::unique_ptr<CholeskyFactor> factor;  ///< of K_ss, the free original DOFs' block
  Eigen::VectorXd w;               ///< K_ss^-1 (f_s - K_sc u_c): the uncut body's free displacements
  SparseMatrix K_ss;               ///< the free original DOFs' block, lower triangle (for CutSolver::Refactor)
  Eigen::VectorXd g_s;             ///< f_s - K_sc u_c
  double assemble_seconds = 0;
  double solve_seconds = 0;        ///< one solve with `factor` (for CutSolver::Auto)
};

/// Assembles the uncut body's system for `problem` and factorizes K_ss. Throws xfem::Error for a
/// Dirichlet condition with an exact field other than "linear" (its values depend on the node's
/// side of the cut, so the standard block would change with the cut; the linear field is the same
/// on both sides) and for an unconstrained body (naming the
/// condition that is missing, as xfem-solve does).
UncutBody factorize_uncut(const TetMesh& mesh, const Problem& problem, Ordering ordering = Ordering::Metis);

/// How a cut's system is solved (both give the same solution up to round-off):
///   Schur     block elimination on the enriched DOFs with the uncut body's one factorization: the
///             dense Schur complement S costs about (enriched DOFs) solves with the factor and
///             (enriched DOFs)^3 / 3 flops, cheap for a small cut, dearer than a new factorization
///             for thousands of enriched DOFs;
///   Refactor  the uncut body's K_ss (reused, not reassembled) with the enriched rows and columns
///             appended, factorized anew by CHOLMOD: the cost of one sparse factorization;
///   Auto      Schur when (enriched DOFs) x (the time of one solve with the uncut factor, measured
///             once) is below the time the uncut factorization took, else Refactor.
enum class CutSolver { Auto, Schur, Refactor };

/// One cut of a sweep solved on the factorized uncut body.
struct CutSolution {
  EnrichedMesh em;                 ///< the classified, enriched mesh (as xfem-enrich would write it)
  Classification::Counts counts;
  Eigen::VectorXd u;               ///< 3N, m: the full solution, as xfem-solve would write it
  long enriched_tets = 0;          ///< tets with enriched DOFs (the only ones assembled)
  long enriched_dofs = 0;          ///< scalar enriched DOFs solved for (size of the Schur complement)
  long unsupported_dofs = 0;       ///< enriched DOFs with a zero row of K: fixed to 0 (as xfem-solve does)
  /// Wall times, s: classify (the classification alone), enrich (the DOF numbering and the check
  /// that every piece is held), assemble (ProgressiveCut: keys, integration and the gathered
  /// columns), solve (the Schur complement's update and solve; ProgressiveCut: without the
  /// back-substitution, which is timed apart).
  double classify_seconds = 0, enrich_seconds = 0, assemble_seconds = 0, solve_seconds = 0;
  /// complete_solution's solve with the uncut factor (u_s = w - A^-1 pending), wherever it ran.
  double back_substitution_seconds = 0;
  bool schur_used = false;         ///< which solver ran (Auto decides per cut)
  SchurStats schur;
  long recomputed_tets = 0;        ///< ProgressiveCut: tets whose element matrices were computed (the others reused)
  double keys_seconds = 0;         ///< ProgressiveCut, part of assemble_seconds: which element matrices to compute
  double elements_seconds = 0;     ///< ProgressiveCut, part of assemble_seconds: computing them
  IncrementalSchurStats incremental;  ///< ProgressiveCut: what the Schur complement's update did
  long reused_columns = 0;         ///< ProgressiveCut: enriched columns of K copied from the previous step, not summed
  /// ProgressiveCut::step with complete = false: the load b that the enriched DOFs put on the free
  /// original DOFs (reduced indices), whose response A^-1 b is still to be subtracted from u there
  /// (complete_solution). Empty when u is complete.
  Eigen::VectorXd pending;
};

/// Completes a solution ProgressiveCut::step left incomplete: u_s -= A^-1 pending with body's
/// factor (one solve), pending cleared. Does nothing to a complete one. Safe to run in another
/// thread than the steps (CholeskyFactor::solve). Throws xfem::Error for a non-finite result.
void complete_solution(const UncutBody& body, CutSolution& solution);

/// Classifies the body against `cut`, numbers the DOFs, assembles only the tets with enriched DOFs
/// (their K_ee, K_es; f_e = 0 since loads act on original DOFs) and solves by block elimination
/// on the enriched DOFs with body.factor, or by a new factorization (`solver`). The result equals xfem-classify, -enrich, -assemble and
/// -solve on the same cut up to round-off. Throws xfem::Error when a piece cut off the body has no
/// Dirichlet condition.
CutSolution solve_cut(const UncutBody& body, std::shared_ptr<const CutSurface> cut,
                      const ClassifyOptions& options = {}, CutSolver solver = CutSolver::Auto);

/// A sweep's cuts solved one after the other on the uncut body, each step at the cost of what the
/// cut's growth changed (issue 20). Per step: the body is classified against the cut and enriched
/// as solve_cut does (GrowingCutClassifier: the previous step's classification reused away from the
/// new triangles); element matrices are computed only for enriched tets whose inputs changed
/// since the previous step (their enrichment layout, node sides, cut class, the sweep's triangles
/// near them and, where the front matters, the front segments near them), the others reused; the
/// enriched DOFs' columns of K are gathered from them (an enriched DOF none of whose tets changed
/// keeps the previous step's columns) and the Schur complement on the enriched DOFs
/// updated (IncrementalSchur: only new or changed columns computed, its Cholesky factor refactorized
/// from the first changed row on). The solution equals solve_cut's (and the six tools') to round-off.
class ProgressiveCut {
 public:
  explicit ProgressiveCut(const UncutBody& body, const ClassifyOptions& options = {});

  /// Computes the body's response A^-1 on the free original DOFs that the cuts `cuts` (every step
  /// of the sweep) couple to enriched DOFs, once: after it, a step needs one solve with the factor.
  /// Optional (a step extends the region by what it needs), but without it the steps pay for their
  /// new region DOFs (a solve each, in blocks).
  /// With `ids` (ids[i] names the triangles of cuts[i] as step() takes them), a cut that holds the
  /// previous one is classified by a GrowingCutClassifier from it (the same classification).
  void prepare(const std::vector<std::shared_ptr<const CutSurface>>& cuts,
               const std::function<void(double)>& progress = {}, const std::vector<std::vector<int>>* ids = nullptr);
  long region_size() const { return schur_.region_size(); }

  /// Solves the cut `cut` whose triangle k is triangle `ids[k]` of the sweep (the identity of a
  /// triangle from step to step: cut_until keeps the sweep's order). Throws xfem::Error as solve_cut.
  /// With complete = false the last solve, which only the original DOFs' displacements need and no
  /// later step does, is left to complete_solution (CutSolution::pending): a caller that draws the
  /// frame in another thread takes it off the steps' path.
  CutSolution step(std::shared_ptr<const CutSurface> cut, const std::vector<int>& ids, bool complete = true);

 private:
  struct Element {
    std::vector<double> key;  // what the element matrix was computed from (element_key)
    Eigen::MatrixXd k;
  };
  const UncutBody& body_;
  ClassifyOptions options_;
  Quadrature rule_;
  IncrementalSchur schur_;
  GrowingCutClassifier classifier_;  // the previous step's classification, reused away from the cut's growth
  SharedFaces faces_;                // the body's, for the check that every piece is held
  std::unordered_map<int, Element> elements_;
  struct Columns {  // an enriched DOF's three columns of K as the last step gathered them
    std::vector<std::pair<int, int>> incidence;  // its (tet, entry) pairs, in order
    EnrichedColumn column[3];
    double g[3] = {0, 0, 0};
  };
  std::unordered_map<long, Columns> columns_;  // by the DOF's point * 5 + function
};

}  // namespace xfem
