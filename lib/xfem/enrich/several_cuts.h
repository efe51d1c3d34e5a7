// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

#include "xfem/enrich/classification.h"
#include "xfem/integrate/conforming_quadrature.h"
#include "xfem/geometry/cut_surface.h"
#include "xfem/enrich/dof_numbering.h"
#include "xfem/geometry/element_split.h"
#include "xfem/enrich/enriched_basis.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/system/linear_system.h"

namespace xfem {

/// Several cuts in one body (docs/METHOD.md "Several cuts", docs/FORMATS.md "Several cuts").
/// Cut k has its own side function H_k, classification, front and crack-tip frames. A node gets
/// one enrichment per cut whose support it straddles, plus the junction (product) enrichment
/// H_a H_b where two cuts cross inside its support (the four sign combinations of H_a and H_b
/// all have volume there: Daux et al. 2000), so that every piece the cuts make can move on its own.
/// A cut ending on another (a T-junction) has its Heaviside restricted to its side of that cut
/// (0 on the other side) and its boundary there is no front. One cut keeps every single-cut file
/// and number; the functions here are used only with two or more.
constexpr int kMaxCuts = 16;

/// The cut surfaces of `paths`, in order; a file whose triangles carry the cell array `cut_id`
/// (one component, whole numbers) gives one cut per distinct value, in increasing order (the
/// triangles with that value and the points they use). `names` gets a name per cut ("a.vtp", or
/// "a.vtp#3" for cut_id 3). Errors name the file.
std::vector<TriangleMesh> read_cuts(const std::vector<std::string>& paths, std::vector<std::string>& names,
                                    std::vector<std::string>* warnings = nullptr);

/// The decisions of xfem-classify for several cuts.
struct CutsClassification {
  std::vector<Classification> cuts;  ///< per cut: its own side, enrichment, cut_class, front, counts
  std::vector<int> ends_on;          ///< per cut: the cut it ends on (a T-junction), -1 if none
  std::vector<int> ends_side;        ///< per cut: the side of cut ends_on it lies on (+1 / -1), 0 if none
  struct Product {
    int a = 0, b = 0;                ///< cuts a < b
    std::vector<char> node;          ///< per point: 1 if the node has the product enrichment H_a H_b
    long count = 0;
  };
  std::vector<Product> products;     ///< pairs with at least one product node
  /// Nodes whose support holds all four sign combinations of two cuts, one of them below
  /// tiny_support of it: not given the product (the pieces stay joined inside that sliver only).
  long product_tiny = 0;
};

/// Classifies `mesh` against every cut (classify() per cut), finds T-junctions (front segments of
/// cut k lying on cut i: cut k ends on cut i, those segments are no front, its tets there become
/// completely cut), splits every tet met by a cut into exact pieces by all cuts and decides the
/// enrichments by the pieces' volumes: a node gets the enrichment of cut k (if not branch
/// enriched for k) when at least options.tiny_support of its support has another value of g_k
/// (H_k, restricted for a junction) than the node, and the product H_a H_b when each of the four
/// sign combinations holds that much. Throws xfem::Error naming the configuration, tet and cuts
/// that are not handled: three cuts in one tet; a front of one cut in a tet another cut meets;
/// branch enrichments of two cuts in one tet; a cut ending on two cuts; two cuts ending on each
/// other (a V: merge them into one surface).
CutsClassification classify_cuts(const TetMesh& mesh, const std::vector<const CutSurface*>& cuts,
                                 const ClassifyOptions& options = {});

/// The arrays of docs/FORMATS.md "Several cuts" on `mesh`: cut 0 as store_classification, cut
/// k >= 1 with the suffix `_k` (`side_1`, `enrichment_1`, `cut_class_1`, `cut_edges_1`,
/// `front_segments_1`, `front_normals_1`, `classification_counts_1`), field `cut_count`,
/// `cut_junctions` (Int32, 2 per cut: ends_on, ends_side) and point arrays
/// `product_enrichment_a_b` (Int32 0/1) per product pair.
void store_cuts_classification(const CutsClassification& c, TetMesh& mesh);

/// Number of cuts a classified mesh was made with: its field `cut_count`, 1 when absent.
int cut_count(const TetMesh& mesh);

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

/// Reads enriched.vtu and its cuts (one file each, or cut_id files: read_cuts): for a mesh with one
/// cut exactly read_enriched_mesh; with several, also em.cuts and em.products (em.cut, em.front are
/// cut 0's). Checks that the cuts are those the mesh was classified with (fingerprints).
EnrichedMesh read_enriched_mesh_cuts(const std::string& vtu, const std::vector<std::string>& cut_paths,
                                     std::vector<std::string>* warnings = nullptr);

/// Stores the fingerprint of every cut on a classified mesh (`cut_fingerprint`, `cut_fingerprint_k`).
void store_cut_fingerprints(const std::vector<TriangleMesh>& cuts, TetMesh& mesh);

/// Side codes of a mesh with several cuts (the `side` argument of enriched_basis, the sides of
/// integration points and of visualization points): 0 = decide by the cut surfaces; c >= 2:
/// bit k of c - 2 set <=> H_k = +1.
int pack_sides(const int* sides, int cuts);
inline int code_side(int code, int k) { return ((code - 2) >> k) & 1 ? 1 : -1; }

/// g_k, the enrichment function of cut k, given the sides H_0..H_{K-1} of a point: H_k, or for a
/// cut ending on cut i, H_k on its side of cut i and 0 on the other.
int cut_function(const EnrichedMesh& em, int k, const int* sides);

/// enriched_basis for a mesh with several cuts (called by enriched_basis).
void several_cuts_basis(const EnrichedMesh& em, int t, const TetShape& shape, const Eigen::Vector3d& x, int code,
                        BasisAt& out);

/// The cut whose branch DOFs tet t holds (at most one, classify_cuts makes sure), or -1. For one
/// cut: 0 when the tet holds branch DOFs.
int branch_cut_of_tet(const EnrichedMesh& em, int t);
/// Its front and cut (em.front, em.cut for one cut or a tet without branch DOFs).
const CrackFront& front_of_tet(const EnrichedMesh& em, int t);
const CutSurface* cut_of_tet(const EnrichedMesh& em, int t);

/// split_cut_elements for several cuts: every tet some cut meets split by all of them (by the
/// front of the one cut whose front runs through it), each piece with its side code.
CutElementSplits split_cut_elements_several(const EnrichedMesh& em);

/// find_pieces for several cuts: a cut tet is one part per region (the values of every g_k);
/// neighbours connect parts of the same region that both have a face on the shared face.
std::vector<Piece> find_pieces_several(const EnrichedMesh& em, const std::vector<char>& node_constrained);

/// The split mesh of xfem-visualize for several cuts: uncut tets whole on the input's nodes, every
/// piece of a cut tet (split_cut_elements_several) a tet on its own 4 points, evaluated with its
/// side code; the wound: the pieces' faces lying on a cut where the material opens.
SplitMesh split_mesh_several(const EnrichedMesh& em);

}  // namespace xfem
