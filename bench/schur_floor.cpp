// SPDX-License-Identifier: MIT
// The floor of a sweep step's Schur factor update (issue 35, docs/PERFORMANCE.md "The speed targets
// against this machine's floors"). Every cutting step of an xfem-sweep report updates S's
// Cholesky factor with
//   the new rows against the kept factor   (triangular solve, k rows x p: k p^2 flops)
//   the trailing block's update            (t^2 p)
//   the trailing block's factorization     (t^3 / 3)
// for k = added_dofs, t = refactored_rows and p = enriched_dofs - t. No exact method that keeps a
// Cholesky factor of S avoids this work: S is dense (A^-1 is), and the new rows' part of the factor
// is S's new rows times the kept factor's inverse. Its floor is those flops at the machine's peak,
// taken as the best of RUNS large matrix products (dgemm, n = 2000, OpenBLAS's threads on every
// core): no BLAS kernel runs faster. Printed per step beside the step's own factor time
// (`schur_factor_seconds`), then the medians.
//   schur_floor report.json [runs]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include <Eigen/Core>

#include "xfem/core/median.h"
#include "xfem/core/seconds_since.h"

extern "C" void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
                       const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
                       const double* beta, double* c, const int* ldc);

namespace {

/// The best rate of RUNS products C -= A B^T of n x n matrices: flop/s.
double peak_rate(int runs) {
  const int n = 2000;
  const Eigen::MatrixXd A = Eigen::MatrixXd::Random(n, n), B = Eigen::MatrixXd::Random(n, n);
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n, n);
  const double one = 1.0, minus = -1.0;
  double best = 1e300;
  for (int r = 0; r < runs + 1; ++r) {  // the first run starts OpenBLAS's threads: not counted
    const auto t0 = std::chrono::steady_clock::now();
    dgemm_("N", "T", &n, &n, &n, &minus, A.data(), &n, B.data(), &n, &one, C.data(), &n);
    if (r > 0) best = std::min(best, xfem::seconds_since(t0));
  }
  if (!std::isfinite(C(0, 0))) {
    std::fprintf(stderr, "schur_floor: the product is not finite\n");
    std::exit(1);
  }
  return 2.0 * n * n * double(n) / best;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: schur_floor report.json [runs]\n");
    return 2;
  }
  const int runs = argc == 3 ? std::atoi(argv[2]) : 5;
  if (runs < 1) {
    std::fprintf(stderr, "schur_floor: runs must be at least 1\n");
    return 2;
  }
  struct Step {
    int step, k, p, t;
    double measured;
  };
  std::vector<Step> steps;
  try {
    std::ifstream in(argv[1]);
    if (!in) throw std::runtime_error("cannot open");
    nlohmann::json report;
    in >> report;
    for (const auto& s : report.at("steps")) {
      if (s.at("enriched_dofs").get<int>() == 0) continue;  // the steps that cut, as median_step's
      const int m = s.at("enriched_dofs"), t = s.at("refactored_rows");
      steps.push_back({s.at("step"), s.at("added_dofs"), m - t, t, s.at("schur_factor_seconds")});
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "schur_floor: %s: not an xfem-sweep report of the incremental solver (%s)\n", argv[1],
                 e.what());
    return 1;
  }
  if (steps.empty()) {
    std::fprintf(stderr, "schur_floor: %s: no step cuts\n", argv[1]);
    return 1;
  }
  const double peak = peak_rate(runs);
  std::printf("peak: %.1f GFlop/s (dgemm 2000^3, best of %d)\n", peak / 1e9, runs);
  std::printf("step      k      p      t   GFlop   floor ms   the step's ms   the step's GFlop/s\n");
  std::vector<double> floor_s, measured_s, gflop;
  for (const Step& s : steps) {
    const double flops = double(s.k) * s.p * s.p + double(s.t) * s.t * s.p + double(s.t) * s.t * s.t / 3;
    std::printf("%4d %6d %6d %6d %7.3f %10.2f %15.2f %20.1f\n", s.step, s.k, s.p, s.t, flops / 1e9,
                1e3 * flops / peak, 1e3 * s.measured, s.measured > 0 ? flops / s.measured / 1e9 : 0.0);
    floor_s.push_back(flops / peak);
    measured_s.push_back(s.measured);
    gflop.push_back(flops / 1e9);
  }
  std::printf("median over %zu steps: %.3f GFlop, floor %.2f ms, the steps' factor update %.2f ms\n", steps.size(),
              xfem::median(gflop), 1e3 * xfem::median(floor_s), 1e3 * xfem::median(measured_s));
}
