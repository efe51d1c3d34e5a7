// SPDX-License-Identifier: MIT
#include "xfem/solve/enriched_dof_fixes.h"

#include <vector>

#include "xfem/core/cli.h"
#include "xfem/system/dirichlet.h"

namespace xfem {

std::string enriched_point_key(const LinearSystem& s, long k) {
  if (k < s.np + s.ns) return "sign_dof = " + std::to_string(k);
  return "branch_dof = " + std::to_string(s.np + s.ns + 4 * ((k - s.np - s.ns) / 4));
}

EnrichedDofFixes fix_degenerate_enrichment(LinearSystem& s, double drop_tolerance,
                                           const std::function<void(const std::string&)>& info,
                                           const std::function<void(const std::string&)>& warn) {
  using cli::three_digits;
  // Enriched DOFs without support make K singular whatever the threshold: always eliminated.
  const auto unsupported = fix_unsupported_enrichment(s);
  if (!unsupported.empty()) {
    std::vector<long> vectors;
    for (long d : unsupported)
      if (vectors.empty() || vectors.back() != d / 3) vectors.push_back(d / 3);
    warn(std::to_string(unsupported.size()) + " enriched DOFs (" + std::to_string(vectors.size()) +
         (vectors.size() == 1 ? " vector" : " vectors") +
         ") have an exactly zero row in K (no support on one side of the cut): fixed to 0; first " +
         describe_dof(s, unsupported.front()) + " (its mesh point: the one with " + enriched_point_key(s, vectors.front()) +
         " in enriched.vtu)");
  }
  // drop what was asked, warn below 1e-8
  const auto tiny = tiny_enriched_dofs(s, drop_tolerance > 0 ? drop_tolerance : kTinyWarn);
  if (drop_tolerance > 0) {
    fix_to_zero(s, tiny);
    info("dropped " + std::to_string(tiny.size()) + " enriched DOFs (diagonal < " + three_digits(drop_tolerance) +
         " x mean original diagonal): fixed to 0");
  } else if (!tiny.empty()) {
    warn(std::to_string(tiny.size()) + " enriched DOFs have a diagonal below " + three_digits(kTinyWarn) +
         " x the mean original diagonal, first " + describe_dof(s, tiny.front()) +
         ": sign/branch nodes with tiny support make K near-singular (try --drop-tiny-enrichment 1e-6)");
  }
  return {static_cast<long>(unsupported.size()), drop_tolerance > 0 ? static_cast<long>(tiny.size()) : 0L};
}

}  // namespace xfem
