// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/integrate/conforming_quadrature.h"
#include "xfem/integrate/cut_element_splits.h"
#include "xfem/integrate/element_stiffness.h"
#include "xfem/integrate/scratch_matrix.h"
#include "xfem/integrate/straight_front_rule.h"

namespace xfem {

class FaceIntegralCache;  // consistent_gradients.h

/// closed_form_stiffness's buffers, kept by a caller that integrates many tets (one per thread):
/// then no memory is allocated per tet (scratch_matrix.h says why that matters).
struct ClosedFormWorkspace {
  std::vector<int> a_cols, b_cols;
  ScratchMatrix A, Ga, Saa, S, B, sums, Sbb, Sab;
  std::vector<TipCoordinates> tips;
  StraightFrontRule straight;  ///< for the caller's straight_front_rule
};

/// Stiffness of formula (5) of an enriched tet t, block by block, with quadrature points only
/// where the integrand needs them (docs/METHOD.md "Integration"). With a_r the gradients of the
/// tet's non-branch basis functions (originals N_m, sign functions N_l psi_l) on region r (a side
/// of the cut, or a region of several cuts: side_volumes.h), constant there because linear tets
/// have constant shape-function gradients and psi is constant on a side, and b_p the (shifted,
/// consistent_gradients.h) gradients of the branch functions at the points p of `branch_rule`
/// (weights w_p), the moments S = integral of grad Phi grad Phi^T are
///   non-branch x non-branch  S = sum_r V_r a_r a_r^T                   (closed form: side volumes)
///   non-branch x branch      S = sum_r a_r (sum_{p in r} w_p b_p)^T     (one sum per region)
///   branch x branch          S = sum_p w_p b_p b_p^T                    (the volume rule)
/// and k rearranges S (stiffness_from_moments). For an original N_m the cross term is
/// g_m (integral over the tet of grad(N_l F_j))^T, which the shift makes the divergence theorem's
/// face integrals exactly (branch_gradient_integrals): no volume point enters it. The same numbers
/// as element_stiffness_at_points on the same points up to round-off (S there is G^T G over every
/// point; here the constant rows are summed first), at the cost of the branch columns only, and
/// none at all for a tet without branch DOFs. K stays a sum of squares (positive semi-definite).
/// `branch_rule`: the points of the branch functions (conforming_rule, or any rule whose points
/// carry the side codes of the pieces they lie in; side 0 in a tet no cut meets); ignored, and may
/// be empty, when the tet has no branch DOFs. `consistent_order`, `face_cache` as for
/// element_stiffness_at_points (conforming_quadrature.h); `near_face_points` as for sampled_gradients. Throws xfem::Error if a point's side is
/// not one of the tet's regions.
void closed_form_stiffness(const EnrichedMesh& em, const CutElementSplits& splits, int t, const PointRule& branch_rule,
                           const Lame& material, Eigen::MatrixXd& k, int consistent_order,
                           FaceIntegralCache* face_cache = nullptr, int near_face_points = 0);
/// The same with the caller's buffers (the same bits). `straight` (optional): the tet's
/// straight_front_rule, used for the branch functions instead of `branch_rule` (which may then be
/// empty); its signed weights enter S as sum_p w_p b_p b_p^T all the same (positive part minus
/// negative part), and each point's sums go to its side's region (the only region of an uncut tet).
/// `straight_face_points` > 0: the consistent shift's faces by a straight front exactly
/// (branch_gradient_integrals), for every tet of an assembly alike (a face's two tets must agree).
void closed_form_stiffness(const EnrichedMesh& em, const CutElementSplits& splits, int t, const PointRule& branch_rule,
                           const Lame& material, Eigen::MatrixXd& k, int consistent_order,
                           FaceIntegralCache* face_cache, int near_face_points, ClosedFormWorkspace& work,
                           const StraightFrontRule* straight = nullptr, int straight_face_points = 0);
/// The default rule of order n (integration.rule "conforming"), what xfem-assemble and xfem-sweep
/// both compute, so that they agree: a tet with branch DOFs by a straight front by
/// straight_front_rule, any other on the exact pieces' rule of order n (conforming_rule), the
/// blocks in closed form with the shift's faces by a straight front exact. `points`: a buffer.
void default_rule_stiffness(const EnrichedMesh& em, const CutElementSplits& splits, int t, int order,
                            const Lame& material, Eigen::MatrixXd& k, FaceIntegralCache* face_cache,
                            ClosedFormWorkspace& work, PointRule& points);
/// The moments S of the above (3|C| x 3|C|, k = stiffness_from_moments(S)), a view into `work`
/// valid until its next use: for the nonlinear path's straight-front correction (element_points.h).
Eigen::Map<Eigen::MatrixXd, Eigen::AlignedMax> closed_form_moments(
    const EnrichedMesh& em, const CutElementSplits& splits, int t, const PointRule& branch_rule, int consistent_order,
    FaceIntegralCache* face_cache, int near_face_points, ClosedFormWorkspace& work,
    const StraightFrontRule* straight = nullptr, int straight_face_points = 0);

}  // namespace xfem
