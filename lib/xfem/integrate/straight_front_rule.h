// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/geometry/crack_front.h"
#include "xfem/geometry/cut_surface.h"
#include "xfem/integrate/conforming_quadrature.h"
#include "xfem/integrate/cut_element_splits.h"

namespace xfem {

/// The branch functions of a tet integrated without exact pieces, where the front near the tet is
/// one straight line with a constant frame (a, b, c) and the cut, where it meets the tet, is the
/// half-plane behind that line (issue 35: the reduction for straight fronts; docs/METHOD.md
/// "Straight fronts"). With (xi, eta, zeta) = (a, b, c) . (x - O), O on the line, the branch
/// functions are sqrt(rho) times functions of the angle theta around the line, the shape
/// functions linear. So the integrand of the branch x branch block, grad(N_l F_j) grad(N_m F_k)^T, is
/// rho^-1, rho^0 and rho^1 times polynomials in (rho, zeta) of low degree and functions of theta
/// alone. The tet is the signed sum over its faces not parallel to c of the prisms between the
/// face and a fixed plane zeta = zeta0, and each face's shadow on the (xi, eta) plane the signed
/// sum of the triangles (origin, edge) in polar coordinates around the line (the origin). In each,
/// zeta = zeta0 + tau (Z - zeta0) to the face's plane Z and rho = rho_edge(theta) sigma^2: the
/// integrand is then a polynomial of degree <= 7 in sigma and <= 2 in tau, integrated exactly by 4 x
/// 2 Gauss points, and only theta is sampled: `angle_points` Gauss points per stretch of the edge
/// between the cut's plane crossings, in v with u = p sinh v along the edge (p the line's distance
/// to it), where the integrand is analytic in a strip of half-width pi / 2 whatever p; stretches
/// longer than 1.5 in v are divided. The first moments (per side, for the other blocks and the
/// consistent shift) are polynomials of degree <= 6 in sigma: exact too.
///
/// The points lie in the prisms, mostly outside the tet, with signed weights; their crack-tip
/// coordinates are the line's affine ones (the same, where both exist, as CrackFront::coordinates on
/// such a front: checked at the tet's corners, edges' midpoints and centroid), and their side is
/// the sign of eta: theta's sub-intervals never cross the cut's plane.
struct StraightFrontRule {
  PointRule points;                  ///< x, signed weights, side +1 (eta > 0) / -1 (with several cuts: side codes); the positive weights first
  int negative_begin = 0;            ///< index of the first point with a negative weight
  std::vector<TipCoordinates> tips;  ///< per point, the line's crack-tip coordinates
};

/// Fills `out` and returns true when tet t qualifies: branch DOFs (of one cut; with several cuts no
/// other cut meeting the tet, whose sides are then the tet centre's), every face of that cut
/// meeting the tet in the plane of the line and behind it, the front's chain straight with one
/// frame within reach of the tet (its segments within the centroid's distance to the front plus 2
/// longest edges), the crack-tip coordinates there affine, no face of the tet nearly (but not
/// exactly) parallel to the line, and the rule's volume on each side equal to the exact pieces'
/// (side_volumes; ahead of the front they are the halves of the cut's plane, as here) within 1e-9
/// of the tet's. A tet the line passes through qualifies. Otherwise returns false and the caller
/// integrates the exact pieces.
bool straight_front_rule(const EnrichedMesh& em, const CutElementSplits& splits, int t, int angle_points,
                         StraightFrontRule& out);

/// The integrals over the triangle (A, B, C) of N_v F_j (N_v its barycentric functions in the order
/// A, B, C; F_j the four branch functions, each point with the side of the cut's plane it lies on),
/// when the front near the triangle is one straight line with one frame (as straight_front_rule), the
/// cut meeting its box lies in the line's plane behind it and the triangle does not lie in that
/// plane: exact but for the angle's sampling (`angle_points` per stretch). A triangle crossing the
/// line's direction c over its shadow on the (xi, eta) plane, in the same polar coordinates as
/// straight_front_rule; one containing c in its own coordinates (along its shadow's line, and c).
/// Decided from the triangle alone, so that the two tets sharing a face get the same numbers
/// (consistent_gradients.h). Returns false otherwise (integral zero).
bool straight_front_face_integrals(const CrackFront& front, const CutSurface* cut, const Eigen::Vector3d& A,
                                   const Eigen::Vector3d& B, const Eigen::Vector3d& C, int angle_points,
                                   Eigen::Matrix<double, 3, 4>& integral);

/// Gauss points in the angle per stretch of an edge (straight_front_rule) for the rule of order n:
/// measured in docs/PERFORMANCE.md ("Straight fronts").
int straight_front_angle_points(int order);

}  // namespace xfem
