// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/integrate/oversampling_quadrature.h"
#include "xfem/geometry/tet_shape.h"

namespace xfem {

/// Lame parameters (DESIGN.md "Numerics"), pascals.
struct Lame {
  double lambda = 0.0;  ///< E nu / ((1 + nu)(1 - 2 nu))
  double mu = 0.0;      ///< E / (2 (1 + nu)), the shear modulus
};
/// From Young's modulus E (Pa) and Poisson's ratio nu; no checks (read_problem validates).
Lame lame(double E, double nu);

/// Local stiffness of formula (5) as corrected in DESIGN.md, for basis gradients g_n (rows of a
/// |C| x 3 matrix) integrated exactly or by quadrature:
///   k[3n+j][3m+i] = integral mu g_n,i g_m,j + lambda g_n,j g_m,i + delta_ij mu g_n . g_m.
/// Rows/columns 3n+j: component j (x, y, z) of the n-th entry of the tet's extended connectivity.

/// Closed form for a plain linear tet (constant gradients: one point is exact), N/m.
/// Symmetric positive semi-definite, 6 rigid modes in its null space.
Eigen::Matrix<double, 12, 12> tet_stiffness(const TetShape& shape, const Lame& material);

/// Stiffness of tet `t` of an enriched mesh, 3|C| x 3|C| in the order of its C (paper 3.5).
/// A tet with |C| = 4 (no enriched DOF) uses tet_stiffness. Others (blending, completely and
/// partially cut) integrate the enriched basis (enriched_basis.h) with `rule` (paper 3.6); cut
/// tets (cut_class > 0) first refine it at the cut when rule.refine_levels > 0 (refine_at_cut).
void element_stiffness(const EnrichedMesh& em, int t, const Quadrature& rule, const Lame& material,
                       Eigen::MatrixXd& k);

/// Formula (5) from sampled gradients: G is q x 3n, row p holding sqrt(w_p) dPhi_c/dx_a at
/// column 3c + a for integration point p with weight w_p (volume included). Then
/// S = G^T G = integral of dPhi_n/dx_a dPhi_m/dx_b, and k (3n x 3n) rearranges S.
/// Shared by every quadrature rule (oversampling, conforming_quadrature.h).
void stiffness_from_gradients(const Eigen::MatrixXd& G, const Lame& material, Eigen::MatrixXd& k);

/// The same from the moments S (3n x 3n, symmetric): S(3c + a, 3d + b) = integral of
/// dPhi_c/dx_a dPhi_d/dx_b, however they were obtained (closed_form_stiffness.h sums them block by block).
void stiffness_from_moments(const Eigen::Ref<const Eigen::MatrixXd>& S, const Lame& material, Eigen::MatrixXd& k);

}  // namespace xfem
