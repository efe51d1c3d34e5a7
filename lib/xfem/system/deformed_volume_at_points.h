// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Core>

#include "xfem/system/nonlinear_assembly.h"

namespace xfem {

/// The body's volume after the displacement u, integrated over the nonlinear solve's own points:
/// sum_p w_p det F_p, the exact volume of the discrete deformation wherever F is constant (plain
/// tets, each side of a sign-enriched tet) and the rule's value where F varies (tets with branch
/// DOFs). xfem-visualize's deformed.vtu measures another thing there: its cells' corners moved by
/// u and joined by straight edges (docs/VERIFICATION.md "Large deformation", the organ's volume).
/// Split by the kind of tet, so that what the enriched tets add can be told from the body's.
struct PointVolume {
  struct Part {
    long tets = 0;
    double before = 0.0;  ///< m^3, sum of w_p
    double after = 0.0;   ///< m^3, sum of w_p det F_p
    /// The largest det F of a point carrying volume (next_to_front_weight of its tet's or more),
    /// its tet (-1: no tet) and that tet's centroid (reference configuration).
    double max_J = 0.0;
    int max_J_tet = -1;
    Eigen::Vector3d max_J_at = Eigen::Vector3d::Zero();
  };
  Part body, plain, sign, branch;  ///< every tet; tets with original DOFs only; with sign DOFs only; with branch DOFs
};

/// The volumes at u (3N) on the points of `body` (integrate_body).
PointVolume deformed_volume_at_points(const EnrichedMesh& em, const BodyIntegration& body, const Eigen::VectorXd& u);

}  // namespace xfem
