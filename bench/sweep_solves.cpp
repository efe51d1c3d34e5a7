// SPDX-License-Identifier: MIT
// Cost of solves with the uncut body's factor (xfem-sweep's one factorization), per right-hand side,
// for blocks of 1, 16, 64 and 256 columns: what the region Green's function of progressive cutting
// costs per column (docs/PERFORMANCE.md "Progressive cutting").
//   sweep_solves body.vtu problem.json
#include <chrono>
#include <cstdio>

#include "xfem/system/problem.h"
#include "xfem/progressive/progressive_cut.h"
#include "xfem/io/vtk_io.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: sweep_solves body.vtu problem.json\n");
    return 2;
  }
  const xfem::TetMesh mesh = xfem::read_tet_mesh(argv[1]);
  const xfem::Problem problem = xfem::read_problem(argv[2]);
  const xfem::UncutBody body = xfem::factorize_uncut(mesh, problem);
  std::printf("free DOFs %zu, factor %.3g s\n", body.free_dofs.size(),
              body.factor->analyze_seconds + body.factor->factor_seconds);
  for (int cols : {1, 16, 64, 256}) {
    const Eigen::MatrixXd B = Eigen::MatrixXd::Random(body.factor->size(), cols);
    const auto t0 = std::chrono::steady_clock::now();
    const Eigen::MatrixXd X = body.factor->solve(B);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%4d columns: %.3f s, %.2f ms per column (check %.3g)\n", cols, s, 1e3 * s / cols, X(0, 0));
  }
}
