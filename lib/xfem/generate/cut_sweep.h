// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

#include "xfem/core/mesh.h"

namespace xfem {

/// The times of a sweep (a cut that grows): the cell array `time` of a cut surface, one value per
/// triangle (seconds): when the blade creates the triangle (docs/FORMATS.md, "sweep.vtp").
/// Throws xfem::Error naming `file` when the array is missing, has more than one component, or a
/// value is not finite.
std::vector<double> cut_times(const TriangleMesh& cut, const std::string& file);

/// The cut at time t: the triangles with time <= t, in their order, with only the points they use
/// (in their order) and every array kept. May have no triangle.
TriangleMesh cut_until(const TriangleMesh& sweep, const std::vector<double>& times, double t);

/// The sweep's ids of cut_until's triangles: the k with times[k] <= t, increasing.
std::vector<int> cut_until_ids(const std::vector<double>& times, double t);

/// The K step times of a sweep whose triangles have times `times`: t_k = t0 + k (t1 - t0) / K,
/// k = 1..K, t0 and t1 the first and last time (the last step is the whole cut). K >= 1.
std::vector<double> step_times(const std::vector<double>& times, int steps);

/// The path of a blade's top end: a polyline, or a circular arc (centre, radius, from angle a0
/// to a1 in degrees, in the plane through the centre perpendicular to `axis`, counter-clockwise
/// about `axis`, angle 0 along the plane direction closest to x).
struct BladePath {
  std::vector<Eigen::Vector3d> polyline;  ///< >= 2 points, or empty for the arc
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(), axis = Eigen::Vector3d::UnitZ();
  double radius = 0, a0 = 0, a1 = 0;
};

/// A blade (a straight segment of length `depth`, m) hanging from a point moving along `path`,
/// pointing along `down` (a unit vector, default -z) turned by `tilt` degrees about the path's
/// tangent: the swept surface as triangles of about `resolution` metres, each with the cell array
/// `time` = duration x (arc length at which the blade's leading edge has passed the triangle) /
/// (path length). The normal (+1 side) is tangent x blade direction, consistent over the surface.
/// Throws xfem::Error for a path of zero length, a non-positive depth, resolution or duration, a
/// blade along the path's tangent, or a resolution finer than 1e6 triangles would need.
TriangleMesh cut_sweep(const BladePath& path, double depth, const Eigen::Vector3d& down, double tilt,
                       double resolution, double duration);

}  // namespace xfem
