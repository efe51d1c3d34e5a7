// SPDX-License-Identifier: MIT
#pragma once
#include <functional>
#include <string>

#include "xfem/system/linear_system.h"

namespace xfem {

/// Enriched DOFs whose diagonal is below this fraction of the mean original diagonal make K
/// near-singular (sign nodes with tiny support, paper end of 5.2): warned about, never dropped
/// unless asked.
constexpr double kTinyWarn = 1e-8;

/// The enriched.vtu point array and value that find the mesh point of enriched vector k
/// (FORMATS.md), e.g. "sign_dof = 12".
std::string enriched_point_key(const LinearSystem& s, long k);

/// What fix_degenerate_enrichment fixed to 0.
struct EnrichedDofFixes {
  long unsupported = 0;  ///< enriched DOFs with an exactly zero row of K
  long dropped = 0;      ///< enriched DOFs below the drop tolerance (0 without one)
};

/// xfem-solve's checks of the enriched DOFs before a solve: those without support make K singular
/// whatever the threshold and are always fixed to 0 (with a warning naming the first and its mesh
/// point); with `drop_tolerance` > 0 those whose diagonal is below it times the mean original
/// diagonal are fixed to 0 too (`info` says how many), else those below kTinyWarn are warned
/// about. Messages go to `info` and `warn` (without the tool's prefix).
EnrichedDofFixes fix_degenerate_enrichment(LinearSystem& s, double drop_tolerance,
                                           const std::function<void(const std::string&)>& info,
                                           const std::function<void(const std::string&)>& warn);

}  // namespace xfem
