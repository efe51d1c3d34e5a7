// SPDX-License-Identifier: MIT
#pragma once

#include "xfem/enrich/enriched_mesh.h"

namespace xfem {

/// Several cuts in one body (classification_several_cuts.h): what every stage shares about them.

/// At most this many cuts in one body (docs/METHOD.md "Several cuts"): a side code holds one bit per cut.
constexpr int kMaxCuts = 16;

/// Side codes of a mesh with several cuts (the `side` argument of enriched_basis, the sides of
/// integration points and of visualization points): 0 = decide by the cut surfaces; c >= 2:
/// bit k of c - 2 set <=> H_k = +1.
int pack_sides(const int* sides, int cuts);
inline int code_side(int code, int k) { return ((code - 2) >> k) & 1 ? 1 : -1; }

/// g_k, the enrichment function of cut k, given the sides H_0..H_{K-1} of a point: H_k, or for a
/// cut ending on cut i, H_k on its side of cut i and 0 on the other.
int cut_function(const EnrichedMesh& em, int k, const int* sides);

}  // namespace xfem
