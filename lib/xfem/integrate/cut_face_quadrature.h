// SPDX-License-Identifier: MIT
#pragma once
#include <array>
#include <Eigen/Dense>
#include <vector>

#include "xfem/enrich/enriched_basis.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/integrate/polygon_split.h"

namespace xfem {

/// Length of the segment (p, q) inside the convex polygon of unit normal `normal` (in its plane);
/// -1 if it misses the polygon.
double segment_length_in_polygon(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Polygon& poly,
                                 const Eigen::Vector3d& normal);

/// Gauss points of the convex polygon, fanned from `apex` (a corner, or a point inside it) over its
/// edges; each triangle (apex, B, C) gets the collapsed n x n Gauss rule x = apex + s (B - apex) +
/// s t (C - B) (`nodes`, `weights` on [0, 1], n of them), split into four at its edges' midpoints
/// first, recursively up to `depth` times, while a front segment of `fronts` passes closer to it
/// than its longest edge (F ~ sqrt(r) is nearly singular there). Positions `x` and weights `w`
/// (m^2) replace the vectors' contents. Exact for polynomials of degree 2n - 2 on each triangle.
void polygon_gauss_rule(const Polygon& poly, const Eigen::Vector3d& apex, int depth,
                        const std::vector<const FrontSegment*>& fronts, const std::vector<double>& nodes,
                        const std::vector<double>& weights, std::vector<Eigen::Vector3d>& x, std::vector<double>& w);

/// The segments of `front` whose bounding boxes meet the tet's (its corners') grown by `tolerance`:
/// the ones a rule in that tet must know about.
std::vector<const FrontSegment*> fronts_near(const CrackFront& front, const std::array<Eigen::Vector3d, 4>& corners,
                                             double tolerance);

/// Where the branch functions are singular in the polygon: a front segment piercing its inside
/// (that point), else a corner on the front (the first found), else its first corner.
Eigen::Vector3d polygon_fan_apex(const Polygon& poly, const Eigen::Vector3d& normal,
                                 const std::vector<const FrontSegment*>& fronts, double tolerance);

/// Tet face (A, B, C) (its corners in increasing node id order, `normal` its unit normal) split
/// where the branch functions are not smooth on it: along the trace of every cut triangle of
/// `meeting` crossing a part's inside (none without a cut), then along every front segment lying
/// in its plane. Everything depends on the face alone (tolerances of its own size, the fronts
/// near its own bounding box), so the two tets sharing it split it alike; the stiffness's face
/// integrals (consistent_gradients) and the cut's face points (face_points_on_cut) share it, so a
/// load or a contact pressure sees the jump the stiffness integrates.
struct FaceParts {
  std::vector<Polygon> parts;
  std::vector<const FrontSegment*> fronts;  ///< the segments of `fronts` whose boxes meet the face's
  double tolerance = 0;                     ///< 1e-12 of the face's longest edge
};
FaceParts split_face(const CutSurface* cut, const std::vector<const FrontSegment*>& fronts,
                     const std::vector<int>& meeting, const Eigen::Vector3d& A, const Eigen::Vector3d& B,
                     const Eigen::Vector3d& C, const Eigen::Vector3d& normal);

/// One integration point on a cut's faces (docs/METHOD.md "Loads on the cut's faces").
struct CutFacePoint {
  int tet = -1;                  ///< the mesh tet it lies in
  int cut = 0;                   ///< the cut it lies on (0 for a mesh with one cut)
  int triangle = -1;             ///< the cut triangle it lies on
  Eigen::Vector3d x = Eigen::Vector3d::Zero();       ///< metres, on the cut
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< the cut triangle's unit normal (towards H = +1)
  double weight = 0.0;           ///< m^2, > 0
};

/// The corner of tet p opposite the face in whose plane every vertex of `polygon` lies (within
/// `tol`), or -1: a cut running along a mesh face. Such a polygon belongs to the tet below the cut
/// only (cut_face_points).
int corner_off_face_holding(const std::array<Eigen::Vector3d, 4>& p, const std::vector<Eigen::Vector3d>& polygon, double tol);

/// The integration points of cut `k`'s faces in tet t: the wound's own geometry, every triangle of
/// the cut surface clipped to the tet (clip_triangle; a convex polygon), integrated by
/// polygon_gauss_rule with max(m, 2) Gauss points per direction, m = consistent_face_points(order)
/// (conforming_quadrature.h: `order` is the conforming rule's), fanned from polygon_fan_apex
/// (a front point piercing the polygon or a corner on the front: the collapse of the rule sits
/// where sqrt(r) is least smooth) and subdivided towards the front max(0, m - 3) times. These
/// are the very points with which branch_gradient_integrals (consistent_gradients.h) integrates the
/// cut's term in the shift of the rule of that order (sampled_gradients), so that a load on the faces and the stiffness agree to round-off
/// (the superposition identity of docs/VERIFICATION.md). Linear integrands (the sign part of a
/// load) are exact; the branch part (sqrt r N_l) converges with the order. Nothing for a tet without
/// enriched DOFs. A polygon lying in a face of the tet (a cut along mesh faces) counts once, in the
/// tet below the cut: the nodes on the cut are above, so the tet above may carry no enriched DOF,
/// and the one below, which has no volume above the cut, carries the jump. Such a face takes the
/// points branch_gradient_integrals takes on it (the face split along a front lying in it, its
/// parts on the cut fanned from their singular points), once however many cut triangles cover it:
/// the stiffness's consistent shift and a load or contact pressure then integrate the jump of the
/// branch functions there with the same points (a crack lying in a node layer behaves as no cut
/// under contact to 1.8e-10 of max |u|, not 1.7e-5; docs/METHOD.md "Contact").
void cut_face_points(const EnrichedMesh& em, int t, int k, int order, std::vector<CutFacePoint>& out);

/// Every point of cut k's faces, tet after tet in increasing order.
std::vector<CutFacePoint> cut_face_points(const EnrichedMesh& em, int k, int order);

/// The jump of tet t's basis across cut k at x (a point on it): Phi_e(x, above) - Phi_e(x, below)
/// for every entry e of the tet's C, in its order (0 for original DOFs; N_l for a sign DOF of the
/// cut; N_l (F_j(theta = pi) - F_j(theta = -pi)) for branch DOFs, 2 sqrt(r) N_l for F_0). With
/// several cuts, x keeps its own side of every other cut. `scratch` holds the basis evaluations.
void basis_jump(const EnrichedMesh& em, int t, int k, const Eigen::Vector3d& x, Eigen::VectorXd& jump,
                BasisAt& scratch);

}  // namespace xfem
