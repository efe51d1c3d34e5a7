// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

#include "xfem/core/mesh.h"
#include "xfem/enrich/enriched_mesh.h"

namespace xfem {

/// The files a solution (u.mtx) is read with, as the user named them (for the messages).
struct SolutionFiles {
  std::string solution{};         ///< u.mtx
  std::string mesh{};             ///< the mesh it is evaluated on (xfem-enrich output or a plain tet mesh)
  std::vector<std::string> cuts{};  ///< the cuts given with the mesh, in xfem-classify's order; none for a plain mesh
  std::string problem{};          ///< problem.json, or empty when the reader does not use the problem
  /// The reader takes the first 3 NP values only, an X-FEM solution's enrichment left out on
  /// purpose (xfem-rmserror --standard-dofs-only): the cuts it was solved with are not required.
  bool standard_dofs_only = false;
};

/// Checks that a solution belongs to the files it is read with (docs/FORMATS.md "Fingerprints"),
/// for every tool that reads one (xfem-visualize, xfem-front, xfem-probe, xfem-rmserror). From the
/// "% xfem-fingerprint" lines of `files.solution` (malformed or conflicting lines are errors):
/// `enriched` must be `mesh`'s; `cut`, `cut_1`, ... those of `cuts` (cut k from files.cuts[k]);
/// `problem` that of files.problem when given. A cut the solution was solved with but not given,
/// or given (and recorded by the mesh as classified with) but not solved with, is an error too. A solution without fingerprints (another
/// solver's, or older) passes. Throws xfem::Error "<u.mtx>: ..." naming both files.
void check_solution_provenance(const SolutionFiles& files, const TetMesh& mesh,
                               const std::vector<const TriangleMesh*>& cuts);

/// The same for an X-FEM mesh with its cuts (em.cut, em.cuts[1..]); with one cut, also that it is
/// the cut the mesh was classified with (check_cut_matches; several cuts: read_enriched_mesh_cuts).
void check_solution_provenance(const SolutionFiles& files, const EnrichedMesh& em);

}  // namespace xfem
