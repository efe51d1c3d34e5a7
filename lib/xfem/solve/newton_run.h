// SPDX-License-Identifier: MIT
#pragma once
#include <string>

#include "xfem/core/json_io.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/solve/newton.h"
#include "xfem/solve/newton_contact.h"
#include "xfem/system/problem.h"

namespace xfem {

/// What xfem-newton is asked for: its outputs and the Newton settings beyond problem.json.
struct NewtonRun {
  std::string problem_path;    ///< problem.json, for the fingerprint u.mtx carries
  std::string output;          ///< u.mtx
  std::string reactions_path;  ///< nodal reactions (.mtx); empty: not written
  std::string report_path;     ///< the JSON report; empty: not written
  std::string ordering = "metis";
  /// Each tet's law (problem.json `materials`: tet_materials); null: problem.json's `material` for all.
  const TetMaterials* materials = nullptr;
  double rtol = 1e-8;
  int max_iterations = 25;
  /// The linear solver (not owned; newton.h): null for CHOLMOD with `ordering`; `backend` and
  /// `processes` name it in the report.
  TangentSolver* solver = nullptr;
  std::string backend = "cholmod";
  int processes = 1;
  /// False on the ranks of a PETSc run other than rank 0: they solve along and write nothing.
  bool root = true;
  /// Contact (problem.json "contact"; newton_contact.h): its settings, and where to write the
  /// contact pressure of each contact node (contact_pressure_file.h; empty: not written).
  NewtonContactSettings contact;
  std::string contact_pressure_path;
};

/// The large-deformation solve of `problem` on `em` (xfem-newton): the body integrated once with
/// the cut-conforming rule of order problem.order, Newton in problem.load_steps load steps
/// (newton.h), then the outputs xfem-solve writes: the reactions r(u) - f on the constrained
/// DOFs (each condition's resultant logged and reported), u.mtx with the fingerprints of the
/// mesh, the cuts and the problem, and the report (the steps with their residual histories,
/// factorizations, timings, the backend, the deformed volume on the points:
/// deformed_volume_at_points). problem.json `cut_loads`: the pressures follow the deformed faces
/// (follower_cut_load.h), the tractions are dead loads on the reference faces; `contact`: the
/// faces' frictionless contact in the reference configuration (newton_contact.h), its outcome in
/// report["contact"] and each step's. Progress on stderr per load step (cli::info) and per iteration
/// (cli::detail). Throws xfem::Error, writing nothing, for the oversampling rule, a piece
/// without a Dirichlet condition, or a Newton failure after the smallest step.
void run_newton(const EnrichedMesh& em, const Problem& problem, const NewtonRun& run, Json& report);

}  // namespace xfem
