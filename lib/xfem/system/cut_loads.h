// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/system/problem.h"

namespace xfem {

/// The number of cuts of an enriched mesh: em.cuts.size() with several, 1 with one cut, 0 without.
int cut_count(const EnrichedMesh& em);

/// Adds problem.cut_loads to f (3N, newtons): for each load on cut k, the integral over the cut's
/// faces of (p n + t) . [[Phi_i]] for every basis function Phi_i (cut_face_points, basis_jump of
/// cut_face_quadrature.h, with problem.order's rule): equal and opposite forces on the two faces,
/// so only the enriched DOFs of the cut elements get any (the sign DOFs, whose jump is N_l, and the
/// branch DOFs, whose F_0 jumps by 2 sqrt(r)). Throws xfem::Error "<file>: cut_loads[i].cut ..." for
/// a cut the mesh does not have, and "<file>: cut_loads[i]: cut k has no face inside the body" when
/// the load finds no cut element. Returns the total area loaded, m^2 (every load's cut counted once
/// per load).
double add_cut_loads(const EnrichedMesh& em, const Problem& problem, Eigen::VectorXd& f);

}  // namespace xfem
