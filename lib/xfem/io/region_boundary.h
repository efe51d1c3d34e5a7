// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <array>
#include <vector>

#include "xfem/core/mesh.h"

namespace xfem {

/// The surfaces that outline the regions of a tet mesh in a picture (docs/FORMATS.md, "PNG
/// snapshot"): every region but the largest (by volume; the body drawn in stress colours) is
/// outlined by its own boundary, the faces of its tets whose opposite tet is missing (the body's
/// outer surface, or a cut face: the split mesh doubles its nodes there) or of another region. So
/// an interface between the largest region and another appears once, between two smaller regions
/// twice (once for each). Faces are matched by their point ids (a conforming mesh).
struct RegionBoundary {
  int majority = 0;             ///< the largest region by volume (the lowest id on a tie)
  Triangles triangles;          ///< point ids, oriented out of the region they bound
  std::vector<int> region;      ///< the region each triangle bounds (never `majority`)
};

/// The boundary of each region but the largest. Empty when the mesh has one region (or none).
RegionBoundary region_boundary(const TetMesh& mesh);

/// The outline of `triangles` seen along `eye` (unit vector towards the eye, parallel projection)
/// at positions `points`: the edges where a face turned towards the eye meets one turned away
/// (the silhouette), and the edges only one triangle uses (an open border). Point id pairs,
/// smaller id first, sorted.
std::vector<std::array<int, 2>> outline_edges(const Points& points, const Triangles& triangles,
                                              const Eigen::Vector3d& eye);

}  // namespace xfem
