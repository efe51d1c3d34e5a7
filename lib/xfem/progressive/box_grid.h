// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <array>
#include <vector>

namespace xfem {

/// Axis-aligned boxes bucketed in a uniform grid, to find the boxes that meet a query box in about
/// the time of the answer: progressive cutting asks it, for every tet with enriched DOFs at every
/// step, which of the cut's (up to thousands of) triangles lie near the tet (element_key).
class BoxGrid {
 public:
  using Box = Eigen::Matrix<double, 3, 2>;  ///< columns lo, hi

  /// Buckets `boxes` (kept by reference) in cells of about `cell` (> 0) on a side; coarser when
  /// that would make more than a few cells per box.
  BoxGrid(const std::vector<Box>& boxes, double cell);

  /// The indices of the boxes meeting the closed box [lo, hi] (touching counts), increasing: the
  /// same as testing every box.
  void meeting(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, std::vector<int>& out) const;

 private:
  long cell_of(int axis, double x) const;
  const std::vector<Box>& boxes_;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  double cell_ = 1;
  std::array<long, 3> n_{{0, 0, 0}};
  std::vector<std::vector<int>> cells_;
};

}  // namespace xfem
