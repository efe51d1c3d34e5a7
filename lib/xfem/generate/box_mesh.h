// SPDX-License-Identifier: MIT
#pragma once
#include "xfem/core/mesh.h"

namespace xfem {

/// Structured tetrahedral mesh of the box [lo, hi]: cells(0) x cells(1) x cells(2) cubes, each
/// split into 6 positively oriented tets around its main diagonal (the same split in every cube,
/// so faces match: the mesh is conforming). Point (i, j, k) has id i + (nx+1) (j + (ny+1) k).
/// Tets are numbered cube by cube (i fastest, then j, then k), 6 per cube.
/// Throws xfem::Error for a non-positive cell count or an empty box.
TetMesh box_mesh(const Eigen::Vector3i& cells, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);

/// A planar cut of a structured box modelled by duplicated nodes (DESIGN.md, "The benchmark"):
/// the cut is the part x < x_front of the grid plane z = z.
struct BoxCut {
  double z = 0.0;        ///< height of the cut plane, metres; must be an interior grid plane
  double x_front = 0.0;  ///< x of the straight crack front (a line parallel to y), metres; an
                         ///< interior grid plane
};

/// box_mesh with the cut `cut` opened by duplicating nodes, for CG-FEM reference solutions
/// (DESIGN.md, "The benchmark"). The grid nodes of the plane z = cut.z with x strictly less than
/// cut.x_front are duplicated; the copies (ids after the grid's, ordered i fastest then j) are
/// used by the tets of the cube layer just above the plane, the originals by the rest; the
/// crack-front nodes at x = x_front stay shared. Point array `cut_side` (Int32): +1 for copies,
/// -1 for the originals that were duplicated, 0 elsewhere (read by rms_error's plain_field).
/// The box 18 x 36 x 120 over [0,0.03]x[0,0.06]x[0,0.2] cut at z = 0.1, x_front = 0.015 gives
/// 466,560 tets and 85,063 + 333 = 85,396 points.
/// Throws xfem::Error (as box_mesh) and when z or x_front is not an interior grid plane (relative
/// tolerance 1e-9 of a cell), naming the value and the nearest grid planes.
TetMesh box_mesh(const Eigen::Vector3i& cells, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                 const BoxCut& cut);

}  // namespace xfem
