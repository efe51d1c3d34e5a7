// SPDX-License-Identifier: MIT
#include "xfem/post/sweep_frame.h"

#include <catch2/catch.hpp>

TEST_CASE("numbered names a sweep's step files with three digits", "[sweep]") {
  CHECK(xfem::numbered("step_", 7, ".vtu") == "step_007.vtu");
  CHECK(xfem::numbered("u_", 123, ".mtx") == "u_123.mtx");
  CHECK(xfem::numbered("cut_", 1000, ".vtp") == "cut_1000.vtp");
}
