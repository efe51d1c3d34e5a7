// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/geometry/tet_shape.h"

namespace xfem {

/// Values and gradients of one element's basis functions at a point, in the order of its C.
struct BasisAt {
  Eigen::VectorXd N;                               ///< |C|
  Eigen::Matrix<double, Eigen::Dynamic, 3> dN;     ///< |C| x 3, per metre
};

/// Evaluates the enriched basis of tet `t` at x (paper 3.4): for an original node N_m; for a
/// sign DOF N_l psi_l(x) with psi_l = (H(x) - H(P_l)) / 2; for the 4 branch DOFs of a node
/// N_l F_j(x), j = 0..3, with the ACTFs F of DESIGN.md in the continuous crack-tip coordinates of
/// CrackFront::coordinates (the frame interpolated along the front at the closest front point: no
/// jump where the closest segment changes).
/// `side` is H(x) to use (+1 / -1), so that a point on the cut can be evaluated on either face;
/// 0 means "decide with the cut surface" (for the ACTFs only behind the front, xa < 0). Behind the
/// front the side decides the face: theta = side * pi on the cut (branch_functions.h). The gradients of psi vanish (H is piecewise constant).
/// With several cuts (em.cuts) `side` is a side code (side_codes.h) and the sign DOFs of cut k, the
/// products and the branch DOFs of the tet's cut are evaluated with g_k (cut_function); the one cut
/// keeps its own loop, on +1 / -1 and em.side (its bits must not change).
/// Throws xfem::Error if a sign DOF needs H(x) with side 0 and no cut, or a branch DOF meets an
/// empty front.
void enriched_basis(const EnrichedMesh& em, int t, const Eigen::Vector3d& x, int side, BasisAt& out);

/// The same with the tet's linear shape functions `shape` = tet_shape(em.mesh, t) computed once by
/// the caller (integration evaluates many points of one tet).
void enriched_basis(const EnrichedMesh& em, int t, const TetShape& shape, const Eigen::Vector3d& x, int side,
                    BasisAt& out);

/// The same with x's crack-tip coordinates `tip` computed by the caller (what the front of the tet's
/// branch cut, front_of_tet, gives: e.g. by CrackFront::coordinates(x, near) with the front's segments
/// near the tet found once for all its points; or a straight front's line, straight_front_rule.h).
void enriched_basis(const EnrichedMesh& em, int t, const TetShape& shape, const Eigen::Vector3d& x, int side,
                    const TipCoordinates& tip, BasisAt& out);

/// u_h(x) = sum over C of U_k Phi_k(x) in tet t, for the solution u (3N scalars, 3k + i).
Eigen::Vector3d displacement_at(const EnrichedMesh& em, int t, const Eigen::Vector3d& x, int side,
                                const Eigen::VectorXd& u);

/// Displacement gradient du_i/dx_j at x in tet t (row i, column j), for strains and stresses.
Eigen::Matrix3d displacement_gradient_at(const EnrichedMesh& em, int t, const Eigen::Vector3d& x, int side,
                                         const Eigen::VectorXd& u);

}  // namespace xfem
