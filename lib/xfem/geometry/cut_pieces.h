// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <array>
#include <vector>

#include "xfem/geometry/crack_front.h"
#include "xfem/geometry/cut_surface.h"

namespace xfem {

using TetCorners = std::array<Eigen::Vector3d, 4>;

/// A tetrahedron split along the cut into pieces that each lie on one side of it.
struct CutPieces {
  std::vector<TetCorners> tets;  ///< corners (m) of each piece
  std::vector<int> side;         ///< per piece: H = +1 above the cut, -1 below (CutSurface::side at its centroid)
  double volume_above = 0.0;     ///< m^3, sum over the pieces with side +1
  double volume_below = 0.0;     ///< m^3, sum over the pieces with side -1
};

/// The part of triangle (a, b, c) inside the closed tet p, as a convex polygon (empty if none).
std::vector<Eigen::Vector3d> clip_triangle(const TetCorners& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                           const Eigen::Vector3d& c);

/// Area of a planar convex polygon.
double polygon_area(const std::vector<Eigen::Vector3d>& polygon);

/// Splits the tet p along the cut: every cut triangle that passes through the inside of a piece
/// splits that piece by its plane (the marching-tetrahedra cases: a tet and a prism, two prisms, or
/// with corners on the plane a tet and a pyramid, two tets), so that in the end no cut triangle
/// crosses the inside of a piece. Each piece then lies on one side of the cut, whatever the cut
/// does inside the tet (a fold, several folds, a cut through a corner or along a face), and the
/// volumes on each side are exact up to round-off for a piecewise planar cut. A corner within
/// 1e-12 of the tet's longest edge from a plane counts as on it (no slivers of round-off size).
/// Pieces of zero volume are not returned. Meant for the elements the cut separates, not for those
/// its front passes through (there H also jumps across the cut's extension ahead of the front).
CutPieces split_by_cut(const TetCorners& p, const CutSurface& cut);

/// The same, given `triangles`: the cut's triangles that meet p (CutSurface::triangles_meeting),
/// for callers that need them too.
CutPieces split_by_cut(const TetCorners& p, const CutSurface& cut, const std::vector<int>& triangles);

/// Splits a tet the cut's front passes through (a partially cut element) into exact pieces: by
/// the plane of every cut triangle that passes through a piece's inside, as split_by_cut, and then
/// by the plane through every front segment that meets the tet, spanned by the segment and its
/// cut normal b (every piece the segment meets, even at a point, is split). Each piece then lies
/// on one side of the cut's plane, and a piece with a face on the cut lies behind the front: the
/// wound ends exactly at the front, which is made of the pieces' edges (where the front-singular
/// rules of conforming_quadrature.h want it). Exact for a piecewise planar cut with a polygonal
/// front, kinks inside the element included. Ahead of the front the side of a piece only names the
/// half of the cut's plane extended it lies in (the material is whole there). `front` is the whole
/// front; segments that miss the tet are skipped.
CutPieces split_at_front(const TetCorners& p, const CutSurface& cut, const std::vector<int>& triangles,
                         const std::vector<FrontSegment>& front);

/// The pieces of tet p on either side of the plane through `point` with unit `normal` (side +1 on
/// the normal's side), appended to `above` and `below`. Corners within `tolerance` of the plane count
/// as on it; a tet the plane does not cross goes whole to its side. Exposed for tests.
void split_by_plane(const TetCorners& p, const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                    double tolerance, std::vector<TetCorners>& above, std::vector<TetCorners>& below);

}  // namespace xfem
