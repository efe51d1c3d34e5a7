// SPDX-License-Identifier: MIT
#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "xfem/geometry/crack_front.h"
#include "xfem/geometry/cut_surface.h"
#include "xfem/core/mesh.h"

namespace xfem {

/// How a tet meets the cut (paper 3.3). Values are those of the cell array `cut_class`.
enum class CutClass : int { Uncut = 0, Partial = 1, Complete = 2 };

/// A node's enrichment (paper 3.3). Values are those of the point array `enrichment`.
enum class Enrichment : int { None = 0, Sign = 1, Branch = 2 };

struct ClassifyOptions {
  /// "Radius enrichment": also branch-enrich every node within this distance (metres) of the
  /// cut front. 0 = the paper's rule (only the nodes of partially cut elements).
  double tip_radius = 0.0;
  /// A node is sign enriched only if the part of its support on the other side of the cut is at
  /// least this fraction of the support's volume (below it the sign function is nearly zero and
  /// K near-singular: the enrichment is removed and counted as sign_tiny).
  double tiny_support = 1e-7;
  /// Called with the fraction done in [0, 1] (may be empty).
  std::function<void(double)> progress;
};

/// Everything xfem-classify decides; later stages read it, never recompute it.
struct Classification {
  std::vector<int> side;              ///< per point: H(P_m) = +1 / -1 (CutSurface::side)
  std::vector<char> on_cut;           ///< per point: 1 if the point lies on the closed cut (exactly, or within 1e-10 of the mesh's bounding-box diagonal: rule D1)
  std::vector<Enrichment> enrichment; ///< per point
  std::vector<CutClass> cut_class;    ///< per tet
  std::vector<int> cut_edges;         ///< per tet: how many of its 6 edges are cut (0..6)
  std::vector<int> cut_faces;         ///< per tet: how many of its 4 faces are completely cut
  CrackFront front;                   ///< the cut front inside the body, oriented (crack_front.h)

  /// Summary counts (array `classification_counts`, JSON of --summary).
  struct Counts {
    long points = 0, tets = 0, edges = 0, cut_edges = 0, points_on_cut = 0;
    long uncut = 0, partial = 0, complete = 0;
    long none = 0, sign = 0, branch = 0;
    long sign_tiny = 0;      ///< nodes whose support lies on the other side by less than tiny_support: not enriched
    long radius_branch = 0;  ///< nodes branch-enriched only because of tip_radius
    long front_segments = 0;
  } counts;
};

/// Classifies `mesh` against `cut` (paper 3.3, DESIGN.md "Numerics"):
///  - an edge is cut if it meets the closed cut (exact predicates), each unique edge tested once;
///  - a face is completely cut if two (or three) of its edges are cut;
///  - a tet is uncut (no cut edge), completely cut (>= 3 completely cut faces), else partially cut;
///  - nodes of partially cut tets are branch enriched; nodes of completely cut tets that are not
///    branch enriched are sign enriched;
///  - the front: the cut's boundary edges clipped to the cut tets, oriented so that a = b x c
///    points away from the cut.
/// Degenerate geometry follows the rules D1..D6 of docs/CLASSIFICATION.md:
///  D1 a point on the cut has side +1 (it is treated as lying infinitesimally above the cut);
///  D2 an edge with an end point on the cut is cut iff its end points have different sides
///     (so an edge along the cut or in the cut's plane is not cut);
///  D3 a node of completely cut tets is sign enriched only if one of them has a node strictly on
///     the other side (off the cut): else its enrichment would vanish identically;
///  D4 a front piece lying on the body's surface is no front (a cut through the whole body).
/// Throws xfem::Error if there are partially cut tets but no front inside the body to define the
/// crack-tip frames of their branch nodes.
Classification classify(const TetMesh& mesh, const CutSurface& cut, const ClassifyOptions& options = {});

/// The classification of a mesh without a cut (e.g. a cut-aligned mesh whose cut is modelled by
/// doubled nodes): every tet uncut, every side +1, no enrichment, no front; N = NP downstream.
Classification classify_without_cut(const TetMesh& mesh);

/// Writes the arrays of docs/FORMATS.md "classified.vtu" onto `mesh`: point `side`, `enrichment`,
/// cell `cut_class`, `cut_edges`, field `front_segments`, `front_normals`,
/// `classification_counts` (Int64, in the order of count_names()).
void store_classification(const Classification& c, TetMesh& mesh);

/// Names of the counts, in the order of the field array `classification_counts`.
std::vector<std::string> count_names();
std::vector<long> count_values(const Classification::Counts& c);

}  // namespace xfem
