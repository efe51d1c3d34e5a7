// SPDX-License-Identifier: MIT
#pragma once
#include <array>
#include <memory>
#include <vector>

#include "xfem/core/mesh.h"

namespace xfem {

/// The cut surface Gamma^c (paper 3.2) with a spatial search structure over its triangles
/// (a CGAL AABB tree; CGAL stays inside the .cpp). Normals n^c = (P1 - P0) x (P2 - P0) define the
/// side above (+1) and below (-1) the cut.
class CutSurface {
 public:
  /// `cut` must be validated (read_triangle_mesh / validate_triangle_mesh): consistently oriented.
  explicit CutSurface(TriangleMesh cut);
  ~CutSurface();
  CutSurface(CutSurface&&) noexcept;
  CutSurface& operator=(CutSurface&&) noexcept;

  const TriangleMesh& mesh() const;

  /// The point of the cut closest to x, the triangle it lies in and the distance.
  struct Closest {
    int triangle = -1;
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    double distance = 0.0;
  };
  Closest closest(const Eigen::Vector3d& x) const;

  /// H(x) (paper, formula (2)): +1 when x lies on the side the cut's normal points to, -1 below,
  /// judged at the closest cut point (with the angle-weighted pseudo-normal where that point is on
  /// an edge or vertex of the cut, so that curved cuts give one answer). A point on the cut is +1.
  int side(const Eigen::Vector3d& x) const;
  /// side(x), bit for bit, judged at `closest` = closest(x), for a caller that has it: one search
  /// instead of two.
  int side(const Eigen::Vector3d& x, const Closest& closest) const;

  /// side() of rows begin..end-1 of `points`, in order. Same answers, several times faster for
  /// spatially coherent points such as a mesh's nodes: each search starts from the previous row's
  /// closest point. Safe to call from several threads at once.
  std::vector<int> sides(const Points& points, long begin, long end) const;
  /// side() of points[0 .. count-1] into out[0 .. count-1], the same way: for a few points close
  /// together, such as the centroids of one tet's pieces (split_by_cut, split_at_front).
  void sides(const Eigen::Vector3d* points, int count, int* out) const;

  /// Does the closed segment [a, b] meet the closed cut surface? Exact predicates.
  bool meets_segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;

  /// Boundary edges of the cut (edges of exactly one triangle): endpoints in the direction the
  /// triangle traverses them, and that triangle's index.
  struct BoundaryEdge {
    int p0 = -1, p1 = -1, triangle = -1;
  };
  const std::vector<BoundaryEdge>& boundary_edges() const;

  /// Unit normal of triangle `t`.
  Eigen::Vector3d unit_normal(int t) const;

  /// The triangles that meet the closed tetrahedron (p[0], .., p[3]), in increasing order (exact
  /// predicates on the given coordinates).
  std::vector<int> triangles_meeting(const std::array<Eigen::Vector3d, 4>& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace xfem
