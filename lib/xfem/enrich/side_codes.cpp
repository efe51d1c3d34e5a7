// SPDX-License-Identifier: MIT
#include "xfem/enrich/side_codes.h"

namespace xfem {

int pack_sides(const int* sides, int cuts) {
  int code = 0;
  for (int k = 0; k < cuts; ++k)
    if (sides[k] > 0) code |= 1 << k;
  return code + 2;
}

int cut_function(const EnrichedMesh& em, int k, const int* sides) {
  const CutLayer& c = em.cuts[k];
  if (c.ends_on >= 0 && sides[c.ends_on] != c.ends_side) return 0;
  return sides[k];
}

}  // namespace xfem
