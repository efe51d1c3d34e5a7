// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

#include "xfem/core/json_io.h"

#include "xfem/enrich/classification.h"
#include "xfem/geometry/cut_surface.h"

namespace xfem {

/// Several cuts in one body (docs/METHOD.md "Several cuts", docs/FORMATS.md "Several cuts").
/// Cut k has its own side function H_k, classification, front and crack-tip frames. A node gets
/// one enrichment per cut whose support it straddles, plus the junction (product) enrichment
/// H_a H_b where two cuts cross inside its support (the four sign combinations of H_a and H_b
/// all have volume there: Daux et al. 2000), so that every piece the cuts make can move on its own.
/// A cut ending on another (a T-junction) has its Heaviside restricted to its side of that cut
/// (0 on the other side) and its boundary there is no front. One cut keeps every single-cut file
/// and number: classify_cuts, store_cuts_classification and number_several_cuts are used only
/// with two or more; the later stages take both through one entry point each (read_enriched_mesh_cuts,
/// enriched_basis, split_cut_elements, find_pieces, split_mesh(EnrichedMesh)), which chooses.

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

/// The suffix of cut k's arrays (docs/FORMATS.md "Several cuts"): "" for cut 0, "_k" for k >= 1.
std::string cut_suffix(int k);
/// The suffix of the arrays of the product of cuts a and b: "_a_b".
std::string pair_suffix(int a, int b);

/// What xfem-classify reports of several cuts: a line per cut and per crossing pair on stderr
/// (cli::info; the junction nodes left out, cli::detail) and the summary's `cuts`, `products` and
/// `product_tiny` added to `j` (docs/FORMATS.md "Several cuts"). `cut_names` as read_cuts gives them.
void report_cuts_classification(const CutsClassification& c, const std::vector<std::string>& cut_names, Json& j);

}  // namespace xfem
