// SPDX-License-Identifier: MIT
// Lame parameters from E and nu (declared in element_stiffness.h). A file of its own: problem.json's
// parser uses it (integrate/tet_materials.h), and the readers' fuzz harnesses link that parser
// without the element integration (fuzz/CMakeLists.txt).
#include "xfem/integrate/element_stiffness.h"

namespace xfem {

Lame lame(double E, double nu) {
  Lame m;
  m.lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  m.mu = E / (2.0 * (1.0 + nu));
  return m;
}

}  // namespace xfem
