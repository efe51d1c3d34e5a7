// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>

#include "xfem/integrate/material_law.h"

namespace xfem {

/// The compressible neo-Hookean law of material_law.h: false for J = det F <= 0 (no energy there,
/// `out` untouched), else energy, P and A = dP/dF. With continued_below = Jc in (0, 1), the law is
/// continued for J < Jc (every J, also J <= 0): its volumetric part h(J) = -mu ln J + lambda/2 (ln J)^2
/// replaced there by h's second-order Taylor polynomial at Jc (docs/METHOD.md "Next to a crack front").
bool neo_hookean_stress(const Lame& lame, const Eigen::Matrix3d& F, StressAt& out, double continued_below = 0.0);

}  // namespace xfem
