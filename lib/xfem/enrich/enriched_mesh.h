// SPDX-License-Identifier: MIT
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "xfem/geometry/crack_front.h"
#include "xfem/geometry/cut_surface.h"
#include "xfem/core/mesh.h"

namespace xfem {

/// One cut of a mesh with several cuts (classification_several_cuts.h; docs/FORMATS.md "Several cuts").
struct CutLayer {
  std::vector<int> side;        ///< per point: H_k(P_m) (`side`, `side_k`)
  std::vector<int> cut_class;   ///< per tet (`cut_class`, `cut_class_k`)
  long sign_first = 0, ns = 0;      ///< its sign DOFs: sign_first .. sign_first + ns - 1
  long branch_first = 0, nb = 0;    ///< its branch DOFs: branch_first .. branch_first + 4 nb - 1
  CrackFront front;
  std::shared_ptr<const CutSurface> cut;
  int ends_on = -1;   ///< T-junction: the cut this one ends on (its Heaviside is 0 on the far side), -1 none
  int ends_side = 0;  ///< the side of cut ends_on this cut lies on
};

/// The product (junction) DOFs H_a H_b of two crossing cuts: first .. first + count - 1.
struct ProductBlock {
  int a = 0, b = 0;
  long first = 0, count = 0;
};

/// What the numerical stages (assemble, visualize, rmserror) read of an xfem-enrich output: the
/// mesh with its arrays, the decisions of xfem-classify and the DOF numbering of xfem-enrich
/// (never recomputed), and the cut for H(x) and the crack-tip frames.
struct EnrichedMesh {
  TetMesh mesh;
  std::vector<int> side;       ///< per point: H(P_m), +1 / -1 (array `side`)
  std::vector<int> cut_class;  ///< per tet: 0 uncut, 1 partially cut, 2 completely cut
  long np = 0, ns = 0, nb = 0, n = 0;  ///< N = NP + NS + 4 NB (array `dof_counts`)
  std::vector<long> offsets;   ///< T+1 offsets into dofs/local (array `extended_offsets`)
  std::vector<long> dofs;      ///< the paper's C, element after element (array `extended_dofs`)
  std::vector<int> local;      ///< the paper's L (array `extended_local`)
  CrackFront front;            ///< fields `front_segments`, `front_normals`
  std::shared_ptr<const CutSurface> cut;
  /// Several cuts only (empty for one cut: then side, cut_class, front and cut above are all there
  /// is): every cut, cut 0 included (its side, cut_class, front and cut are also those above).
  std::vector<CutLayer> cuts;
  std::vector<ProductBlock> products;

  int tets() const { return static_cast<int>(mesh.tets.rows()); }
  /// Number of entries of C for tet t (4 for a plain element).
  int size(int t) const { return static_cast<int>(offsets[t + 1] - offsets[t]); }
  /// Whether tet t has only its 4 nodes' original DOFs: a linear element, whatever the cut.
  bool plain(int t) const {
    if (size(t) != 4) return false;
    for (long e = offsets[t]; e < offsets[t + 1]; ++e)
      if (dofs[e] >= np) return false;
    return true;
  }
  /// Does tet t hold branch (crack-tip) DOFs? Only those tets' basis gradients vary inside a side.
  bool branch(int t) const {
    for (long e = offsets[t]; e < offsets[t + 1]; ++e)
      if (dofs[e] >= np + ns) return true;
    return false;
  }
};

/// Reads enriched.vtu (`vtu`) and the cut (`cut_path`) and checks the contract of
/// docs/FORMATS.md: every array present with the right size, C and L consistent (ids < N, local
/// ids 0..3). Throws xfem::Error naming the file and the array, e.g.
/// "enriched.vtu: field array 'dof_counts' missing (is this xfem-enrich output?)".
EnrichedMesh read_enriched_mesh(const std::string& vtu, const std::string& cut_path,
                                std::vector<std::string>* warnings = nullptr);

/// Reads enriched.vtu and its cuts (one file each, or cut_id files: read_cuts): for a mesh with one
/// cut exactly read_enriched_mesh; with several, also em.cuts and em.products (em.cut, em.front are
/// cut 0's). Checks that the cuts are those the mesh was classified with (fingerprints).
EnrichedMesh read_enriched_mesh_cuts(const std::string& vtu, const std::vector<std::string>& cut_paths,
                                     std::vector<std::string>* warnings = nullptr);

/// What a solve reads (xfem-assemble, xfem-newton): read_enriched_mesh_cuts with its warnings on
/// stderr (cli::warn); throws xfem::Error naming `vtu` when the mesh has enriched DOFs and no cut
/// is given.
EnrichedMesh read_enriched_mesh_to_solve(const std::string& vtu, const std::vector<std::string>& cut_paths);


/// The cut whose branch block holds `dof` (a branch DOF of a mesh with several cuts), or -1.
int branch_cut_of_dof(const EnrichedMesh& em, long dof);
/// The cut whose branch DOFs tet t holds (at most one, classify_cuts makes sure), or -1. For one
/// cut: 0 when the tet holds branch DOFs.
int branch_cut_of_tet(const EnrichedMesh& em, int t);
/// Its front and cut (em.front, em.cut for one cut or a tet without branch DOFs).
const CrackFront& front_of_tet(const EnrichedMesh& em, int t);
const CutSurface* cut_of_tet(const EnrichedMesh& em, int t);

}  // namespace xfem
