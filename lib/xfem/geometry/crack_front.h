// SPDX-License-Identifier: MIT
#pragma once
#include <memory>
#include <vector>

#include "xfem/core/mesh.h"
#include "xfem/geometry/segment_tree.h"

namespace xfem {

/// One straight piece of the cut front (a boundary edge of the cut inside the body), stored so
/// that the crack-tip frame of DESIGN.md follows from it alone:
///   b = unit normal of the cut triangle the edge belongs to,
///   c = (p1 - p0) / |p1 - p0|,
///   a = b x c, pointing away from the cut into intact material (p0, p1 are ordered to make it so).
struct FrontSegment {
  Eigen::Vector3d p0, p1;
  Eigen::Vector3d b;  ///< unit normal of the owning cut triangle
};

/// Local frame at the closest front segment: x_abc = R^T (x - origin), R = (a | b | c).
struct CrackTipFrame {
  Eigen::Matrix3d R;
  Eigen::Vector3d origin;
};

/// Continuous crack-tip coordinates of a point (branch_functions.h): xa ahead of the front, xb
/// along the cut's normal, both measured from the point's foot P on the front in the frame
/// (a, b, c) interpolated along the front at P (FrontPolyline::frame), with their gradients.
struct TipCoordinates {
  double xa = 0.0, xb = 0.0;          ///< metres
  Eigen::Matrix<double, 2, 3> grad;   ///< row 0: grad xa, row 1: grad xb (global coordinates)
};

/// The front's segments joined end to end (p1 of one = p0 of the next, within 1e-9 of the front's
/// size) into chains: a polyline per connected piece of front, open (ending on the body's surface)
/// or closed (a front that is a loop, e.g. a disc-shaped cut inside the body). Vertices keep the
/// segments' orientation, so a = b x c points away from the cut everywhere along a chain.
struct FrontPolyline {
  std::vector<Eigen::Vector3d> points;   ///< vertices; a closed chain does not repeat its first
  std::vector<Eigen::Vector3d> normals;  ///< per segment i (points i -> i+1): the cut's unit normal b
  std::vector<double> arc;               ///< arc length at each vertex, arc[0] = 0
  bool closed = false;
  double length = 0.0;                   ///< total arc length, metres (a closed chain's closing segment included)
  /// Unit tangent c and normal b at vertices 0 .. segments(), the values frame() interpolates,
  /// filled by front_polylines (frame() is called for every integration point of a branch-enriched
  /// tet); a chain built without them has them computed on each call.
  std::vector<Eigen::Vector3d> vertex_c, vertex_b;

  int segments() const { return static_cast<int>(points.size()) - (closed ? 0 : 1); }
  /// Position, unit tangent c and unit cut normal b at arc length s (s is wrapped for a closed
  /// chain, clamped to [0, length] for an open one). Tangent and normal are those of the segment
  /// containing s, averaged with the neighbour's at a vertex.
  Eigen::Vector3d position(double s) const;
  void frame(double s, Eigen::Vector3d& c, Eigen::Vector3d& b) const;
  /// The closest point of the chain to x: its arc length and the distance; `segment` (optional)
  /// receives its segment, `inside` whether it lies strictly inside that segment (not at a vertex).
  void closest(const Eigen::Vector3d& x, double& s, double& distance, int* segment = nullptr,
               bool* inside = nullptr) const;
  /// Signed arc length from s0 to s (the shorter way round for a closed chain).
  double arc_offset(double s0, double s) const;
};

/// The cut front: a set of segments with a search for the one closest to a point.
class CrackFront {
 public:
  CrackFront() = default;
  explicit CrackFront(std::vector<FrontSegment> segments);
  bool empty() const { return segments_.empty(); }
  const std::vector<FrontSegment>& segments() const { return segments_; }
  /// Index of the segment closest to x (Euclidean distance to the closed segment); ties go to the
  /// lowest index, so the answer is deterministic. Throws xfem::Error if there are no segments.
  int closest_segment(const Eigen::Vector3d& x) const;
  /// The frame of the closest segment (origin p0).
  CrackTipFrame frame(const Eigen::Vector3d& x) const;
  /// The crack-tip coordinates of x for the branch functions, continuous in x: the foot of x is
  /// the front point P(s) whose normal plane (normal to the tangent c(s) interpolated along the
  /// front) contains x, the nearest one if several (beyond an open chain's end: the end point);
  /// with the frame (a, b, c)(s) interpolated there, xa = a . (x - P), xb = b . (x - P). On a
  /// straight front this is frame(x)'s (xa, xb) exactly; on a front of segments it no longer jumps
  /// where the closest segment changes. Continuous within the front's radius of curvature (the
  /// normal planes of a curved front meet beyond it). Throws xfem::Error if there are no segments.
  TipCoordinates coordinates(const Eigen::Vector3d& x) const;
  /// The chain segments (indices in the chains' order) that coordinates() can take for any point of
  /// a region: the nearest segment, or one near enough to hold the foot, of some point in it. The
  /// region is the ball (centre, radius) around `points` (e.g. a tet's vertices), which holds their
  /// convex hull. Found once per tet, it replaces the segment tree's two searches per point.
  struct Near {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double radius = -1;             ///< metres; < 0: no region (coordinates(x, near) searches the tree)
    std::vector<int> chain_segments;  ///< for coordinates(), increasing
    std::vector<int> segments;        ///< for distance(): indices in segments(), increasing
  };
  /// What a Near list serves: coordinates(x, near), distance(..., near) or both.
  enum class NearFor { coordinates, distances, both };
  Near near(const Eigen::Vector3d* points, int count, NearFor use = NearFor::both) const;
  /// coordinates(x[i]) for i < count into out[i], bit for bit: for integration rules, whose
  /// consecutive points lie close together. Each run of up to 64 consecutive points gets its own near()
  /// list, found with the tree once, and its points scan that short list.
  void coordinates(const Eigen::Vector3d* x, int count, TipCoordinates* out) const;
  /// coordinates(x), bit for bit, scanning only near.chain_segments when x lies in near's ball (the
  /// segment tree otherwise, as coordinates(x)).
  TipCoordinates coordinates(const Eigen::Vector3d& x, const Near& near) const;
  /// The front's chains (front_polylines), built once.
  const std::vector<FrontPolyline>& chains() const { return *chains_; }
  /// Distance from x to the front (its nearest segment); +infinity for an empty front.
  double distance(const Eigen::Vector3d& x) const;
  /// Distance from the segment pq to the front; +infinity for an empty front.
  double distance(const Eigen::Vector3d& p, const Eigen::Vector3d& q) const;
  /// The same two, bit for bit, from near.segments when x (p and q) lie in near's ball: the
  /// rules of a tet's pieces ask for these at every piece's vertices and edges.
  double distance(const Eigen::Vector3d& x, const Near& near) const;
  double distance(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Near& near) const;

 private:
  // Segment trees (segment_tree.h) over the segments in their order and in the chains' order,
  // built once with the chains: the searches above visit only the segments near the point.
  struct Index {
    SegmentTree by_segment, by_chain;
    std::vector<int> chain_of, segment_of;  ///< per chain-order segment: its chain and index in it
    double longest = 0;                     ///< the longest chain segment, metres
  };
  // coordinates() with the candidate segments of its two passes given by `visit1(x, bound2, f)` and
  // `visit2(x, reach2, f)`, each calling f(k) in increasing chain index k.
  template <class Visit1, class Visit2>
  TipCoordinates coordinates_visiting(const Eigen::Vector3d& x, Visit1&& visit1, Visit2&& visit2) const;
  std::vector<FrontSegment> segments_;
  std::shared_ptr<const std::vector<FrontPolyline>> chains_;
  std::shared_ptr<const Index> index_;
};

/// The chains of a front, in the order of their first segment. Throws xfem::Error for an empty
/// front.
std::vector<FrontPolyline> front_polylines(const CrackFront& front);
std::vector<FrontPolyline> front_polylines(const std::vector<FrontSegment>& segments);

/// Reads/writes the front as the field arrays `front_segments` (Float64, 6 components: p0, p1)
/// and `front_normals` (Float64, 3 components: b) of a mesh written by xfem-classify.
CrackFront read_front(const TetMesh& mesh, const std::string& file);
void store_front(const CrackFront& front, TetMesh& mesh);

}  // namespace xfem
