// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/core/json_io.h"
#include "xfem/system/linear_system.h"
#include "xfem/system/problem.h"

namespace xfem {

/// Which Dirichlet condition of problem.json fixes which scalar DOF, so that the reaction forces
/// can be summed per condition. Written by xfem-assemble beside the system
/// (system/dirichlet_conditions.json, docs/FORMATS.md), read by xfem-solve.
struct DirichletGroups {
  std::vector<std::string> names;         ///< per condition: its name, or "dirichlet[i]" without one
  std::vector<std::vector<long>> dofs;    ///< per condition: original scalar DOFs 3k + i (k < NP) it
                                          ///< fixes, increasing; a DOF two conditions fix belongs to
                                          ///< the first one only, so the groups partition the DOFs
};

/// The groups of `problem`'s Dirichlet conditions on `mesh` (the nodes select_nodes selects,
/// the components a condition prescribes: its non-null `value` components, all 3 for `exact`).
/// Enriched DOFs fixed by `exact_enriched` conditions are left out: their reactions are
/// generalised forces, not forces at a point. Throws like select_nodes.
DirichletGroups dirichlet_groups(const TetMesh& mesh, const Problem& problem);

/// Writes `groups` as `dir`/dirichlet_conditions.json (atomically; `dir` created if missing);
/// `generator` as in system.json.
void write_dirichlet_groups(const DirichletGroups& groups, const std::string& dir, const std::string& generator);

/// Reads `dir`/dirichlet_conditions.json. A system without the file (written before it existed)
/// gives one group, "constrained DOFs", holding every constrained original DOF of `system`.
/// Throws xfem::Error naming the file for malformed content or a DOF that `system` does not fix.
DirichletGroups read_dirichlet_groups(const std::string& dir, const LinearSystem& system);

/// The nodal reactions r = K u - f (3N, newtons) on the constrained DOFs `system.fixed`, 0 on the
/// free ones (where K u - f is the solver's residual, not a force). `system.K` must be the full
/// matrix (Dirichlet not eliminated), as read_linear_system returns it; `u` the full solution.
Eigen::VectorXd nodal_reactions(const LinearSystem& system, const Eigen::VectorXd& u);

/// A resultant: total force (N) and its moment about the origin (N m), sum of x_k x F_k.
struct Resultant {
  std::string name;
  long nodes = 0;                                      ///< nodes with at least one DOF in the group
  Eigen::Vector3d force = Eigen::Vector3d::Zero();     ///< N
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();    ///< N m, about (0, 0, 0)
};

/// Per Dirichlet group, the resultant of the nodal reactions `r` (3N) at the mesh points
/// `coordinates` (NP x 3, m). Throws xfem::Error when `coordinates` is not NP x 3.
std::vector<Resultant> condition_reactions(const DirichletGroups& groups, const Eigen::VectorXd& r,
                                           const Eigen::MatrixXd& coordinates);

/// The resultant of the applied loads f (3N; only original DOFs carry loads, DESIGN.md) at
/// `coordinates`, named "applied loads". With the reactions it sums to zero (equilibrium: K
/// annihilates the rigid-body modes, which the original DOFs reproduce exactly).
Resultant applied_load(const Eigen::VectorXd& f, const Eigen::MatrixXd& coordinates);

/// The report entry: {"moment_about": [0,0,0], "conditions": [{"name", "nodes", "force",
/// "moment"}...], "applied": {"force", "moment"}}; forces in N, moments in N m.
/// Without `moments` the moment keys are left out.
Json reactions_json(const std::vector<Resultant>& reactions, const Resultant& applied, bool moments = true);

/// Everything xfem-solve reports, from the system directory `dir` (for its
/// dirichlet_conditions.json), the system as solved and its full solution `u`.
struct Reactions {
  Eigen::VectorXd r;                  ///< nodal reactions, 3N, N (nodal_reactions)
  std::vector<Resultant> conditions;  ///< per Dirichlet condition
  Resultant applied;                  ///< of the loads f
  bool moments = true;                ///< false: the system has no coordinates.mtx, moments left 0
};
/// A system without point coordinates (no coordinates.mtx) gets forces only (`moments` false).
Reactions reactions(const std::string& dir, const LinearSystem& system, const Eigen::VectorXd& u);

/// The point array `reaction` of deformed.vtu (Float64 x 3, N): point k < `np` (an input mesh
/// node: rows 0..NP-1 of the split mesh) gets r[3k..3k+2], the `points` - NP points the split adds
/// get 0, so the array sums to the total reaction. Throws xfem::Error when r has fewer than 3 NP values.
DataArray reaction_array(const Eigen::VectorXd& r, long np, long points);

/// One line: "reaction of 'NAME' (12 nodes): force (fx, fy, fz) N, |F| = .. N; moment about the
/// origin (mx, my, mz) N m".
std::string describe_reaction(const Resultant& r, bool moments = true);

}  // namespace xfem
