// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <functional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "xfem/solve/schur_solver.h"

namespace xfem {

/// One enriched scalar DOF's coupling as the assembled system has it: its column of K_se (free
/// original DOFs by reduced index, increasing) and of K_ee (enriched DOFs by key, increasing, itself
/// included). Exact zeros are left out.
struct EnrichedColumn {
  long key = 0;  ///< the DOF's identity from step to step (progressive_cut.h: point, enrichment, component)
  std::vector<std::pair<int, double>> se;
  std::vector<std::pair<long, double>> ee;
  bool operator==(const EnrichedColumn& o) const { return key == o.key && se == o.se && ee == o.ee; }
};

/// What the last IncrementalSchur::update did.
struct IncrementalSchurStats {
  long kept = 0;            ///< enriched DOFs whose columns of K (and so of S) were reused
  long added = 0;           ///< new or changed ones: their columns of S computed
  long removed = 0;         ///< gone or changed since the previous update
  long refactored = 0;      ///< trailing rows of S's Cholesky factor computed anew
  long region_added = 0;    ///< free DOFs added to the region by this update
  double region_seconds = 0, columns_seconds = 0, factor_seconds = 0;
};

/// The Schur complement S = K_ee - K_es A^-1 K_se of a growing cut's enriched DOFs, kept from
/// one cut to the next (progressive cutting). Two facts make a step cheap:
///  - K_se is non-zero only on the free original DOFs of the tets with enriched DOFs (the region),
///    so K_es A^-1 K_se = K_eR G K_Re with G = A^-1 restricted to region x region: G is computed
///    once for the region of the whole sweep (solves with A's one factorization, unit right-hand
///    sides, many at once), after which a column of S costs a product with G, not a solve;
///  - a cut that grows leaves the columns of K of enriched DOFs away from its growth unchanged: S
///    keeps their entries, and its Cholesky factor (S ordered by the step each DOF last changed)
///    keeps its leading rows; only the rows from the first changed DOF on are factorized anew.
/// The result is S's factor for the given columns, whatever the previous ones were (an enriched DOF
/// counts as unchanged only if its columns of K are bitwise the same), so the solution does not
/// depend on the history.
class IncrementalSchur {
 public:
  explicit IncrementalSchur(const CholeskyFactor& A) : A_(A) {}

  /// Adds the free DOFs (reduced indices) not yet in the region: their columns of A^-1, `block`
  /// at a time. `progress` gets the fraction done.
  void extend_region(const std::vector<int>& free_dofs, const std::function<void(double)>& progress = {},
                     int block = 256);
  long region_size() const { return static_cast<long>(region_.size()); }

  /// Makes S (and its factor) the Schur complement of `columns` (any order; keys distinct),
  /// extending the region with any free DOF they reach outside it. Throws xfem::Error when S is not
  /// positive definite (a piece of the cut body can move freely or an enrichment is degenerate).
  void update(const std::vector<EnrichedColumn>& columns, IncrementalSchurStats* stats = nullptr);

  /// S^-1 r, r and the result indexed like the last update's columns.
  Eigen::VectorXd solve(const Eigen::VectorXd& r) const;

  /// Room for m enriched DOFs (S and its factor, m x m each), so that no update up to m moves them:
  /// a growing S otherwise grows by half, a fresh allocation and copy of both each time.
  void reserve(long m);

 private:
  const CholeskyFactor& A_;
  std::vector<int> region_;       // region position -> free DOF
  std::vector<int> in_region_;    // free DOF -> region position, -1 (sized on first use)
  Eigen::MatrixXd G_;             // A^-1, region x region
  std::vector<EnrichedColumn> columns_;  // S's order
  std::unordered_map<long, long> position_;  // key -> S position
  Eigen::MatrixXd S_, L_;         // S (its lower triangle; the upper one is left stale) and its lower Cholesky factor; capacity >= m_
  long m_ = 0;
  std::vector<long> caller_;      // last update: caller index -> S position
};

}  // namespace xfem
