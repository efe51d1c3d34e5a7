// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <vector>

namespace xfem {

/// A convex planar polygon, its corners in order.
using Polygon = std::vector<Eigen::Vector3d>;

/// The parts of the convex polygon on and above / on and below the plane (point, normal): corners
/// within `tolerance` of it count as on it and go to both, crossing edges add their crossing point to
/// both. Either part may have fewer than 3 corners (nothing of the polygon on that side). Returns
/// whether the plane crosses the polygon (corners beyond `tolerance` on both sides).
bool split_polygon(const Polygon& poly, const Eigen::Vector3d& point, const Eigen::Vector3d& normal, double tolerance,
                   Polygon& above, Polygon& below);

}  // namespace xfem
