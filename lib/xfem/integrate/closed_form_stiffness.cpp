// SPDX-License-Identifier: MIT
#include "xfem/integrate/closed_form_stiffness.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "xfem/core/error.h"
#include "xfem/enrich/enriched_basis.h"
#include "xfem/geometry/tet_shape.h"
#include "xfem/integrate/side_volumes.h"

namespace xfem {

void closed_form_stiffness(const EnrichedMesh& em, const CutElementSplits& splits, int t, const PointRule& branch_rule,
                           const Lame& material, Eigen::MatrixXd& k, int consistent_order,
                           FaceIntegralCache* face_cache, int near_face_points) {
  ClosedFormWorkspace work;
  closed_form_stiffness(em, splits, t, branch_rule, material, k, consistent_order, face_cache, near_face_points, work);
}

void closed_form_stiffness(const EnrichedMesh& em, const CutElementSplits& splits, int t, const PointRule& branch_rule,
                           const Lame& material, Eigen::MatrixXd& k, int consistent_order,
                           FaceIntegralCache* face_cache, int near_face_points, ClosedFormWorkspace& work,
                           const StraightFrontRule* straight, int straight_face_points) {
  stiffness_from_moments(closed_form_moments(em, splits, t, branch_rule, consistent_order, face_cache, near_face_points,
                                             work, straight, straight_face_points),
                         material, k);
}

void default_rule_stiffness(const EnrichedMesh& em, const CutElementSplits& splits, int t, int order,
                            const Lame& material, Eigen::MatrixXd& k, FaceIntegralCache* face_cache,
                            ClosedFormWorkspace& work, PointRule& points) {
  // Points for the branch functions only: the other blocks need the side volumes alone.
  const int angle_points = straight_front_angle_points(order);
  const bool straight = em.branch(t) && straight_front_rule(em, splits, t, angle_points, work.straight);
  if (!em.branch(t) || straight) points.clear();
  else conforming_rule(em, splits, t, order, points);
  closed_form_stiffness(em, splits, t, points, material, k, order, face_cache, 0, work,
                        straight ? &work.straight : nullptr, angle_points);
}

Eigen::Map<Eigen::MatrixXd, Eigen::AlignedMax> closed_form_moments(
    const EnrichedMesh& em, const CutElementSplits& splits, int t, const PointRule& branch_rule, int consistent_order,
    FaceIntegralCache* face_cache, int near_face_points, ClosedFormWorkspace& work, const StraightFrontRule* straight,
    int straight_face_points) {
  const int n = em.size(t);
  const long base = em.offsets[t];
  const long first_branch = em.np + em.ns;
  // Columns of the non-branch functions (a) and of the branch functions (b).
  std::vector<int>& a_cols = work.a_cols;
  std::vector<int>& b_cols = work.b_cols;
  a_cols.clear();
  b_cols.clear();
  for (int c = 0; c < n; ++c)
    for (int d = 0; d < 3; ++d) (em.dofs[base + c] < first_branch ? a_cols : b_cols).push_back(3 * c + d);
  const int na = static_cast<int>(a_cols.size()), nb = static_cast<int>(b_cols.size());

  // Non-branch gradients per region, constant there: evaluated once, at a point inside it.
  const SideVolumes regions = side_volumes(em.mesh, splits, t);
  const int R = regions.size();
  const TetShape shape = tet_shape(em.mesh, t);
  auto A = work.A.view(R, na);  // row r: a_r
  BasisAt basis;
  for (int r = 0; r < R; ++r) {
    enriched_basis(em, t, shape, regions.point[r], regions.side[r], basis);
    for (int i = 0; i < na; ++i) A(r, i) = basis.dN(a_cols[i] / 3, a_cols[i] % 3);
  }
  auto S = work.S.view(3 * n, 3 * n);
  S.setZero();
  // non-branch x non-branch: sum_r V_r a_r a_r^T.
  // As G^T G of the exact-piece rule (stiffness_from_gradients), with one row sqrt(V_r) a_r per region.
  auto Ga = work.Ga.view(R, na);
  for (int r = 0; r < R; ++r) Ga.row(r) = std::sqrt(regions.volume[r]) * A.row(r);
  auto Saa = work.Saa.view(na, na);
  Saa.setZero();
  Saa.selfadjointView<Eigen::Lower>().rankUpdate(Ga.transpose());
  Saa.triangularView<Eigen::StrictlyUpper>() = Saa.transpose();
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < na; ++j) S(a_cols[i], a_cols[j]) = Saa(i, j);

  if (nb > 0) {
    const PointRule& rule = straight ? straight->points : branch_rule;
    const int q = rule.size();
    // b_p, then overwritten by B: row p sqrt(|w_p|) b_p (the branch columns only: the others are not used)
    auto B = work.B.view(q, nb);
    sampled_gradients(em, t, rule, consistent_order, face_cache, b_cols, B, work.tips, near_face_points,
                      straight ? &straight->tips : nullptr, straight_face_points);
    auto sums = work.sums.view(R, nb);  // row r: sum over p in r of w_p b_p
    sums.setZero();
    for (int p = 0; p < q; ++p) {
      // A straight-front rule's points in an uncut tet have the side of the cut's plane (for theta);
      // they all belong to its one region.
      const auto found = straight && R == 1 ? regions.side.begin()
                                            : std::find(regions.side.begin(), regions.side.end(), rule.side[p]);
      if (found == regions.side.end())
        throw Error("closed-form stiffness of tet " + std::to_string(t) + ": an integration point has side " +
                    std::to_string(rule.side[p]) + ", which no piece of the tet has");
      const int r = static_cast<int>(found - regions.side.begin());
      const double w = rule.weights[p], sw = std::sqrt(std::abs(w));
      for (int i = 0; i < nb; ++i) {
        const double g = B(p, i);
        sums(r, i) += w * g;
        B(p, i) = sw * g;
      }
    }
    auto Sbb = work.Sbb.view(nb, nb);
    Sbb.setZero();
    const int positive = straight ? straight->negative_begin : q;  // the exact pieces' weights are all positive
    Sbb.selfadjointView<Eigen::Lower>().rankUpdate(B.topRows(positive).transpose());
    if (positive < q) Sbb.selfadjointView<Eigen::Lower>().rankUpdate(B.bottomRows(q - positive).transpose(), -1.0);
    Sbb.triangularView<Eigen::StrictlyUpper>() = Sbb.transpose();
    auto Sab = work.Sab.view(na, nb);
    Sab.noalias() = A.transpose() * sums;
    for (int i = 0; i < nb; ++i)
      for (int j = 0; j < nb; ++j) S(b_cols[i], b_cols[j]) = Sbb(i, j);
    for (int i = 0; i < na; ++i)
      for (int j = 0; j < nb; ++j) S(a_cols[i], b_cols[j]) = S(b_cols[j], a_cols[i]) = Sab(i, j);
  }
  return S;
}

}  // namespace xfem
