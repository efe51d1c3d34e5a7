// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/fracture/exact_fields.h"
#include "xfem/post/rms_error.h"

namespace xfem {

/// Errors of an X-FEM solution against an exact field (issue 8, docs/VERIFICATION.md).
struct ExactErrorReport {
  /// At the mesh's nodes, each evaluated on its own side of the cut (array `side`):
  /// rms = sqrt(sum_k |u(P_k) - u_h(P_k)|^2 / (3 NP)), max and its node, as for a reference mesh.
  RmsReport nodes;
  /// Over the volume, by the oversampling rule with `points` per tet (each point on its side of
  /// the cut, H(x)): l2 = ||u_h - u||_L2 (m^2.5), l2_exact = ||u||_L2; h1 = ||grad(u_h - u)||_L2
  /// (m^1.5), h1_exact = ||grad u||_L2. Relative figures: l2 / l2_exact, h1 / h1_exact.
  double l2 = 0.0, l2_exact = 0.0, h1 = 0.0, h1_exact = 0.0;
  /// max over the sample points of |eps(u_h) - eps(u)| (Frobenius norm of the strain error): the
  /// strain itself for a rigid exact field.
  double max_strain = 0.0;
  /// Rigid fields only: max of |[u_h] - [u]|, [.] = u(x, +1) - u(x, -1) the opening (the gap
  /// between the pieces), over the points where the edges of cut tets whose nodes are all
  /// enriched cross the cut (the other tets carry one side's field only); -1 for a
  /// Williams field or without a cut.
  double max_gap_error = -1.0;
  long samples = 0;     ///< sample points evaluated
  double volume = 0.0;  ///< sum of the tet volumes, m^3
};

/// Compares the X-FEM solution `u` (3N scalars) on `em` with `exact`. `points`: oversampling
/// points requested per tet (oversampling_quadrature; m^3 > points). Throws xfem::Error when `u`
/// has the wrong size or a sample needs the cut and `em` has none.
ExactErrorReport exact_error(const EnrichedMesh& em, const Eigen::VectorXd& u, const ExactField& exact, int points);

}  // namespace xfem
