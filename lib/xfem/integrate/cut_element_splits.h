// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <array>
#include <vector>

#include "xfem/enrich/enriched_mesh.h"

namespace xfem {

/// The cut elements of a mesh split along the cut into pieces of one side each, once for all
/// elements, by cut_pieces.h: completely cut elements (cut_class 2) by split_by_cut, partially cut
/// ones (cut_class 1) by split_at_front (also at the planes through the front segments, so that
/// the front is made of the pieces' edges). Exact for a piecewise planar cut, however thin a piece.
struct CutElementSplits {
  std::vector<std::array<Eigen::Vector3d, 4>> tets;  ///< corners (m) of every piece
  std::vector<int> side;   ///< per piece: +1 / -1 (ahead of the front: its half of the cut's plane)
  std::vector<int> index;  ///< per mesh tet: its row in `first`, -1 for uncut tets
  std::vector<int> first;  ///< CSR: pieces first[i] .. first[i+1]-1
};
/// With several cuts (em.cuts): every tet some cut meets split by all of them (by the front of the
/// one cut whose front runs through it), each piece with its side code (side_codes.h) instead of
/// +1 / -1 (split_by_cuts.h). Two loops, not one: the one cut's pieces carry +1 / -1 (the side
/// convention of its basis, stress intensity and visualization), and a mesh without cut elements
/// needs no cut surface. Throws xfem::Error when em has cut elements but no cut surface.
CutElementSplits split_cut_elements(const EnrichedMesh& em);

}  // namespace xfem
