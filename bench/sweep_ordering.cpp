// SPDX-License-Identifier: MIT
// The uncut body's factor with and without a sweep-aware ordering (issue 35): nnz(L) of K_ss, the
// free original DOFs' block that xfem-sweep factorizes once, ordered by METIS (what it does), by AMD,
// and by constrained AMD (CHOLMOD's CAMD) with the DOFs the sweep will touch (the region: the free
// DOFs of tets with enriched DOFs at some step) last, in the order of the step that first reaches
// them. Ordered so, a step's new columns of the Schur complement need only the trailing rows of L
// (K_se is zero outside the region): what this costs in fill is what this measures. Prints one
// JSON line. Usage: sweep_ordering body.vtu problem.json sweep.vtp STEPS
#include <cholmod.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "xfem/enrich/classification.h"
#include "xfem/generate/cut_sweep.h"
#include "xfem/io/vtk_io.h"
#include "xfem/progressive/progressive_cut.h"
#include "xfem/solve/cholmod_view.h"
#include "xfem/system/problem.h"

namespace {

struct Fill {
  double lnz = 0;         // nonzeros of L (CHOLMOD's count after the symbolic analysis)
  double region_lnz = 0;  // of them, in the columns of region DOFs
  double seconds = 0;     // the analysis
};

// Symbolic analysis of A (lower triangle) with CHOLMOD's `ordering`, or the permutation `given`.
Fill analyze(cholmod_sparse* A, int ordering, const std::vector<int>* given, const std::vector<char>& in_region,
             cholmod_common& c) {
  c.nmethods = 1;
  c.method[0].ordering = given ? CHOLMOD_GIVEN : ordering;
  c.postorder = given ? 0 : 1;  // a postorder could move region columns before others
  c.supernodal = CHOLMOD_SUPERNODAL;
  const auto t0 = std::chrono::steady_clock::now();
  cholmod_factor* L = cholmod_analyze_p(A, given ? const_cast<int*>(given->data()) : nullptr, nullptr, 0, &c);
  Fill f;
  f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  f.lnz = c.lnz;
  const int* perm = static_cast<const int*>(L->Perm);
  const int* count = static_cast<const int*>(L->ColCount);
  for (std::size_t k = 0; k < L->n; ++k)
    if (in_region[perm[k]]) f.region_lnz += count[k];
  cholmod_free_factor(&L, &c);
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: sweep_ordering body.vtu problem.json sweep.vtp STEPS\n");
    return 2;
  }
  const xfem::TetMesh mesh = xfem::read_tet_mesh(argv[1]);
  const xfem::Problem problem = xfem::read_problem(argv[2]);
  const xfem::TriangleMesh sweep = xfem::read_triangle_mesh(argv[3]);
  const int steps = std::atoi(argv[4]);
  const std::vector<double> times = xfem::cut_times(sweep, argv[3]);
  const std::vector<double> t = xfem::step_times(times, steps);
  const xfem::UncutBody body = xfem::factorize_uncut(mesh, problem);
  const int nf = static_cast<int>(body.free_dofs.size());
  // The step at which each free DOF first joins the region (0: never).
  std::vector<int> first_step(nf, 0);
  for (int k = 1; k <= steps; ++k) {
    const auto cut = std::make_shared<const xfem::CutSurface>(xfem::cut_until(sweep, times, t[k - 1]));
    if (cut->mesh().triangles.rows() == 0) continue;
    const xfem::EnrichedMesh em = xfem::enriched_mesh(mesh, xfem::classify(mesh, *cut), cut);
    for (int e = 0; e < em.tets(); ++e)
      if (em.size(e) > 4)
        for (int c = 0; c < 4; ++c)
          for (int i = 0; i < 3; ++i) {
            const int f = body.reduced[3 * em.mesh.tets(e, c) + i];
            if (f >= 0 && first_step[f] == 0) first_step[f] = k;
          }
  }
  std::vector<char> in_region(nf);
  long region = 0;
  for (int f = 0; f < nf; ++f) region += in_region[f] = first_step[f] > 0;

  // K_ss's lower triangle as CHOLMOD's (the library's view, as CholeskyFactor passes it).
  xfem::SparseMatrix K = body.K_ss;
  K.makeCompressed();
  cholmod_sparse A = xfem::lower_triangle_view(K);
  cholmod_common c;
  cholmod_start(&c);
  c.print = 0;

  const Fill metis = analyze(&A, CHOLMOD_METIS, nullptr, in_region, c);
  const Fill amd = analyze(&A, CHOLMOD_AMD, nullptr, in_region, c);
  // CAMD: constraint set 0 (the rest of the body) first, then each step's new region DOFs.
  std::vector<int> member(first_step), perm(nf);
  const auto t0 = std::chrono::steady_clock::now();
  cholmod_camd(&A, nullptr, 0, member.data(), perm.data(), &c);
  const double camd_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Fill sweep_aware = analyze(&A, 0, &perm, in_region, c);
  sweep_aware.seconds += camd_seconds;
  // The same with one constraint set for the whole region (last, any order within it).
  for (int f = 0; f < nf; ++f) member[f] = in_region[f] ? 1 : 0;
  const auto t1 = std::chrono::steady_clock::now();
  cholmod_camd(&A, nullptr, 0, member.data(), perm.data(), &c);
  const double camd_last_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  Fill region_last = analyze(&A, 0, &perm, in_region, c);
  region_last.seconds += camd_last_seconds;
  cholmod_finish(&c);
  std::printf("{\"free_dofs\": %d, \"region_dofs\": %ld, \"uncut_factor_nonzeros\": %.0f, "
              "\"metis\": {\"lnz\": %.0f, \"region_lnz\": %.0f, \"seconds\": %.3f}, "
              "\"amd\": {\"lnz\": %.0f, \"region_lnz\": %.0f, \"seconds\": %.3f}, "
              "\"camd_region_last\": {\"lnz\": %.0f, \"region_lnz\": %.0f, \"seconds\": %.3f}, "
              "\"camd_by_step\": {\"lnz\": %.0f, \"region_lnz\": %.0f, \"seconds\": %.3f}}\n",
              nf, region, body.factor->factor_nonzeros, metis.lnz, metis.region_lnz, metis.seconds, amd.lnz,
              amd.region_lnz, amd.seconds, region_last.lnz, region_last.region_lnz, region_last.seconds,
              sweep_aware.lnz, sweep_aware.region_lnz, sweep_aware.seconds);
}
