// SPDX-License-Identifier: MIT
// Floor for xfem-assemble (issue 9, docs/PERFORMANCE.md): the same element matrices, in memory, no
// file I/O in the timed part. Reads the enriched mesh and problem.json first (untimed), takes the
// sparsity pattern of K from one untimed call of the library, then times
// Element matrices by problem.json's rule, as xfem-assemble computes them by default: the
// cut-conforming rule (the cut elements split once per pass, then each enriched tet on its own
// points, face integrals shared between the two tets of a face) or the paper's oversampling.
//   loop:    the element matrix of every tet + scatter of its lower triangle into K's values
//            (rows found by binary search in the column) — a plain loop, none of assembly.cpp's
//            tricks (block tables, closed-form direct scatter);
//   compute: the same element matrices without the scatter (a checksum keeps them alive);
//   library: xfem::stiffness_matrix as xfem-assemble calls it (pattern + element loop + scatter).
// Prints the minimum over REPEATS of each as one JSON line on stdout.
// Usage: bare_assemble ENRICHED.vtu CUT PROBLEM.json [POINTS=0: problem's rule] [REPEATS=3]
// (CUT may be "" for a plain mesh.)
#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "xfem/system/assembly.h"
#include "xfem/integrate/conforming_quadrature.h"
#include "xfem/integrate/consistent_gradients.h"
#include "xfem/integrate/element_stiffness.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/core/error.h"
#include "xfem/integrate/oversampling_quadrature.h"
#include "xfem/system/problem.h"

namespace {
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: bare_assemble ENRICHED.vtu CUT PROBLEM.json [POINTS] [REPEATS=3]\n");
    return 2;
  }
  try {
    const xfem::Problem problem = xfem::read_problem(argv[3]);
    const xfem::EnrichedMesh em = xfem::read_enriched_mesh(argv[1], argv[2]);
    const int points = argc > 4 && std::atoi(argv[4]) > 0 ? std::atoi(argv[4]) : problem.points;
    const int repeats = argc > 5 ? std::max(1, std::atoi(argv[5])) : 3;
    const xfem::Lame material = xfem::lame(problem.E, problem.nu);
    const xfem::Quadrature rule = xfem::oversampling_quadrature(points, problem.refine);
    // POINTS given: the oversampling rule with them (as xfem-assemble --points); else problem.json's rule.
    const int order = problem.rule == xfem::Problem::Rule::Conforming && !(argc > 4 && std::atoi(argv[4]) > 0)
                          ? problem.order
                          : 0;
    xfem::SparseMatrix K = xfem::stiffness_matrix(em, material, rule, nullptr, {}, order);  // the pattern (untimed)
    // One pass over the tets' element matrices, each handed to `use`.
    xfem::PointRule at;
    const auto each_element = [&](const auto& use) {
      const xfem::CutElementSplits splits = order > 0 ? xfem::split_cut_elements(em) : xfem::CutElementSplits();
      xfem::FaceIntegralCache faces;
      Eigen::MatrixXd k;
      for (int t = 0; t < em.tets(); ++t) {
        if (order > 0 && em.size(t) > 4) {
          xfem::conforming_rule(em, splits, t, order, at);
          xfem::element_stiffness_at_points(em, t, at, material, k, order, &faces);
        } else {
          xfem::element_stiffness(em, t, rule, material, k);
        }
        use(t, k);
      }
    };
    const auto* outer = K.outerIndexPtr();
    const auto* inner = K.innerIndexPtr();
    double* values = K.valuePtr();

    double best_loop = 1e300, best_compute = 1e300, best_library = 1e300, checksum = 0.0;
    std::vector<long> g;  // scalar DOF of each row/column of k
    for (int r = 0; r < repeats; ++r) {
      auto t0 = std::chrono::steady_clock::now();
      std::fill(values, values + K.nonZeros(), 0.0);
      each_element([&](int t, const Eigen::MatrixXd& k) {
        const int m = em.size(t);
        g.resize(3 * m);
        for (int a = 0; a < m; ++a)
          for (int j = 0; j < 3; ++j) g[3 * a + j] = 3 * em.dofs[em.offsets[t] + a] + j;
        for (int c = 0; c < 3 * m; ++c) {
          const long col = g[c];
          const auto* first = inner + outer[col];
          const auto* last = inner + outer[col + 1];
          for (int row = 0; row < 3 * m; ++row) {
            if (g[row] < col) continue;
            const auto* found = std::lower_bound(first, last, g[row]);
            values[found - inner] += k(row, c);
          }
        }
      });
      best_loop = std::min(best_loop, since(t0));

      t0 = std::chrono::steady_clock::now();
      each_element([&](int, const Eigen::MatrixXd& k) { checksum += k.trace(); });
      best_compute = std::min(best_compute, since(t0));

      t0 = std::chrono::steady_clock::now();
      const xfem::SparseMatrix L = xfem::stiffness_matrix(em, material, rule, nullptr, {}, order);
      best_library = std::min(best_library, since(t0));
      checksum += L.nonZeros();
    }
    long enriched = 0;
    for (int t = 0; t < em.tets(); ++t) enriched += em.size(t) > 4;
    std::printf("{\"tets\": %d, \"enriched_tets\": %ld, \"nonzeros\": %ld, \"repeats\": %d, "
                "\"loop_seconds\": %.6f, \"compute_seconds\": %.6f, \"library_seconds\": %.6f, \"checksum\": %.6e}\n",
                em.tets(), enriched, static_cast<long>(K.nonZeros()), repeats, best_loop, best_compute, best_library,
                checksum);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bare_assemble: error: %s\n", e.what());
    return 1;
  }
}
