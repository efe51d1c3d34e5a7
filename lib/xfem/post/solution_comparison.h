// SPDX-License-Identifier: MIT
#pragma once
#include <string>

#include "xfem/core/json_io.h"

namespace xfem {

/// A solution to compare (xfem-rmserror): an X-FEM solution (an xfem-enrich mesh with its `cut`
/// and `solution` u.mtx) or a plain one (any tet mesh, `solution` its nodal displacements, or
/// empty for the mesh's point array 'displacement').
struct ComparedSolution {
  std::string mesh, cut, solution;
  /// A solution vector given for a mesh without its cut compares its first 3 NP values (the standard
  /// DOFs), an X-FEM solution's enrichment left out on purpose; otherwise an X-FEM solution (more
  /// than 3 NP values) for a mesh without its cut is an error.
  bool standard_dofs_only = false;
};

/// RMS and max error of `s` against the exact field of the JSON file `exact_path` at the
/// solution's own nodes, each on its side of the cut, plus the relative L2 and H1-seminorm errors
/// over the volume (`samples` points per tet). Logs the errors; returns xfem-rmserror's report
/// (its "rms" the RMS error). Throws xfem::Error when the inputs do not belong together (the
/// solution's recorded fingerprints) or an error is not finite.
Json compare_with_exact(const ComparedSolution& s, const std::string& exact_path, int samples);

/// RMS and max error of `s` against a reference solution over the reference's nodes (the mesh
/// `reference`, point array 'cut_side' for the side of duplicated nodes; its displacements from
/// `reference_solution`, or its point array 'displacement' when that is empty). Reference nodes
/// outside the mesh but within `radius` (< 0: 1e-6 of the mesh's bounding-box diagonal) are
/// evaluated at the nearest tet; those beyond are left out with a warning. Logs the errors;
/// returns xfem-rmserror's report (its "rms" the RMS error). Throws xfem::Error as
/// compare_with_exact and when no reference node lies in the mesh.
Json compare_with_reference(const ComparedSolution& s, const std::string& reference,
                            const std::string& reference_solution, double radius);

}  // namespace xfem
