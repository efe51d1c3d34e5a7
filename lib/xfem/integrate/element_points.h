// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>

#include "xfem/integrate/conforming_quadrature.h"
#include "xfem/integrate/cut_element_splits.h"
#include "xfem/enrich/enriched_mesh.h"

namespace xfem {

class FaceIntegralCache;  // consistent_gradients.h

/// The integration points of one tet, each with its weight and the gradients of the tet's basis
/// there: what the nonlinear forces and tangent are integrated from (element_forces.h). Linear
/// tets have constant shape-function gradients, and with the shifted Heaviside each side of a cut
/// tet is an ordinary linear tet with its own nodal displacements: there the gradients, and so
/// the deformation gradient F, are constant per side.
struct ElementPoints {
  Eigen::VectorXd weight;    ///< q, m^3 (the rule's weights, volume included)
  Eigen::MatrixXd gradient;  ///< q x 3|C|: row p, column 3c + a holds dPhi_c/dx_a at point p (order of C)
  /// A tet by a straight front (straight_front_rule.h): S_straight - S_points, the moments
  /// (integral of grad Phi grad Phi^T, 3|C| x 3|C|) of the straight-front rule minus those of the
  /// points above; empty otherwise. The points above stay the exact pieces' (a nonlinear law needs
  /// points inside the tet, and the straight rule's lie outside with signed weights), and the
  /// element's forces add the linear law's k(correction) u (element_forces.h): the linear part of
  /// the integrand, which the straight rule integrates exactly, is xfem-assemble's, so that small
  /// loads recover the linear path and the linear model equals it.
  Eigen::MatrixXd correction;
  int size() const { return static_cast<int>(weight.size()); }
};

/// The points of tet t:
///  - a tet with only its nodes' original DOFs (em.plain(t)): one point, the tet's volume, the
///    linear shape functions' gradients;
///  - an enriched tet: the cut-conforming rule of order `order` (conforming_rule, the linear
///    path's default rule) with consistent gradients (sampled_gradients); when the tet has no
///    branch DOFs its gradients are constant on each side, so the points whose gradient rows are
///    equal bit for bit are merged into one carrying their summed weight: the material is
///    evaluated once per side (per region of several cuts), weighted by the side's volume.
/// `splits` = split_cut_elements(em); `face_cache` as for element_stiffness_at_points. The consistent
/// shift's faces by a straight front are integrated as xfem-assemble's default
/// (straight_front_face_integrals), and a branch tet by one gets `correction`.
void element_points(const EnrichedMesh& em, const CutElementSplits& splits, int t, int order,
                    FaceIntegralCache* face_cache, ElementPoints& out);

}  // namespace xfem
