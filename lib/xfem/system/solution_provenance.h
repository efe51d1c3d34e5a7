// SPDX-License-Identifier: MIT
#pragma once
#include <string>

#include "xfem/core/fingerprint.h"
#include "xfem/enrich/enriched_mesh.h"

namespace xfem {

/// What a solution of `em` under problem.json `problem_path` is made from: the fingerprints of
/// the enriched mesh, the problem file and every cut ("cut", "cut_1", ...). xfem-assemble records
/// them beside the system, xfem-solve and xfem-newton write them into u.mtx, and the later tools
/// check them against the files they are given (docs/FORMATS.md "Fingerprints").
Provenance solution_provenance(const EnrichedMesh& em, const std::string& problem_path);

}  // namespace xfem
