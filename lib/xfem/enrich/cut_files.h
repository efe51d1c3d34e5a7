// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

#include "xfem/core/mesh.h"

namespace xfem {

/// The cut surfaces of `paths`, in order; a file whose triangles carry the cell array `cut_id`
/// (one component, whole numbers) gives one cut per distinct value, in increasing order (the
/// triangles with that value and the points they use). `names` gets a name per cut ("a.vtp", or
/// "a.vtp#3" for cut_id 3). Errors name the file.
std::vector<TriangleMesh> read_cuts(const std::vector<std::string>& paths, std::vector<std::string>& names,
                                    std::vector<std::string>* warnings = nullptr);

/// Stores the fingerprint of every cut on a classified mesh (`cut_fingerprint`, `cut_fingerprint_k`).
void store_cut_fingerprints(const std::vector<TriangleMesh>& cuts, TetMesh& mesh);

}  // namespace xfem
