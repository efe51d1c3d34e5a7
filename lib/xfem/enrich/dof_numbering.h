// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

#include "xfem/core/mesh.h"

namespace xfem {

/// The paper's numbering of the displacements U_k (paper 3.3, DESIGN.md "Numerics") and each
/// element's extended connectivity C with local node ids L.
struct DofNumbering {
  long np = 0, ns = 0, nb = 0, n = 0;  ///< N = NP + NS + 4 NB
  std::vector<long> sign_dof;    ///< per point: its sign DOF (NP..NP+NS-1), -1 if none
  std::vector<long> branch_dof;  ///< per point: the first of its 4 branch DOFs, -1 if none
  std::vector<long> offsets;     ///< T+1: element t owns dofs/local[offsets[t] .. offsets[t+1])
  std::vector<long> dofs;        ///< C, element after element
  std::vector<int> local;        ///< L: the local node (0..3) each entry of C belongs to
};

/// Numbers the DOFs: originals 0..NP-1 (the point ids), then the sign-enriched points in
/// increasing point order (NP..NP+NS-1), then the branch-enriched points in increasing point order,
/// 4 consecutive ids each (NP+NS..N-1).
/// C of element t: its 4 nodes in the element's own order (L = 0,1,2,3), then its enriched
/// entries sorted by DOF id (sign DOFs of its nodes in increasing point order, then the branch
/// DOFs of its nodes in increasing point order), each with the local id of its node. A sign DOF
/// enters only cut elements (partial or complete) containing its node, the 4 branch DOFs enter
/// every element containing their node (blending elements included).
/// This is the ordering of elements 1 to 4 of the paper's figure 2; its element 0 lists the
/// enriched DOFs in local-node order instead (8, 7, 9), which contradicts the other four, and is
/// not followed.
/// @param tets        #T x 4 point ids
/// @param points      NP, the number of points
/// @param enrichment  per point: 0 none, 1 sign, 2 branch (array `enrichment`)
/// @param cut_class   per tet: 0 uncut, 1 partial, 2 complete (array `cut_class`)
/// Throws xfem::Error naming the point or tet with a value out of range.
DofNumbering dof_numbering(const Tets& tets, long points, const std::vector<int>& enrichment,
                           const std::vector<int>& cut_class);

/// Writes the arrays of docs/FORMATS.md "enriched.vtu": field `dof_counts` (Int64: NP, NS, NB, N),
/// `extended_offsets`, `extended_dofs` (Int64), `extended_local` (Int32); point `sign_dof`,
/// `branch_dof` (Int64).
void store_dof_numbering(const DofNumbering& d, TetMesh& mesh);

/// xfem-enrich: numbers the DOFs of a classified mesh (the arrays of xfem-classify in `mesh`, read
/// from `file`) and stores the numbering on it, for one cut (dof_numbering, store_dof_numbering) or
/// several (number_several_cuts). Throws xfem::Error naming `file` and the array missing or wrong,
/// or branch nodes without a front.
DofNumbering number_classified_mesh(TetMesh& mesh, const std::string& file);

/// The DOF numbering of a classified mesh with several cuts (cut_count > 1), read from its arrays:
/// originals 0..NP-1; then the one-vector enrichments: the sign DOFs of cut 0, of cut 1, ..., then
/// the product DOFs of each pair (a, b) in increasing (a, b); then the branch DOFs (4 each) of cut 0,
/// cut 1, ...; each block in increasing point order. NS counts all one-vector DOFs, NB all branch
/// nodes: N = NP + NS + 4 NB as for one cut. C of a tet: its 4 nodes, then its nodes' one-vector
/// DOFs if any cut cuts the tet, and their branch DOFs always, sorted by DOF id.
/// Stores `dof_counts`, `extended_*`, `sign_dof`, `branch_dof` (cut 0), `sign_dof_k`,
/// `branch_dof_k`, `product_dof_a_b` (point, Int64, -1 if none), `cut_dof_blocks` (field, Int64,
/// 4 per cut: first sign DOF, sign count, first branch DOF, branch node count) and
/// `product_dof_blocks` (field, Int64, 4 per pair: a, b, first DOF, count) on `mesh`.
/// Throws xfem::Error naming the array that is missing or wrong.
DofNumbering number_several_cuts(TetMesh& mesh, const std::string& file);

}  // namespace xfem
