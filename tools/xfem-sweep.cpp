// SPDX-License-Identifier: MIT
// Progressive cutting (issue 20): a blade's sweep as a time series, the uncut body factorized once
// and each step solved on the enriched DOFs alone (DESIGN.md, "Cutting does not touch the
// standard block").
#include "xfem/core/blas_threads.h"
#include "xfem/core/cli.h"
#include "xfem/post/sweep_run.h"

int main(int argc, char** argv) {
  // Each step's Schur update (threaded BLAS) is followed by this program's own threads: OpenBLAS's
  // idle threads must not spin through them (blas_threads.h). First, before any thread starts.
  xfem::blas_threads_sleep_when_idle();
  auto tool = xfem::cli::make_tool(
      "xfem-sweep",
      "Progressive cutting: the cut of a blade's sweep (a cut surface whose triangles carry the cell array 'time',\n"
      "e.g. from xfem-mesh cut-sweep) solved at K times t_k = t0 + k (t1 - t0) / K, k = 1..K, the cut at t_k being\n"
      "the triangles with time <= t_k. The uncut body is assembled and factorized once (CHOLMOD); each step\n"
      "classifies (the previous step's answers reused away from the new triangles) and enriches the body,\n"
      "integrates only the tets whose enrichment or nearby cut changed since the previous step and solves for the\n"
      "enriched DOFs by block elimination, the Schur complement kept from step to step (the uncut body's response on the DOFs the sweep touches computed once; --solver for the other ways):\n"
      "the same solution as xfem-classify, -enrich, -assemble and -solve on that cut (docs/PERFORMANCE.md: the cost). Writes per step\n"
      "DIR/step_NNN.vtu and DIR/step_NNN_wound.vtp (as xfem-visualize's deformed.vtu and wound.vtp) and the\n"
      "ParaView time series DIR/sweep.pvd (docs/FORMATS.md). Dirichlet conditions must have fixed values.",
      "xfem-sweep organ.vtu --cut sweep.vtp --problem problem.json --steps 40 -o frames --report sweep.json");
  xfem::SweepOptions o;
  auto& app = tool->app;
  app.add_option("body", o.body_path, "tetrahedral mesh of the uncut body (.vtu/.vtk/.msh)")->required();
  app.add_option("-c,--cut", o.cut_path, "the sweep: cut triangles with cell array 'time' in s (.vtp/.vtu/.vtk)")->required();
  app.add_option("-p,--problem", o.problem_path, "problem.json (material, materials per region, integration, Dirichlet "
                                                 "conditions with fixed values, Neumann, body force)")->required();
  app.add_option("--steps", o.steps, "number of steps K (>= 1)")->required();
  app.add_option("-o,--output", o.dir, "directory of the frames (created; files of the same names are replaced)")->required();
  app.add_option("--report", o.report_path, "JSON report: the factorization once, per step the time, counts and DOFs");
  app.add_flag("--solutions", o.solutions, "also write each step's solution DIR/u_NNN.mtx (3N values, m, as xfem-solve's "
                                           "u.mtx, with the fingerprints of the body, the step's cut and the problem)");
  app.add_flag("--cuts", o.cuts, "also write each step's cut DIR/cut_NNN.vtp (the triangles with time <= t_k)");
  app.add_flag("--png", o.png, "also render each step as DIR/step_NNN.png with one camera and one colour range for the "
                               "whole sweep (those of the last step; needs an X display: run under xvfb-run -a)");
  app.add_option("--scale", o.scale, "displacement magnification in the pictures, dimensionless")
      ->check(xfem::cli::range(1e-6, 1e6));
  app.add_option("--width", o.width, "picture width, pixels")->check(xfem::cli::range(64, 8192));
  app.add_option("--height", o.height, "picture height, pixels")->check(xfem::cli::range(64, 8192));
  app.add_option("--solver", o.solver,
                 "how each step is solved (the same solution every way): incremental (default: block elimination "
                 "on the enriched DOFs, the Schur complement kept from step to step, only what the cut's growth "
                 "changed computed anew, after a one-time computation of the uncut body's response on the DOFs the "
                 "whole sweep touches), schur (the Schur complement formed anew each step: a solve with the factor "
                 "per enriched DOF), refactor (the uncut K_ss, reused, with the enriched rows and columns, "
                 "factorized anew) or auto (schur while the enriched DOFs times one solve take less than the "
                 "factorization did, else refactor)")
      ->check(CLI::IsMember({"incremental", "auto", "schur", "refactor"}));
  app.add_option("--backend", o.backend,
                 "linear solver of the uncut body: cholmod (the only one: the sweep reuses one Cholesky factorization "
                 "for every step; petsc is refused, see docs/PERFORMANCE.md)")
      ->check(CLI::IsMember({"cholmod", "petsc"}));
  app.add_option("--compression", o.compression,
                 "compression of the frames' VTK XML files: lz4 (default: VTK's LZ4 compressor, written ~9x faster "
                 "than zlib for files ~1.25x larger; ParaView >= 5.5 and every xfem tool read it), zlib (level 1, as "
                 "the other tools write: for readers without LZ4) or none (docs/FORMATS.md, \"Conventions\")")
      ->check(CLI::IsMember({"lz4", "zlib", "none"}));
  app.add_option("--ordering", o.ordering, "CHOLMOD fill-reducing ordering: metis (default) or amd")
      ->check(CLI::IsMember({"metis", "amd"}));
  app.add_flag("--allow-large", o.allow_large, "run even with more than 1000 steps (each a solve and its frames)");
  return xfem::cli::run(*tool, argc, argv, [&] { xfem::run_sweep(o); });
}
