// SPDX-License-Identifier: MIT
#pragma once
#include <array>

namespace xfem {

/// Cost guard: meshes beyond this many tets (or cuts beyond this many triangles) take hours or
/// exhaust memory; refused with the estimate unless --allow-large.
constexpr double kMaxGeneratedElements = 2e7;

/// Throws xfem::Error "about N <what> requested (limit 2e+07; ...)" when `estimate` exceeds
/// kMaxGeneratedElements (or is NaN) and `allowed` (--allow-large) is false.
void check_element_estimate(double estimate, const char* what, bool allowed);

/// Regular tets of edge `size` fill a volume V with about 6 sqrt(2) V / size^3 tets.
double tets_for(double volume, double size);

/// Coordinates beyond 1e6 m are not a body xfem-mesh meshes (and overflow volumes and CGAL).
/// Throws xfem::Error "<option> <value>: coordinates must lie within 1e6 m of the origin".
void check_extent(const std::array<double, 3>& a, const char* option);

}  // namespace xfem
