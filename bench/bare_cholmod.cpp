// SPDX-License-Identifier: MIT
// Baseline for xfem-solve --backend cholmod: the same system/ directory, read by the same reader,
// Dirichlet DOFs eliminated in a plain loop, then the bare CHOLMOD calls with the settings of
// lib/xfem/solve/cholmod_solver.cpp (supernodal, METIS, postorder). Prints the timings on stdout as
// one JSON line. Usage: bare_cholmod SYSTEM_DIR [amd]
#include <cholmod.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <vector>

#include "xfem/system/linear_system.h"

namespace {
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bare_cholmod SYSTEM_DIR [amd]\n");
    return 2;
  }
  const auto t_start = std::chrono::steady_clock::now();
  const xfem::LinearSystem s = xfem::read_linear_system(argv[1]);
  const double read_seconds = since(t_start);

  // K_ff (lower triangle, CSC) and f_f - K_fc u_c.
  const int n = static_cast<int>(3 * s.n);
  std::vector<int> reduced(n, 0);
  std::vector<double> value(n, 0.0);
  for (std::size_t k = 0; k < s.fixed.size(); ++k) reduced[s.fixed[k]] = -1, value[s.fixed[k]] = s.fixed_values[k];
  int nf = 0;
  for (int d = 0; d < n; ++d)
    if (reduced[d] == 0) reduced[d] = nf++;
  std::vector<int> p(1, 0), i;
  std::vector<double> x, b;
  for (int d = 0; d < n; ++d) {
    if (reduced[d] < 0) continue;
    double rhs = s.f[d];
    for (xfem::SparseMatrix::InnerIterator it(s.K, d); it; ++it) {
      const int r = reduced[it.row()];
      if (r < 0) {
        rhs -= it.value() * value[it.row()];
      } else if (it.row() >= d) {
        i.push_back(r);
        x.push_back(it.value());
      }
    }
    b.push_back(rhs);
    p.push_back(static_cast<int>(i.size()));
  }

  cholmod_common c;
  cholmod_start(&c);
  c.supernodal = CHOLMOD_SUPERNODAL;
  c.nmethods = 1;
  c.method[0].ordering = argc > 2 && std::strcmp(argv[2], "amd") == 0 ? CHOLMOD_AMD : CHOLMOD_METIS;
  c.postorder = 1;
  cholmod_sparse A{};
  A.nrow = A.ncol = nf;
  A.nzmax = x.size();
  A.p = p.data();
  A.i = i.data();
  A.x = x.data();
  A.stype = -1;
  A.itype = CHOLMOD_INT;
  A.xtype = CHOLMOD_REAL;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = A.packed = 1;
  cholmod_dense B{};
  B.nrow = B.nzmax = B.d = nf;
  B.ncol = 1;
  B.x = b.data();
  B.xtype = CHOLMOD_REAL;
  B.dtype = CHOLMOD_DOUBLE;

  auto t0 = std::chrono::steady_clock::now();
  cholmod_factor* L = cholmod_analyze(&A, &c);
  const double analyze = since(t0);
  t0 = std::chrono::steady_clock::now();
  cholmod_factorize(&A, L, &c);
  const double factor = since(t0);
  t0 = std::chrono::steady_clock::now();
  cholmod_dense* X = cholmod_solve(CHOLMOD_A, L, &B, &c);
  const double solve = since(t0);
  const bool ok = X && c.status == CHOLMOD_OK;
  std::printf("{\"read_seconds\": %.4g, \"analyze_seconds\": %.4g, \"factor_seconds\": %.4g, \"solve_seconds\": %.4g, "
              "\"factor_nonzeros\": %.0f, \"status\": %d, \"total_seconds\": %.4g}\n",
              read_seconds, analyze, factor, solve, c.lnz, c.status, since(t_start));
  cholmod_free_dense(&X, &c);
  cholmod_free_factor(&L, &c);
  cholmod_finish(&c);
  return ok ? 0 : 1;
}
