// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "xfem/core/fingerprint.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/io/vtk_io.h"
#include "xfem/post/deformed_mesh.h"

namespace xfem {

/// What xfem-visualize's outputs are made from (docs/FORMATS.md "deformed.vtu", field array
/// `inputs_fingerprint`): FNV-1a 64 over the enriched mesh's geometry fingerprint, each cut's,
/// problem.json's, the solution's values (their IEEE bits), the wound offset and, with
/// --contact-pressure, the wound's contact_pressure values (their IEEE bits). Two runs with the
/// same inputs write the same bytes; a deformed.vtu and a wound.vtp of different runs differ here.
Fingerprint visualize_inputs_fingerprint(const EnrichedMesh& em, const Eigen::VectorXd& u,
                                         const std::string& problem_path, double wound_offset,
                                         const std::vector<double>& wound_pressure = {});

/// Writes `body.volume` to `volume_path` and, unless `wound_path` is empty, `body.wound` to it,
/// both carrying `inputs` as the field array "inputs_fingerprint", written together
/// (write_atomically_together: a kill leaves the old pair, the new pair, or, between the two
/// renames only, a pair whose fingerprints differ).
void write_visualize_outputs(DeformedBody& body, const std::string& volume_path, const std::string& wound_path,
                             Compression packing, Fingerprint inputs);

}  // namespace xfem
