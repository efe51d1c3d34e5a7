// SPDX-License-Identifier: MIT
#pragma once
#include "xfem/mesh.h"

namespace xfem {

/// Structured tetrahedral mesh of the box [lo, hi]: cells(0) x cells(1) x cells(2) cubes, each
/// split into 6 positively oriented tets around its main diagonal (the same split in every cube,
/// so faces match: the mesh is conforming). Point (i, j, k) has id i + (nx+1) (j + (ny+1) k).
/// Throws xfem::Error for a non-positive cell count or an empty box.
TetMesh box_mesh(const Eigen::Vector3i& cells, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);

}  // namespace xfem
