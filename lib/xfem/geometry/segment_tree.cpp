// SPDX-License-Identifier: MIT
#include "xfem/geometry/segment_tree.h"

#include <algorithm>
#include <limits>

#include "xfem/core/error.h"

namespace xfem {

namespace {
constexpr int kLeafSegments = 4;
}

SegmentTree::SegmentTree(const std::vector<Eigen::Vector3d>& p0, const std::vector<Eigen::Vector3d>& p1) {
  if (p0.size() != p1.size()) throw Error("segment tree: as many start points as end points are needed");
  if (p0.empty()) return;
  p0_ = p0;
  p1_ = p1;
  nodes_.reserve(2 * p0.size() / kLeafSegments + 2);
  build(p0, p1, 0, static_cast<int>(p0.size()));
}

int SegmentTree::build(const std::vector<Eigen::Vector3d>& p0, const std::vector<Eigen::Vector3d>& p1, int begin,
                       int end) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Eigen::Vector3d lo = p0[begin], hi = p0[begin];
  for (int k = begin; k < end; ++k) {
    lo = lo.cwiseMin(p0[k]).cwiseMin(p1[k]);
    hi = hi.cwiseMax(p0[k]).cwiseMax(p1[k]);
  }
  Node n;
  n.centre = 0.5 * (lo + hi);
  // A ball holding both ends of a segment holds the segment.
  for (int k = begin; k < end; ++k)
    n.radius = std::max({n.radius, (p0[k] - n.centre).norm(), (p1[k] - n.centre).norm()});
  n.begin = begin;
  n.end = end;
  if (end - begin > kLeafSegments) {
    // Halving the index range keeps the depth at log2(segments / 4), far within the walk's stack.
    const int mid = begin + (end - begin) / 2;
    n.left = build(p0, p1, begin, mid);
    n.right = build(p0, p1, mid, end);
  }
  nodes_[index] = n;
  return index;
}

double SegmentTree::nearest_bound2(const Eigen::Vector3d& x) const {
  if (nodes_.empty()) return std::numeric_limits<double>::infinity();
  const Node* n = &nodes_[0];
  while (n->left >= 0) {
    const Node &l = nodes_[n->left], &r = nodes_[n->right];
    n = (x - l.centre).norm() - l.radius <= (x - r.centre).norm() - r.radius ? &l : &r;
  }
  double best = std::numeric_limits<double>::infinity();
  for (int k = n->begin; k < n->end; ++k) best = std::min(best, point_segment_distance(x, p0_[k], p1_[k]));
  return best * best;
}

}  // namespace xfem
