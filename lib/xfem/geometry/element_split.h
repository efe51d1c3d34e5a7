// SPDX-License-Identifier: MIT
#pragma once
#include <vector>

#include "xfem/geometry/crack_front.h"
#include "xfem/geometry/cut_surface.h"
#include "xfem/core/mesh.h"

namespace xfem {

/// The body's mesh with every cut element split along the cut (paper 4.1, the triangulation for
/// visualization): a conforming tetrahedral mesh in which the points on the cut are duplicated,
/// one copy per side, so that each copy can move with its own side's displacement.
///
/// The rule (docs/FORMATS.md, "deformed.vtu"): an edge of the mesh is split when its two nodes
/// have opposite sides (array `side` of xfem-classify) and it meets the cut; its point is the
/// meeting point (CGAL, the one nearest the edge's lower-numbered node). A face with two split
/// edges is crossed by the cut along the segment joining their points; a face with one split edge
/// is entered by the cut front, and its point where a front segment pierces it (CGAL) ends the
/// cut on that face. Every face is triangulated from its own edges' and front points only (quads
/// split along the diagonal from their lowest-numbered node), so neighbouring elements agree and
/// the result is conforming. An element the cut crosses completely and in one plane is then
/// coned from one inner point M, the mean of the edge points, duplicated like them: the cut inside
/// it is the fan from M over the cut's segments on its faces. Elements the front runs through,
/// and elements a folded cut crosses, are split instead into their exact pieces (cut_pieces.h),
/// the wound being the cut's triangles clipped to them; their points are their own (faces match
/// the neighbours' in space, not point by point), and only points on the cut behind the front
/// have a copy per side, so such an element opens exactly behind its front.
struct SplitMesh {
  Points points;                 ///< #P x 3 undeformed positions (m); rows 0..NP-1 are the input's nodes
  std::vector<int> point_side;   ///< #P: side to evaluate the displacement with (+1 / -1, 0 = decide by the cut)
  std::vector<int> point_tet;    ///< #P: an input tet containing the point, to evaluate the field in
  Tets tets;                     ///< #T' x 4, positively oriented
  std::vector<int> parent;       ///< #T': the input tet each output tet lies in
  std::vector<int> tet_side;     ///< #T': +1 / -1 for a piece above / below the cut (ahead of the
                                 ///< front: the half of the cut's plane it lies in); 0 for an
                                 ///< element kept whole
  Triangles wound;               ///< the cut's faces inside the body: every cut triangle twice, once
                                 ///< per side, oriented with the normal pointing out of its side's piece
  std::vector<int> wound_side;   ///< per wound triangle: +1 / -1
  int split_complete = 0;        ///< elements the cut crosses completely
  int split_partial = 0;         ///< elements split only behind the front
  int degenerate_faces = 0;      ///< faces with one split edge but no front point (cut grazing a
                                 ///< node or the front missing the face): split at that edge only
};

/// Splits the cut elements of `mesh` along `cut` (paper 4.1).
/// @param side       per point, H(P_m) = +1 / -1 as decided by xfem-classify
/// @param cut_class  per tet, 0 uncut (kept whole), 1 partially or 2 completely cut
/// @param cut        the cut's triangles (m)
/// @param front      the cut front's segments (from the enriched mesh); may be empty for a cut
///                   that crosses the body completely
/// Throws xfem::Error when `side` or `cut_class` do not match the mesh's size or hold values other
/// than +-1 / 0..2.
SplitMesh split_mesh(const TetMesh& mesh, const std::vector<int>& side, const std::vector<int>& cut_class,
                     const TriangleMesh& cut, const std::vector<FrontSegment>& front);

/// The same, given the cut as the CutSurface the caller already holds (EnrichedMesh::cut), so that
/// its search structures are not built a second time. The same result, bit for bit.
SplitMesh split_mesh(const TetMesh& mesh, const std::vector<int>& side, const std::vector<int>& cut_class,
                     const CutSurface& cut, const std::vector<FrontSegment>& front);

/// The "split" of a mesh without a cut (a plain CG-FEM mesh, doubled nodes included): the mesh
/// itself, every tet whole (tet_side 0), every point evaluated on `side` (+1 / -1 per point) in
/// the first tet that uses it, no wound. Throws xfem::Error when `side` does not match the mesh.
SplitMesh unsplit_mesh(const TetMesh& mesh, const std::vector<int>& side);

}  // namespace xfem
