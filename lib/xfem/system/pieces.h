// SPDX-License-Identifier: MIT
#pragma once
#include <array>
#include <vector>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/system/linear_system.h"

namespace xfem {

/// The connected pieces of the cut body and whether a Dirichlet condition holds each one, so
/// that xfem-solve can name a piece that would move rigidly (issue 5; DESIGN.md, "a real solver
/// must at least detect and report" near-singular systems).
///
/// Graph: a completely cut tet (cut_class 2) is two halves, above (+1) and below (-1) the cut; a
/// partially cut tet (1) is one part touching both sides (the crack front holds it together); an
/// uncut tet (0) is one part. Two tets sharing a face connect on the sides both have there: an
/// uncut tet lies on the side of the shared face's nodes (majority of `side`), so a cut tet's
/// half connects only to neighbours on its side; uncut and partially cut parts connect to
/// everything they touch. A piece is constrained if a constrained node's part lies in it: the
/// node's own side of each completely cut tet around it (its original DOF does not hold the
/// other side, where its sign DOF adds an independent motion), any other tet around it.
///
/// Several cuts (m.cuts) are a graph of their own: a cut tet is one part per region (the values
/// of every g_k, side_codes.h), a tet a front runs through one part touching every region, and
/// neighbours connect parts of the same region that both have a face on the shared face. The one
/// cut keeps its halves: the same pieces, found on the mesh's shared faces alone (no splitting).
///
/// @param mesh              mesh, `side` (+1/-1 per point) and `cut_class` (per tet) are read
/// @param node_constrained  per mesh point: nonzero if any of its DOFs has a Dirichlet value
/// @return the pieces, ordered by their lowest tet index (piece 0 holds tet 0); Piece::tets counts
///         tets and tet halves. Throws xfem::Error if the array sizes do not match the mesh.
std::vector<Piece> find_pieces(const EnrichedMesh& mesh, const std::vector<char>& node_constrained);

/// find_pieces with the points held by the Dirichlet DOFs `fixed` (scalar DOFs 3k + i): only the
/// original DOFs hold a piece in place, the enriched ones (fixed by exact conditions) do not.
std::vector<Piece> find_pieces_held_by(const EnrichedMesh& mesh, const std::vector<long>& fixed);

/// The faces two tets of `mesh` share (the mesh alone: for many cuts of one body, e.g. the steps
/// of a sweep): per face its 3 nodes sorted and the two tets. Throws xfem::Error for a node index
/// out of range.
struct SharedFaces {
  std::vector<std::array<int, 5>> faces;
  int tets = 0, points = 0;
};
SharedFaces shared_faces(const TetMesh& mesh);

/// find_pieces with the mesh's shared faces computed before (the same result).
std::vector<Piece> find_pieces(const EnrichedMesh& mesh, const std::vector<char>& node_constrained,
                               const SharedFaces& shared);

}  // namespace xfem
