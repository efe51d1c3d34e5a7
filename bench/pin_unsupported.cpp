// SPDX-License-Identifier: MIT
// Prepares a system/ directory for bench/bare_cholmod so that it factorizes exactly the matrix
// xfem-solve factorizes: enriched DOFs whose row of K is exactly zero (no support on one side of
// the cut) are added to the Dirichlet data with value 0, as xfem-solve does
// (xfem::fix_unsupported_enrichment). Without this CHOLMOD stops at the first zero pivot and the
// "floor" would be a partial factorization. Untimed preparation for bench/bench.py.
// Usage: pin_unsupported SYSTEM_DIR OUT_DIR   (prints the number of DOFs pinned)
#include <cstdio>
#include <exception>

#include "xfem/system/dirichlet.h"
#include "xfem/system/linear_system.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: pin_unsupported SYSTEM_DIR OUT_DIR\n");
    return 2;
  }
  try {
    xfem::LinearSystem s = xfem::read_linear_system(argv[1]);
    const auto pinned = xfem::fix_unsupported_enrichment(s);
    xfem::write_linear_system(s, argv[2], "bench/pin_unsupported");
    std::printf("%zu\n", pinned.size());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pin_unsupported: error: %s\n", e.what());
    return 1;
  }
}
