// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>

namespace xfem {

/// An organ-like smooth closed body (a stand-in for the paper's liver, section 5): a flattened
/// ellipsoid, thicker at +x than at -x and bent so that its ends curl up. With a = 0.075,
/// b = 0.05, c0 = 0.035 (metres), c(x) = c0 (1 + 0.35 x / a) and s(x) = 0.012 (x / a)^2:
///   f(p) = (x / a)^2 + (y / b)^2 + ((z - s(x)) / c(x))^2 - 1,
/// negative inside, zero on the surface. The body spans x in [-0.075, 0.075] (0.15 m), y in
/// [-0.05, 0.05], z in about [-0.036, 0.039], and is 2 c(x) sqrt(1 - x^2/a^2) thick through
/// y = 0: 0.050 m at x = -a/2, 0.071 m at x = +a/2.
/// Every cross-section x = const is an ellipse of area pi b c(x) (1 - x^2/a^2) (the bend only
/// shears it), so the volume is (4/3) pi a b c0, that of the unbent ellipsoid.
double organ_function(const Eigen::Vector3d& p);

/// Volume enclosed by organ_function's zero set, m^3: (4/3) pi a b c0 = 5.4978e-4.
double organ_volume();

/// A sphere around the origin that holds the body with margin (radius, metres): the bounding
/// object Mesh_3 needs.
constexpr double organ_bounding_radius = 0.1;

}  // namespace xfem
