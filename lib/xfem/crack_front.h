// SPDX-License-Identifier: MIT
#pragma once
#include <vector>

#include "xfem/mesh.h"

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

 private:
  std::vector<FrontSegment> segments_;
};

/// Reads/writes the front as the field arrays `front_segments` (Float64, 6 components: p0, p1)
/// and `front_normals` (Float64, 3 components: b) of a mesh written by xfem-classify.
CrackFront read_front(const TetMesh& mesh, const std::string& file);
void store_front(const CrackFront& front, TetMesh& mesh);

}  // namespace xfem
