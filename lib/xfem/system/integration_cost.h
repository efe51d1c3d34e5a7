// SPDX-License-Identifier: MIT
#pragma once
#include <string>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/system/problem.h"

namespace xfem {

/// About how many integration points assembling `em` with `problem`'s rule takes in the tets with
/// enriched DOFs (xfem-assemble's cost guard): conforming, a cut tet splits into about 24
/// sub-tets of at most (order + 1)^3 points; oversampling, m^3 points (m^3 > `points`), and refinement splits
/// the ~m^2 sub-tets the cut crosses into 8, `refine` times. `*enriched_tets`: how many tets have
/// enriched DOFs.
double integration_points_estimate(const EnrichedMesh& em, const Problem& problem, int points, int refine,
                                   long* enriched_tets);

/// xfem-assemble's cost guard: the estimate above, and xfem::Error naming `input`, the estimate and
/// how to lower it when it exceeds 2e8 and `allow_large` is false. Returns the estimate.
double check_integration_cost(const EnrichedMesh& em, const Problem& problem, int points, int refine, bool allow_large,
                              const std::string& input);

}  // namespace xfem
