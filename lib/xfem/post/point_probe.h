// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "xfem/post/rms_error.h"

namespace xfem {

/// A point where a solution is sampled (xfem-probe): its position and, for a point on the cut,
/// the face to evaluate (+1: the side the cut's normal points to, -1: the other, 0: none).
struct ProbePoint {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();  ///< metres
  int side = 0;
};

/// Reads probe points from a CSV file (a header naming the columns x,y,z or x,y,z,side, then one
/// point per line; '#' lines are comments) or a VTK XML polydata (.vtp: its points, and point
/// array `side` when present). Throws xfem::Error "<path>: line 4: ..." / "<path>: ..." on an
/// unreadable file, a wrong header, a non-numeric or non-finite value, a side other than -1, 0,
/// 1, or no point at all.
std::vector<ProbePoint> read_probe_points(const std::string& path);

/// The solution `field` at every point, on the point's side. Throws xfem::Error naming
/// `points_name` and the (1-based) point when a point lies outside the mesh beyond the field's
/// snapping radius: sampling there would be an extrapolation, not a value of the solution.
std::vector<Eigen::Vector3d> probe(const FieldAt& field, const std::vector<ProbePoint>& points,
                                   const std::string& points_name);

/// Writes "x,y,z,side,ux,uy,uz" and one line per point (17 significant digits), atomically.
void write_probe_csv(const std::vector<ProbePoint>& points, const std::vector<Eigen::Vector3d>& values,
                     const std::string& path);

}  // namespace xfem
