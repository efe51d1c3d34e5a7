// SPDX-License-Identifier: MIT
#include "xfem/crack_front.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "xfem/error.h"

namespace xfem {

namespace {

double segment_distance_squared(const FrontSegment& s, const Eigen::Vector3d& x) {
  const Eigen::Vector3d d = s.p1 - s.p0;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((x - s.p0).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (s.p0 + t * d - x).squaredNorm();
}

}  // namespace

CrackFront::CrackFront(std::vector<FrontSegment> segments) : segments_(std::move(segments)) {
  for (std::size_t i = 0; i < segments_.size(); ++i) {
    const FrontSegment& s = segments_[i];
    if (!((s.p1 - s.p0).norm() > 0) || !(s.b.norm() > 0) || !s.p0.allFinite() || !s.p1.allFinite() ||
        !s.b.allFinite())
      throw Error("crack front: segment " + std::to_string(i) + " is degenerate (zero length or zero normal)");
  }
}

int CrackFront::closest_segment(const Eigen::Vector3d& x) const {
  if (segments_.empty()) throw Error("crack front: no segments (the cut has no front inside the body)");
  // A linear scan: fronts have hundreds of segments, and a strict '<' gives ties to the lowest index.
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < segments_.size(); ++i) {
    const double d = segment_distance_squared(segments_[i], x);
    if (d < best_d) {
      best_d = d;
      best = static_cast<int>(i);
    }
  }
  return best;
}

CrackTipFrame CrackFront::frame(const Eigen::Vector3d& x) const {
  const FrontSegment& s = segments_[closest_segment(x)];
  const Eigen::Vector3d c = (s.p1 - s.p0).normalized();
  // b is the triangle's normal, orthogonal to its own edge up to rounding; re-orthogonalise so
  // that R is a rotation to machine precision.
  const Eigen::Vector3d b = (s.b - s.b.dot(c) * c).normalized();
  CrackTipFrame f;
  f.R.col(0) = b.cross(c);
  f.R.col(1) = b;
  f.R.col(2) = c;
  f.origin = s.p0;
  return f;
}

CrackFront read_front(const TetMesh& mesh, const std::string& file) {
  const DataArray& seg =
      require_array(mesh.field_data, "front_segments", "field", 6, static_cast<std::size_t>(-1), file, "xfem-classify");
  const DataArray& nrm =
      require_array(mesh.field_data, "front_normals", "field", 3, seg.tuples(), file, "xfem-classify");
  std::vector<FrontSegment> segments(seg.tuples());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    segments[i].p0 = Eigen::Vector3d(seg(i, 0), seg(i, 1), seg(i, 2));
    segments[i].p1 = Eigen::Vector3d(seg(i, 3), seg(i, 4), seg(i, 5));
    segments[i].b = Eigen::Vector3d(nrm(i, 0), nrm(i, 1), nrm(i, 2));
  }
  try {
    return CrackFront(std::move(segments));
  } catch (const Error& e) {
    throw Error(file + ": field array 'front_segments': " + e.what());
  }
}

void store_front(const CrackFront& front, TetMesh& mesh) {
  const auto& s = front.segments();
  DataArray seg = make_array(DataArray::Type::Float64, 6, s.size());
  DataArray nrm = make_array(DataArray::Type::Float64, 3, s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      seg.values[6 * i + k] = s[i].p0[k];
      seg.values[6 * i + 3 + k] = s[i].p1[k];
      nrm.values[3 * i + k] = s[i].b[k];
    }
  }
  mesh.field_data["front_segments"] = std::move(seg);
  mesh.field_data["front_normals"] = std::move(nrm);
}

}  // namespace xfem
