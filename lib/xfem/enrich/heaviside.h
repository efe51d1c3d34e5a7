// SPDX-License-Identifier: MIT
#pragma once

namespace xfem {

/// Shifted Heaviside psi_m(x) = (H(x) - H(P_m)) / 2 (paper, formula (2); DESIGN.md "Numerics").
/// @param h_x  H(x): +1 on the side the cut's normal points to, -1 below
/// @param h_m  H(P_m), the side of the enriched node, decided once by xfem-classify
/// @return 0 on the node's own side, +1 or -1 on the other side. Its gradient vanishes (H is
///         piecewise constant), which is why sign-enriched basis functions N_m psi_m have
///         gradient psi_m grad N_m.
inline double shifted_heaviside(int h_x, int h_m) { return 0.5 * (h_x - h_m); }

}  // namespace xfem
