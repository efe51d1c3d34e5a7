// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

#include "xfem/enrich/classification.h"
#include "xfem/enrich/classification_memory.h"

namespace xfem {

/// A box: columns lo, hi.
using GrowthBox = Eigen::Matrix<double, 3, 2>;

/// The boxes of the triangles added since the previous cut (and their corners), and their union: the
/// near-triangle test that decides what GrowingCutClassifier judges anew.
struct CutGrowth {
  std::vector<GrowthBox> boxes;
  std::vector<std::array<Eigen::Vector3d, 3>> corners;  // of each new triangle, in the order of `boxes`
  GrowthBox all;
  // Does the closed box [lo - grow, hi + grow] meet a new triangle's box?
  bool near(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double grow = 0) const {
    const auto meets = [&](const GrowthBox& b) {
      return (b.col(0).array() <= hi.array() + grow).all() && (b.col(1).array() >= lo.array() - grow).all();
    };
    if (!meets(all)) return false;
    for (const GrowthBox& b : boxes)
      if (meets(b)) return true;
    return false;
  }
  // The distance from x to the nearest new triangle, or `bound` when none is nearer than that.
  double distance(const Eigen::Vector3d& x, double bound) const;
};

/// classify() for a cut that grows from call to call (progressive cutting: the blade adds triangles,
/// none moves or goes away). The mesh's edges are found once, and what classify computes from the
/// cut's geometry near each point, edge and tet (a point on the cut, an edge meeting it, the volumes
/// a tet has on each side) is kept from the previous call and computed anew only near the triangles
/// added since: a point or edge whose box misses every new triangle's box meets the grown cut iff it
/// met the old one (exact predicates on closed triangles); a tet's volumes are reused when no new
/// triangle's box comes within the tet's longest edge of its box (its pieces and their sides, judged
/// at the closest cut point, cannot change); a point's side is reused when no new triangle's box
/// comes as close to it as the previous cut was (its closest cut point and that point's
/// pseudo-normal stay). The front and everything derived are computed as classify() does. The result
/// equals classify(mesh, cut, options) exactly (test/unit/classification.cpp).
class GrowingCutClassifier {
 public:
  /// `mesh` must outlive the classifier.
  explicit GrowingCutClassifier(const TetMesh& mesh, const ClassifyOptions& options = {});
  ~GrowingCutClassifier();
  GrowingCutClassifier(GrowingCutClassifier&&) noexcept;
  GrowingCutClassifier& operator=(GrowingCutClassifier&&) noexcept;

  /// classify(mesh, cut, options). `ids[k]` names triangle k of `cut` from call to call (its index
  /// in the sweep: cut_until_ids); a cut holding every triangle of the previous call, each with the
  /// same id and the same corners, is classified incrementally, any other cut from scratch.
  Classification classify(const CutSurface& cut, const std::vector<int>& ids);

  /// What the last call did: 1 if incrementally; points, edges and tets whose geometry was tested
  /// anew; points whose side was judged anew (a new triangle came as close to them as the previous
  /// cut was: their closest cut point may have moved).
  using Stats = ClassifyWork;
  const Stats& stats() const { return stats_; }

 private:
  const TetMesh* mesh_;
  ClassifyOptions options_;
  std::unique_ptr<ClassificationMemory> memory_;
  Stats stats_;
};

}  // namespace xfem
