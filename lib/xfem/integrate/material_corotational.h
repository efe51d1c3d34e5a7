// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>

#include "xfem/integrate/material_law.h"

namespace xfem {

/// F = U diag(sigma) V^T with U V^T a rotation: the SVD with a reflection (det U det V < 0)
/// moved into the smallest singular value, which then turns negative (an inverted F, J < 0).
/// sigma(0) >= sigma(1) >= |sigma(2)|.
struct RotationVariantSvd {
  Eigen::Matrix3d U, V;
  Eigen::Vector3d sigma;
};
RotationVariantSvd rotation_variant_svd(const Eigen::Matrix3d& F);

/// The fixed-corotated law of material_law.h at any F (also J <= 0): energy, P and A = dP/dF
/// including the derivative of the polar rotation.
void corotational_stress(const Lame& lame, const Eigen::Matrix3d& F, StressAt& out);

}  // namespace xfem
