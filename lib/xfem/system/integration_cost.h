// SPDX-License-Identifier: MIT
#pragma once
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/system/problem.h"

namespace xfem {

/// About how many integration points assembling `em` with `problem`'s rule takes in the tets with
/// enriched DOFs (xfem-assemble's cost guard): conforming, a cut tet splits into about 24
/// sub-tets of order^3 points; oversampling, m^3 points (m^3 > `points`), and refinement splits
/// the ~m^2 sub-tets the cut crosses into 8, `refine` times. `*enriched_tets`: how many tets have
/// enriched DOFs.
double integration_points_estimate(const EnrichedMesh& em, const Problem& problem, int points, int refine,
                                   long* enriched_tets);

}  // namespace xfem
