// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <array>
#include <vector>

#include "xfem/geometry/crack_front.h"
#include "xfem/geometry/cut_surface.h"
#include "xfem/integrate/cut_element_splits.h"
#include "xfem/integrate/element_stiffness.h"
#include "xfem/enrich/enriched_mesh.h"

namespace xfem {

class FaceIntegralCache;  // consistent_gradients.h

/// A cut-conforming, front-singular integration rule for tets with enriched DOFs: the alternative
/// to the paper's oversampling (3.6) selected by problem.json `integration.rule = "conforming"`
/// (docs/FORMATS.md). Oversampling integrates the Heaviside jump only to O(sub-tet size), gives no
/// point to thin slivers cut off a tet, and integrates the 1/r singular stiffness of the crack-tip
/// functions only to ~1e-3 (docs/VERIFICATION.md). This rule
///   1. splits every cut element along the cut into sub-tets of one side each (split_cut_elements:
///      exact for a piecewise planar cut and a polygonal front; sub-tets next to the front have an
///      edge or a vertex on it), so H and theta are evaluated with the sub-tet's own side;
///   2. integrates every sub-tet (and every uncut enriched tet as one) with a collapsed Gauss
///      tensor rule whose collapse sits on the front: on an edge lying on the front an edge-Duffy
///      map, on a vertex lying on the front a vertex-Duffy map, each with the radial variable
///      s = sigma^2, which makes r^(-1/2), r^(-1) (times the Jacobian) and sqrt(r) smooth in the
///      parameters: exponential convergence in the order n instead of O(h_sub);
///   3. shifts the branch functions' sampled gradients per element so that their integrals are
///      exact in the sense of the divergence theorem (consistent_gradients.h): the linear patch
///      test with a front inside the body holds to round-off.

/// Integration points in physical space with absolute weights (m^3) and the side (+1 / -1, or 0 =
/// "decide by the cut surface") with which the enriched basis is to be evaluated at each.
struct PointRule {
  std::vector<Eigen::Vector3d> x;  ///< metres
  std::vector<double> weights;     ///< m^3, all > 0; sum = volume covered
  std::vector<int> side;           ///< per point
  int size() const { return static_cast<int>(weights.size()); }
  void clear() {
    x.clear();
    weights.clear();
    side.clear();
  }
};

/// Gauss-Legendre nodes and weights on [0, 1] (weights sum to 1), n = 1..64, exact for
/// polynomials of degree 2n - 1. Throws xfem::Error outside 1..64.
void gauss_legendre_01(int n, std::vector<double>& nodes, std::vector<double>& weights);

/// The same rule, made once per process and kept: for callers that take a rule per piece or per
/// tet (gauss_legendre_01's Newton iterations and the vectors' allocations cost more than the rule's
/// use there). The same numbers as gauss_legendre_01(n, ...). Throws xfem::Error outside 1..64.
struct GaussRule01 {
  std::vector<double> nodes, weights;
};
const GaussRule01& gauss_legendre_rule_01(int n);

/// Edge-Duffy rule of the tet (a, b, c, d) collapsed on edge ab: x(s,t,w) = (1-s)(a + t(b-a)) +
/// s(c + w(d-c)), Jacobian 6 V s (1-s), s = sigma^2, n Gauss points in each of sigma, t, w
/// (n^3 points appended to `out` with `side`). Integrands ~ 1/r and r^(-1/2), r the distance to
/// the line ab, become smooth. Polynomials of degree p are integrated exactly for 2n - 1 >= 2p + 5
/// (p = 3: n >= 6).
void append_edge_rule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                      const Eigen::Vector3d& d, int n, int side, PointRule& out);

/// The same with `radial` Gauss points in sigma, `along` along ab and `across` along cd (the angle
/// around ab): the integrand near a straight front on ab is polynomial in sigma and t, smooth in w.
/// `squared` false: s = sigma (a plain collapsed Gauss rule, for bounded integrands: a polynomial of
/// degree p is exact for 2 radial - 1 >= p + 2 instead of 2p + 5).
void append_edge_rule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                      const Eigen::Vector3d& d, int radial, int along, int across, int side, PointRule& out,
                      bool squared = true);

/// Vertex-Duffy rule collapsed at a: x = a + u(b-a) + uv(c-b) + uvw(d-c), Jacobian 6 V u^2 v,
/// u = sigma^2: for integrands singular like 1/r at the vertex (r the distance to a line through a
/// that does not enter the tet). Polynomials of degree p exact for 2n - 1 >= 2p + 5.
void append_vertex_rule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                        const Eigen::Vector3d& d, int n, int side, PointRule& out);

/// The same with `radial` Gauss points in sigma and `across` in each of v, w.
void append_vertex_rule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                        const Eigen::Vector3d& d, int radial, int across, int side, PointRule& out);

/// How append_tet_rule lays out its points: Gauss points per direction of each kind of piece and
/// how deep pieces near the front are bisected. of_order(n) is the rule of order n, what every
/// caller of conforming_rule(..., n, ...) gets (the default n = 3); uniform(n) the rule of order n
/// before issue 35 (n in every direction, kept for comparisons).
struct TetRuleLayout {
  int radial = 3;       ///< pieces with an edge / a vertex on the front: points in the distance to it (sigma)
  int along = 3;        ///< edge on the front: points along it
  int across = 3;       ///< edge on the front: points in the angle around it; vertex: in each other direction
  int far = 3;          ///< pieces without a vertex on the front: n^3 edge rule at the edge nearest to it
  int distant = 3;      ///< ... those farther than distant_ratio times their longest edge from the front
  double distant_ratio = 1e300;
  int remote = 3;       ///< ... those farther than remote_ratio times their longest edge
  double remote_ratio = 1e300;
  int near_levels = 1;  ///< bisection levels at most, pieces with a vertex on the front
  int far_levels = 0;   ///< ... without one
  /// A piece without a vertex on the front is bisected (up to far_levels) while the front is nearer
  /// than far_split_ratio times its longest edge.
  double far_split_ratio = 0.5;
  bool far_squared = true;  ///< pieces without a vertex on the front: s = sigma^2 (true) or sigma (append_edge_rule)
  /// Remote pieces (beyond remote_ratio): the symmetric rule of `remote` points (4 or 14,
  /// append_symmetric_tet_rule) instead of the collapsed remote^3 rule: there the integrand is
  /// smooth on the piece's scale, and a symmetric rule reaches a higher degree with fewer points.
  bool remote_symmetric = false;
  /// A piece of a cut tet without a vertex on the front whose volume V, longest edge L and distance
  /// d to the front bound any positive rule's error on it, V L / (d (d + L)), below this fraction of
  /// its tet's V / h (h the tet's longest edge) takes the symmetric 4-point rule (0: never). The
  /// slivers a cut much finer than the mesh makes near the front: they are most of the points of such
  /// tets and almost none of their integral (of_order(n), n <= 3: 1e-2; docs/PERFORMANCE.md).
  double small_piece_fraction = 0;
  /// A piece whose edge the front touches at an interior point (not at one of its vertices) is
  /// split there first, so that the point becomes a vertex of the rules' collapse (of_order(n);
  /// uniform(n) keeps the rule before, which collapses onto the nearest whole edge).
  bool split_at_touch = true;
  /// A piece with an edge on the front whose opposite edge spans more than this angle around the
  /// front (radians) is bisected at that edge; one with a vertex on it, at the widest edge of the
  /// face opposite (0: never; of_order(n): a right angle).
  double max_angle = 0;
  /// The rule of order n before issue 35: n points in every direction, s = sigma^2 everywhere,
  /// bisection min(8, (n-2)^2) levels at the front, min(8, 2(n-3)) away from it.
  static TetRuleLayout uniform(int n);
  /// The rule of order n (conforming_rule, integration.order; issue 35, measured in
  /// docs/PERFORMANCE.md): where the error of uniform(n) is and where its points are wasted.
  ///  - Pieces without a vertex on the front (bounded integrand, the front near): a plain collapsed
  ///    rule (s = sigma) of n + 1 points per direction at the edge nearest to the front, n - 1
  ///    (at least 2) when the front is farther than the piece's longest edge (n <= 3: there the
  ///    symmetric 4-point rule). The sigma^2 map of uniform(n) made a cubic integrand degree 11 in
  ///    sigma; this is where its error was.
  ///  - Pieces with an edge on the front: n points in sigma, n - 2 (at least 2) along the front
  ///    (the integrand is smooth along it), n - 1 (at least 3) in the angle; with a vertex on it:
  ///    n in sigma, n - 1 (at least 3) in each other direction.
  ///  - A piece whose edge the front touches at an interior point is first split there
  ///    (split_at_touch); a piece at the front spanning more than a right angle around it is
  ///    bisected (max_angle).
  ///  - Bisection as uniform(n) from order 4 up, none below (at order 3 it moved the error of
  ///    uniform(3) by nothing measurable and cost 1.8x the points).
  static TetRuleLayout of_order(int n);
  /// The graded rule (integration.rule "graded"): of_order(3) with the pieces with a vertex on the
  /// front bisected once where the front passes close to the part they resolve, the others once
  /// while the front is nearer than half their size.
  static TetRuleLayout graded();
  /// The order whose consistent shift the graded rule takes (consistent_face_points: 4 per direction).
  static constexpr int graded_consistent_order = 3;
  /// The fast rule (xfem-assemble --rule fast, issue 35): of_order(3) with the symmetric 14-point
  /// rule on the pieces farther than half their longest edge from the front, where the integrand is
  /// smooth on the piece's scale; measured in docs/PERFORMANCE.md ("The fast rule").
  static TetRuleLayout fast();
  /// The order whose consistent shift the fast rule takes (the default's: 4 face points per direction).
  static constexpr int fast_consistent_order = 3;
};

/// A fully symmetric rule on the tet (a, b, c, d) with positive weights: `points` 4 (exact for
/// polynomials of degree 2) or 14 (degree 5; Walkington's / Keast's rule); appended with `side`.
/// Throws xfem::Error for another count.
void append_symmetric_tet_rule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                               const Eigen::Vector3d& d, int points, int side, PointRule& out);

/// Gauss points per direction on the faces for the consistent shift of a rule of order n
/// (sampled_gradients, branch_gradient_integrals): n + 1. The face integrands are bounded but
/// carry the front's sqrt(r): at order 3, 4 face points instead of 3 take the median error of the
/// branch x branch block from 4.3e-4 to 6.7e-5 (beam, docs/PERFORMANCE.md); more change little.
int consistent_face_points(int order);

/// The rule for one tet p[0..3] near `front` (may be empty): the vertices within 1e-6 of the tet's
/// longest edge of the front decide it: two -> edge rule on them, one -> vertex rule at it, none ->
/// edge rule on the edge closest to the front (any edge for an empty front). Where the front passes
/// closer than its length to the part of the tet the rule resolves (edge cd of an edge rule, the
/// face opposite a vertex rule's vertex, the whole tet otherwise), the integrand is nearly singular
/// and Gauss rules converge slowly: the tet is bisected at that part's longest edge, recursively
/// (front within one length of a part with a vertex on the front, within half the longest edge of
/// a tet without one; at most min(8, (n-2)^2) levels for a part with a vertex on the front,
/// min(8, 2(n-3)) otherwise: deep bisection pays only for accurate rules), and each half gets its
/// own rule. Appends n^3 points per
/// final tet with `side`.
void append_tet_rule(const std::array<Eigen::Vector3d, 4>& p, const CrackFront& front, int n, int side,
                     PointRule& out);
/// The same with any layout (append_tet_rule(p, front, n, ...) is TetRuleLayout::of_order(n)).
void append_tet_rule(const std::array<Eigen::Vector3d, 4>& p, const CrackFront& front, const TetRuleLayout& layout,
                     int side, PointRule& out);

/// The conforming rule of tet t: per sub-tet of a cut element (side = the sub-tet's side), or the
/// tet itself for an uncut one (side 0), each by append_tet_rule with TetRuleLayout::of_order(n).
void conforming_rule(const EnrichedMesh& em, const CutElementSplits& splits, int t, int n, PointRule& out);
/// The same with any layout of the front-singular rules (TetRuleLayout).
void conforming_rule(const EnrichedMesh& em, const CutElementSplits& splits, int t, const TetRuleLayout& layout,
                     PointRule& out);

/// The gradients of tet t's enriched basis at the points of `rule` (q x 3|C|: row p, column 3c + a
/// holds dPhi_c/dx_a at point p, the order of its C), evaluated with each point's side; with
/// consistent_order > 0 the branch functions' gradients shifted as element_stiffness_at_points
/// says (the shift of the rule of that order: consistent_face_points(consistent_order) per direction). What every element quantity integrated on the rule is built from: the linear stiffness
/// below, the nonlinear forces and tangent (element_forces.h).
/// `near_face_points` > 0: the faces the front passes near get that many points per direction
/// (branch_gradient_integrals' near_order; an experiment, bench/branch_rule_accuracy).
void sampled_gradients(const EnrichedMesh& em, int t, const PointRule& rule, int consistent_order,
                       FaceIntegralCache* face_cache, Eigen::MatrixXd& gradients, int near_face_points = 0);
/// The same, only the columns `columns` (increasing 3c + a; empty: all of them), into `gradients`
/// already shaped q x (their number) (e.g. a ScratchMatrix view), with `tips` a buffer for the
/// points' crack-tip coordinates: both kept by the caller from one tet to the next, so that no
/// memory is allocated per tet (scratch_matrix.h says why), and only the columns used are stored
/// (the closed form needs the branch ones alone). The same bits as those columns of the above.
/// `given_tips` (optional): the points' crack-tip coordinates, one per point, used instead of the
/// front's (straight_front_rule's, whose points lie outside the tet, where the front's own would
/// not be the line's); `tips` is then not touched.
/// `straight_face_points`: branch_gradient_integrals' straight_angle_points.
void sampled_gradients(const EnrichedMesh& em, int t, const PointRule& rule, int consistent_order,
                       FaceIntegralCache* face_cache, const std::vector<int>& columns,
                       Eigen::Ref<Eigen::MatrixXd> gradients, std::vector<TipCoordinates>& tips,
                       int near_face_points = 0, const std::vector<TipCoordinates>* given_tips = nullptr,
                       int straight_face_points = 0);

/// Stiffness of formula (5) of tet t (3|C| x 3|C|, order of its C, N/m) integrated with `rule`
/// (the enriched basis evaluated at each point with the point's side). Same layout as
/// element_stiffness of element_stiffness.h. With consistent_order > 0 the branch functions'
/// gradients are first shifted per element so that the rule integrates them exactly as the
/// divergence theorem does (branch_gradient_integrals, consistent_gradients.h, with
/// consistent_face_points(consistent_order) Gauss points per direction on the faces): the linear patch test then holds to round-off.
/// `face_cache` (optional): face integrals shared between neighbouring tets (consistent_gradients.h);
/// pass the same one for all the tets of an assembly.
void element_stiffness_at_points(const EnrichedMesh& em, int t, const PointRule& rule, const Lame& material,
                                 Eigen::MatrixXd& k, int consistent_order = 0, FaceIntegralCache* face_cache = nullptr);

}  // namespace xfem
