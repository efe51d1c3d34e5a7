// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <array>
#include <vector>

#include "xfem/geometry/cut_surface.h"
#include "xfem/integrate/cut_element_splits.h"

namespace xfem {

/// The volume of each side of one tet (each region, with several cuts): what the closed-form
/// blocks of a cut tet's stiffness need (closed_form_stiffness.h). Linear tets have constant
/// shape-function gradients and the sign enrichment is constant on a side, so every block without
/// branch functions is the plain element matrix's pattern scaled by these volumes.
struct SideVolumes {
  std::vector<int> side;       ///< side code of each region (+1 / -1 for one cut; side_codes.h for several)
  std::vector<double> volume;  ///< m^3, per region, > 0; sum = the tet's volume
  std::vector<Eigen::Vector3d> point;  ///< per region: a point inside it (the centroid of its first piece)
  int size() const { return static_cast<int>(side.size()); }
};

/// From the exact pieces of tet t (`splits` = split_cut_elements(em)): the pieces' volumes summed
/// per side code, regions in order of first appearance. A tet without pieces (splits.index[t] < 0:
/// no cut meets it) is one region, side 0 ("decide by the cut"), its whole volume.
SideVolumes side_volumes(const TetMesh& mesh, const CutElementSplits& splits, int t);

/// The volumes above (+1, [0]) and below (-1, [1]) the cut of the tet p, computed independently
/// of the pieces (for tests): by the divergence theorem, V = 1/3 of the integral of (x - o) . n over
/// the side's boundary (o the tet's centroid), which on a plane is (x0 - o) . n times the area. The
/// boundary of a side is the parts of the tet's faces on it (each face split by the plane of every
/// cut triangle meeting the tet, each part given the side of a point just inside the tet) and the
/// cut inside the tet (each cut triangle clipped by the tet's faces), outer normal -n_cut above and +n_cut below. Exact for a
/// piecewise planar cut that separates the tet (a completely cut element); meaningless for a tet
/// the front passes through (there the sides are told apart by the cut's extension, not the cut).
std::array<double, 2> side_volumes_by_divergence(const std::array<Eigen::Vector3d, 4>& p, const CutSurface& cut);

}  // namespace xfem
