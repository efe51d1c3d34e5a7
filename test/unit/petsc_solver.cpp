// SPDX-License-Identifier: MIT
#include "xfem/solve/petsc_solver.h"

#include <catch2/catch.hpp>

TEST_CASE("petsc_solver: the automatic backend and process count follow the measured thresholds", "[petsc_solver]") {
  CHECK(xfem::automatic_backend(7908, true) == "cholmod");                 // beam S
  CHECK(xfem::automatic_backend(xfem::kPetscFromDofs - 3, false) == "cholmod");
  CHECK(xfem::automatic_backend(xfem::kPetscFromDofs, false) == "petsc");
  CHECK(xfem::automatic_backend(256188, false) == "petsc");                // the reference
  CHECK(xfem::automatic_backend(xfem::kPetscFromDofs, true) == "cholmod");  // cut: CHOLMOD longer
  CHECK(xfem::automatic_backend(xfem::kPetscFromDofsEnriched, true) == "petsc");
  CHECK(xfem::automatic_processes(1000, 2) == 1);
  CHECK(xfem::automatic_processes(xfem::kDofsPerProcess + 1, 2) == 2);
  CHECK(xfem::automatic_processes(1143018, 2) == 2);  // never more than the cores
  CHECK(xfem::automatic_processes(1143018, 0) == 1);  // hardware_concurrency() may say 0
}
