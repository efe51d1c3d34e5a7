// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "xfem/integrate/element_forces.h"
#include "xfem/integrate/material_law.h"
#include "xfem/integrate/tet_materials.h"
#include "xfem/system/stiffness_pattern.h"

namespace xfem {

/// The whole body's integration for the nonlinear solve: every tet's points and basis gradients
/// (element_points), computed once and reused by every residual and tangent of every Newton
/// iteration (they live in the reference configuration), and K's pattern.
struct BodyIntegration {
  std::vector<ElementPoints> tets;
  Pattern pattern;
  long points = 0;  ///< integration points in all
  /// Each tet's law (problem.json `materials`); null: internal_forces' `law` for every tet.
  const TetMaterials* materials = nullptr;
};

/// Integrates em with the cut-conforming rule of order `order` (the linear path's default rule).
/// `progress` (optional) gets the fraction of tets done.
BodyIntegration integrate_body(const EnrichedMesh& em, int order, const std::function<void(double)>& progress = {});

/// The body's internal forces at the displacement u (3N): energy = total strain energy (J),
/// r = internal forces (3N, N), and with `K` non-null the tangent dr/du into *K (3N x 3N, lower
/// triangle, K's pattern: pattern_matrix). Each tet has `law`, or body.materials->law(t) when the body
/// has per-tet materials. Returns false when some point of a model other than
/// "linear" is inverted (det F <= 0); `min_J` gets the smallest det F met.
bool internal_forces(const EnrichedMesh& em, const BodyIntegration& body, const MaterialLaw& law,
                     const Eigen::VectorXd& u, double& energy, Eigen::VectorXd& r, SparseMatrix* K, double* min_J = nullptr,
                     Tangent kind = Tangent::Exact);

}  // namespace xfem
