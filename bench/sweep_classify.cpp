// SPDX-License-Identifier: MIT
// A sweep's classification at the cost of what changed (issue 35): per step of the sweep, the growing
// classifier (xfem-sweep's: the previous step's answers reused away from the new triangles) against
// classify() from scratch on the same cut, their thread CPU times (one thread: the machine's load
// does not enter) and the points whose side was judged anew; every step's arrays must be equal
// (exit status 1 otherwise). docs/PERFORMANCE.md "Progressive cutting".
//   sweep_classify body.vtu sweep.vtp steps [--growing-only]   (the latter to profile the growing one alone)
#include <algorithm>
#include <cstdlib>
#include <string>
#include <cstdio>
#include <ctime>
#include <vector>

#include "xfem/core/median.h"
#include "xfem/core/thread_limit.h"
#include "xfem/enrich/growing_classification.h"
#include "xfem/generate/cut_sweep.h"
#include "xfem/io/vtk_io.h"

namespace {
double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

bool same(const xfem::Classification& a, const xfem::Classification& b) {
  if (a.side != b.side || a.on_cut != b.on_cut || a.enrichment != b.enrichment || a.cut_class != b.cut_class ||
      a.cut_edges != b.cut_edges || a.cut_faces != b.cut_faces ||
      xfem::count_values(a.counts) != xfem::count_values(b.counts) ||
      a.front.segments().size() != b.front.segments().size())
    return false;
  for (std::size_t i = 0; i < a.front.segments().size(); ++i) {
    const auto &s = a.front.segments()[i], &t = b.front.segments()[i];
    if (s.p0 != t.p0 || s.p1 != t.p1 || s.b != t.b) return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const bool growing_only = argc == 5 && std::string(argv[4]) == "--growing-only";
  if (argc != 4 && !growing_only) {
    std::fprintf(stderr, "usage: sweep_classify body.vtu sweep.vtp steps [--growing-only]\n");
    return 2;
  }
  xfem::set_thread_limit(1);
  const xfem::TetMesh mesh = xfem::read_tet_mesh(argv[1]);
  const xfem::TriangleMesh sweep = xfem::read_triangle_mesh(argv[2]);
  const std::vector<double> times = xfem::cut_times(sweep, argv[2]);
  const std::vector<double> t = xfem::step_times(times, std::atoi(argv[3]));
  xfem::GrowingCutClassifier growing(mesh);
  std::vector<double> grown, scratch;
  int unequal = 0;
  std::printf("%zu tets, %zu points, %zu steps\nstep triangles growing_ms scratch_ms sides_judged edges_tested tets_split equal\n",
              static_cast<std::size_t>(mesh.tets.rows()), static_cast<std::size_t>(mesh.points.rows()), t.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    const std::vector<int> ids = xfem::cut_until_ids(times, t[k]);
    if (ids.empty()) continue;
    const xfem::CutSurface cut(xfem::cut_until(sweep, times, t[k]));
    double c0 = cpu_seconds();
    const xfem::Classification a = growing.classify(cut, ids);
    const double ga = cpu_seconds() - c0;
    c0 = cpu_seconds();
    const xfem::Classification b = growing_only ? a : xfem::classify(mesh, cut);
    const double gb = cpu_seconds() - c0;
    const bool equal = same(a, b);
    unequal += !equal;
    if (growing.stats().incremental) {
      grown.push_back(ga);
      scratch.push_back(gb);
    }
    std::printf("%zu %zu %.2f %.2f %ld %ld %ld %s\n", k + 1, ids.size(), 1e3 * ga, 1e3 * gb, growing.stats().sides,
                growing.stats().edges, growing.stats().tets, equal ? "yes" : "NO");
  }
  std::printf("median over the %zu incremental steps (thread CPU, ms): growing %.2f, from scratch %.2f; unequal steps %d\n",
              grown.size(), 1e3 * xfem::median(grown), 1e3 * xfem::median(scratch), unequal);
  return unequal ? 1 : 0;
}
