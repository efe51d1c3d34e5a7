// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <functional>
#include <vector>

namespace xfem {

/// Integration points over a tetrahedron in barycentric form: integral over T of f is about
/// volume(T) * sum_k weights[k] f(sum_m lambda[k][m] P_m). Weights sum to 1.
struct Quadrature {
  std::vector<Eigen::Vector4d> lambda;  ///< barycentric coordinates of each point (sum 1, all > 0)
  std::vector<double> weights;          ///< fractions of the tet's volume
  /// Oversampling rules only: the sub-tet (barycentric corners as columns) each point is the
  /// centroid of, and how often refine_at_cut may split them.
  std::vector<Eigen::Matrix4d> cells;
  int refine_levels = 0;
  int size() const { return static_cast<int>(weights.size()); }
};

/// The paper's oversampling rule (3.6, DESIGN.md "Integration"): the tet is split uniformly into
/// m^3 congruent-volume sub-tets (the Freudenthal subdivision of its edges into m parts), m the
/// smallest integer with m^3 > `requested`, one point at each sub-tet's centroid with weight
/// 1/m^3. requested = 30 (the paper's beam) gives m = 4, 64 points. The rule integrates linear
/// functions exactly and any bounded function to O(1/m) (O(1/m^2) for smooth ones).
/// Points are in a fixed order (deterministic). `refine_levels` (0..8) is stored for
/// refine_at_cut. Throws xfem::Error for requested < 1 or levels outside 0..8.
Quadrature oversampling_quadrature(int requested, int refine_levels = 0);

/// `rule` (an oversampling rule) refined at the cut: each sub-tet whose 4 corners and centroid do
/// not all lie on the same side (`side(lambda)`: +1 / -1 at the point with barycentric coordinates
/// lambda) is split into 8 (at its edge midpoints), recursively up to rule.refine_levels times;
/// every final sub-tet gets its centroid with its volume fraction as weight. The Heaviside part of
/// a cut element's integrals then errs only in a band 2^-levels as thick around the cut, and
/// small pieces cut off a tet still receive points (without any, a sign DOF with small support
/// gets a zero row in K). With refine_levels = 0 (the paper's rule) `rule` comes back unchanged.
Quadrature refine_at_cut(const Quadrature& rule, const std::function<int(const Eigen::Vector4d&)>& side);

/// The sub-tets themselves (m^3 of them, barycentric corners), for tests and for refining.
std::vector<Eigen::Matrix4d> uniform_subtets(int m);  ///< column c: barycentric corner c

}  // namespace xfem
