// SPDX-License-Identifier: MIT
// What classify() shares with GrowingCutClassifier (growing_classification.h): the answers kept
// from one cut to the next and the classification that reuses them. Not for other callers.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "xfem/enrich/classification.h"

namespace xfem {

/// What classify keeps for the next cut of a growing sequence: the mesh's unique edges and each
/// tet's edges (the mesh alone), and the previous cut's exact geometric answers.
struct ClassificationMemory {
  std::vector<std::uint64_t> unique;  // the mesh's edges, sorted keys
  std::vector<int> tet_edges;         // 6 per tet: index into `unique`
  std::vector<char> on_cut;           // per point: meets the previous cut (before D1's snapping)
  std::vector<char> meets;            // per edge: meets the previous cut (-1: not tested, D2)
  std::vector<double> above, below;   // per tet: volumes on each side of the previous cut
  std::vector<char> split;            // per tet: 1 where above/below hold the previous cut's volumes
  bool classified = false;            // the above hold a cut's answers
  std::vector<int> ids;               // the previous cut's triangle ids, increasing
  std::vector<std::array<double, 9>> corners;  // their corners, in the order of `ids`
  // GrowingCutClassifier only (keep_distances): per point its distance to the previous cut and its
  // side (before D1's snapping), so that a point no new triangle comes as close to keeps its side.
  bool keep_distances = false;
  std::vector<double> distance;
  std::vector<int> side;
  std::vector<double> support;        // per point: its support's volume (the mesh alone), once
};

/// What one classification tested anew (GrowingCutClassifier::Stats).
struct ClassifyWork {
  bool incremental = false;
  long points = 0, edges = 0, tets = 0;
  long sides = 0;
};

struct CutGrowth;  // growing_classification.h

/// classify(), with the mesh's edges from `memory` and, when `growth` is given (the cut is the
/// previous one of `memory` plus the triangles of `growth`), the previous cut's answers away from
/// the new triangles. Leaves this cut's answers in `memory` and what it tested in `work`.
Classification classify_with(const TetMesh& mesh, const CutSurface& cut, const ClassifyOptions& options,
                             ClassificationMemory& memory, const CutGrowth* growth, ClassifyWork& work);

}  // namespace xfem
