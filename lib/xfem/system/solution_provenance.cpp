// SPDX-License-Identifier: MIT
#include "xfem/system/solution_provenance.h"

namespace xfem {

Provenance solution_provenance(const EnrichedMesh& em, const std::string& problem_path) {
  Provenance provenance{{"enriched", fingerprint(em.mesh)}, {"problem", fingerprint_json_file(problem_path)}};
  if (em.cut) provenance["cut"] = fingerprint(em.cut->mesh());
  for (std::size_t k = 1; k < em.cuts.size(); ++k) provenance["cut_" + std::to_string(k)] = fingerprint(em.cuts[k].cut->mesh());
  return provenance;
}

}  // namespace xfem
