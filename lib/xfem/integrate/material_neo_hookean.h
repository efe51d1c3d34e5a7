// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>

#include "xfem/integrate/material_law.h"

namespace xfem {

/// The compressible neo-Hookean law of material_law.h: false for J = det F <= 0 (no energy there,
/// `out` untouched), else energy, P and A = dP/dF.
bool neo_hookean_stress(const Lame& lame, const Eigen::Matrix3d& F, StressAt& out);

}  // namespace xfem
