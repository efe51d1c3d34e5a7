// SPDX-License-Identifier: MIT
#pragma once
#include <array>
#include <vector>

#include "xfem/core/mesh.h"
#include "xfem/enrich/side_codes.h"
#include "xfem/geometry/crack_front.h"
#include "xfem/geometry/cut_pieces.h"
#include "xfem/geometry/cut_surface.h"

namespace xfem {

/// The side H_k (+1 / -1) of every cut at one piece.
using Sides = std::array<int, kMaxCuts>;

/// The corners of tet t of `mesh`.
TetCorners tet_corners(const TetMesh& mesh, int t);

/// The longest edge of tet p (for tolerances relative to its size).
double longest_edge(const TetCorners& p);

/// The pieces of tet p split by every cut that cuts it (classes[k] != 0), each with the side of
/// every cut; a tet only one cut's front runs through is split at that front (split_at_front).
/// (Shared by classify_cuts, which decides the enrichments by the pieces' volumes, and by
/// split_cut_elements, which integrates and draws them.)
void split_by_cuts(const TetCorners& p, const std::vector<const CutSurface*>& cuts, const std::vector<int>& classes,
                   const std::vector<const CrackFront*>& fronts, std::vector<TetCorners>& pieces, std::vector<Sides>& sides);

}  // namespace xfem
