// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "xfem/core/mesh.h"

namespace xfem {

/// A bounding-sphere hierarchy over a list of segments (a balanced binary tree over index ranges,
/// in the list's order, which keeps the consecutive segments of a front together), for the scans
/// that look for the front segments nearest to a point: every integration point of a tet with
/// crack-tip functions makes one, and a linear scan over a curved front's hundreds of segments
/// dominated the assembly. The visits come in increasing index, so a scan keeping the first
/// segment with a strict '<' picks the same segment as the linear scan it replaces, bit for bit.
class SegmentTree {
 public:
  SegmentTree() = default;
  /// Segment k runs from p0[k] to p1[k].
  SegmentTree(const std::vector<Eigen::Vector3d>& p0, const std::vector<Eigen::Vector3d>& p1);

  /// Calls visit(k), in increasing k, for the segments that may lie within sqrt(bound2) of the
  /// point x, and for no segment farther than that from x (whole subtrees are skipped); `visit` may
  /// lower bound2 as it goes (a nearest-segment search) or leave it (a range search).
  template <class Visit>
  void visit_near(const Eigen::Vector3d& x, double& bound2, Visit&& visit) const {
    walk([&](const Node& n) { return (x - n.centre).norm(); }, bound2, visit);
  }
  /// An upper bound of the squared distance from x to its nearest segment, found by descending to
  /// the leaf nearest to x: a nearest-segment search started with it (and a selection starting at
  /// infinity) skips from the start what lies farther.
  double nearest_bound2(const Eigen::Vector3d& x) const;
  /// The same for the segment pq: the segments that may lie within sqrt(bound2) of it.
  template <class Visit>
  void visit_near(const Eigen::Vector3d& p, const Eigen::Vector3d& q, double& bound2, Visit&& visit) const {
    walk([&](const Node& n) { return point_segment_distance(n.centre, p, q); }, bound2, visit);
  }

 private:
  struct Node {
    Eigen::Vector3d centre;
    double radius = 0;     ///< every segment of the node lies in the ball (centre, radius)
    int begin = 0, end = 0;  ///< segments begin .. end-1
    int left = -1, right = -1;  ///< children; -1 for a leaf
  };
  std::vector<Node> nodes_;
  std::vector<Eigen::Vector3d> p0_, p1_;

  int build(const std::vector<Eigen::Vector3d>& p0, const std::vector<Eigen::Vector3d>& p1, int begin, int end);

  // Depth first, left child first (increasing segment index). A node is skipped when its ball is
  // farther than sqrt(bound2): the lower bound is kept a hair below the exact one (1e-9 relative)
  // so that rounding never skips a segment the linear scan would have taken.
  template <class Distance, class Visit>
  void walk(Distance&& centre_distance, double& bound2, Visit& visit) const {
    if (nodes_.empty()) return;
    int stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      const double d = centre_distance(n);
      const double lower = d - n.radius - 1e-9 * (d + n.radius);
      if (lower > 0 && lower * lower > bound2) continue;
      if (n.left < 0) {
        for (int k = n.begin; k < n.end; ++k) visit(k);
      } else {
        stack[top++] = n.right;
        stack[top++] = n.left;
      }
    }
  }
};

}  // namespace xfem
