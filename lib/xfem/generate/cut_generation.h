// SPDX-License-Identifier: MIT
#pragma once
#include <vector>

#include "xfem/core/mesh.h"

namespace xfem {

/// Cut surfaces made from parameters (the inputs of xfem-mesh cut-*). Every result is an open,
/// consistently oriented triangle mesh: the normal (P1 - P0) x (P2 - P0) of every triangle points
/// to the same side, the side above the cut (H = +1, DESIGN.md "Numerics"). Points are numbered
/// row by row; the same arguments give the same mesh bit for bit. No arrays are attached.

/// The parallelogram with corners p00, p10 = p00 + e1, p01 = p00 + e2, split into
/// divisions(0) x divisions(1) quads of two triangles each: (divisions(0)+1)(divisions(1)+1)
/// points, 2 divisions(0) divisions(1) triangles, normal along e1 x e2 with e1 = p10 - p00,
/// e2 = p01 - p00. The points of the edges through p00 and through p10 are p00 + t e2 and
/// p10 + t e2, so an edge given by exact corner coordinates stays exact (the beam cut's front
/// x = 0.015). Metres. Throws xfem::Error for divisions < 1 or e1, e2 (nearly) parallel.
TriangleMesh cut_parallelogram(const Eigen::Vector3d& p00, const Eigen::Vector3d& p10, const Eigen::Vector3d& p01,
                               const Eigen::Vector2i& divisions);

/// The paper's beam cut (DESIGN.md, "The benchmark"): the plane z = 0.1, x in [-0.01, 0.015],
/// y in [-0.01, 0.07], normal +z; `divisions` as in cut_parallelogram (1 x 1: the two triangles).
TriangleMesh beam_cut(const Eigen::Vector2i& divisions = Eigen::Vector2i(1, 1));

/// A sinusoidal sheet (the "sinusoidal blade" of the paper's liver example, section 5):
/// z = z0 + amplitude sin(2 pi x / wavelength) over x in [lo(0), hi(0)], y in [lo(1), hi(1)],
/// sampled on a divisions(0) x divisions(1) grid, two triangles per quad, normal pointing to +z
/// (the normal's z component is positive everywhere). Metres.
/// Throws xfem::Error for divisions < 1, an empty rectangle or a non-positive wavelength.
TriangleMesh cut_sine(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double z0, double amplitude,
                      double wavelength, const Eigen::Vector2i& divisions);

/// A flat disc of `radius` around `centre` in the plane normal to `normal` (any length), the
/// cut's normal along `normal`: a cut whose front lies inside the body on all sides. `rings`
/// concentric rings at radii radius k / rings, ring k with 6 k points (ring 0 = the centre),
/// so 1 + 3 rings (rings + 1) points and 6 rings^2 triangles; the outline is the regular
/// 6 rings-gon inscribed in the circle (area 3 rings radius^2 sin(2 pi / (6 rings))).
/// Throws xfem::Error for rings < 1, radius <= 0 or a zero normal.
TriangleMesh cut_disc(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal, double radius, int rings);

/// A folded (zig-zag) sheet: piecewise planar, z = f(x) over x in [lo(0), hi(0)], y in
/// [lo(1), hi(1)], with `folds` straight fold lines running along y (across a beam's width).
/// The folds + 1 flat strips have equal x widths w = (hi(0) - lo(0)) / (folds + 1); the sheet's
/// height is z0 - amplitude at x = lo(0) and alternates z0 + amplitude, z0 - amplitude, ... at
/// the fold lines x_i = lo(0) + i w (i = 1..folds) and at x = hi(0). Each strip is split along y
/// into `divisions` quads of two triangles: (folds + 2)(divisions + 1) points, 2 (folds + 1)
/// divisions triangles, normal pointing to +z. Points on a fold line share its x and z bit for
/// bit, so every strip is exactly planar. Area (hi(1) - lo(1)) (folds + 1) sqrt(w^2 + 4 A^2).
/// Metres. Throws xfem::Error for folds < 0, divisions < 1 or an empty rectangle.
TriangleMesh cut_zigzag(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double z0, double amplitude, int folds,
                        int divisions);

/// Several cut surfaces as one (e.g. two disjoint pieces): the points and triangles of each in
/// turn, triangle indices shifted; each piece keeps its own orientation.
TriangleMesh merge_surfaces(const std::vector<TriangleMesh>& pieces);

/// Total area of a triangle mesh, m^2.
double surface_area(const TriangleMesh& mesh);

}  // namespace xfem
