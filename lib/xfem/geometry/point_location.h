// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "xfem/core/mesh.h"

namespace xfem {

/// The point of triangle (a, b, c) closest to p, by the Voronoi regions of its vertices, edges and
/// face (Ericson, Real-Time Collision Detection, 5.1.5).
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c);

/// Finds the tetrahedra of a mesh that contain a point, through a uniform grid of buckets over
/// the tets' bounding boxes (about one tet per bucket): O(1) per query for well-shaped meshes.
class PointLocator {
 public:
  explicit PointLocator(const TetMesh& mesh);

  /// Barycentric coordinates of x in tet t (sum to 1; all >= 0 inside).
  Eigen::Vector4d barycentric(int t, const Eigen::Vector3d& x) const;

  /// Every tet containing x, with tolerance `tol` on the barycentric coordinates (a point on a
  /// shared face or edge is in all its tets), in increasing tet order.
  std::vector<int> containing(const Eigen::Vector3d& x, double tol = 1e-10) const;

  /// The tet nearest to x: one containing it, else the one at the least Euclidean distance,
  /// searched among the buckets within `radius` (ties: lowest id). Returns -1 if none lies within
  /// `radius`. `distance` receives the distance (0 inside).
  int nearest(const Eigen::Vector3d& x, double radius, double* distance = nullptr) const;

 private:
  const TetMesh& mesh_;
  Eigen::Vector3d lo_, cell_;
  Eigen::Vector3i dims_;
  std::vector<int> start_, items_;  // CSR: bucket b holds items_[start_[b] .. start_[b+1])
  std::vector<Eigen::Matrix4d> inverse_;  // barycentric maps, one per tet
  Eigen::Vector3i bucket_of(const Eigen::Vector3d& x) const;
};

}  // namespace xfem
