// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/system/problem.h"

namespace xfem {

/// The Dirichlet data: scalar DOFs 3k + i of the ORIGINAL nodal DOFs of the selected nodes with
/// their values, increasing (docs/FORMATS.md "problem.json"). Per condition kind, node k at X gets
///   value:        the constant value (null components stay free);
///   exact:        the field's displacement at X on the node's side (em.side); with
///                 exact_enriched, a selected branch-enriched node also gets its 4 branch DOF
///                 vectors fixed to the field's crack-tip coefficients and its original DOF shifted
///                 so that the discrete displacement at the node is exact;
///   rotation:     R(axis, angle) (X - centre) + centre + translation - X;
///   value_array:  the node's tuple of the 3-component point array.
/// `load` in (0, 1] is the load factor of a step of a nonlinear solve: value, exact and
/// value_array values (and an exact field's branch coefficients) are multiplied by it, a rotation
/// turns by load * angle and translates by load * translation, so that a large rotation is reached
/// along its circle, not along the chord. load = 1 gives the full data, bit for bit the values
/// without the factor.
/// Throws xfem::Error naming the condition when it selects no node, when a Williams field's front
/// is not the mesh's (exact_enriched), when a value_array is missing from the mesh, has not 3
/// components or holds a non-finite value at a selected node, or both conditions when two
/// prescribe different values for the same DOF; and naming the problem file for a load outside
/// (0, 1].
void dirichlet_data(const EnrichedMesh& em, const Problem& problem, std::vector<long>& fixed,
                    std::vector<double>& values, double load = 1.0);

/// The displacement the rigid motion `r` prescribes at X when it has gone `load` of its way
/// (turned by load * angle, translated by load * translation).
Eigen::Vector3d rotation_displacement(const PrescribedRotation& r, const Eigen::Vector3d& X, double load = 1.0);

}  // namespace xfem
