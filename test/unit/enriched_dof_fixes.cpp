// SPDX-License-Identifier: MIT
#include "xfem/solve/enriched_dof_fixes.h"

#include <catch2/catch.hpp>

TEST_CASE("enriched_point_key names the enriched.vtu array of an enriched vector", "[solve]") {
  xfem::LinearSystem s;
  s.np = 10;
  s.ns = 2;
  s.nb = 8;
  s.n = s.np + s.ns + s.nb;
  CHECK(xfem::enriched_point_key(s, 10) == "sign_dof = 10");
  CHECK(xfem::enriched_point_key(s, 11) == "sign_dof = 11");
  // Branch vectors come in fours per node: the key is the node's first one.
  CHECK(xfem::enriched_point_key(s, 12) == "branch_dof = 12");
  CHECK(xfem::enriched_point_key(s, 15) == "branch_dof = 12");
  CHECK(xfem::enriched_point_key(s, 17) == "branch_dof = 16");
}
