// SPDX-License-Identifier: MIT
// Progressive cutting (issue 20): a blade's sweep as a time series, the uncut body factorized once
// and each step solved on the enriched DOFs alone (DESIGN.md, "Cutting does not touch the
// standard block").
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "xfem/core/background_queue.h"
#include "xfem/core/blas_threads.h"
#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/core/fingerprint.h"
#include "xfem/core/version.h"
#include "xfem/generate/cut_sweep.h"
#include "xfem/io/matrix_market.h"
#include "xfem/io/paraview_collection.h"
#include "xfem/io/vtk_io.h"
#include "xfem/post/sweep_frame.h"
#include "xfem/progressive/sweep_report.h"
#include "xfem/progressive/sweep_steps.h"

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
  std::string body_path, cut_path, problem_path, dir, report_path, ordering = "metis", solver = "incremental",
              backend = "cholmod", compression = "lz4";
  int steps = 0, width = 1200, height = 900;
  double scale = 1.0;
  bool solutions = false, cuts = false, png = false;
  auto& app = tool->app;
  app.add_option("body", body_path, "tetrahedral mesh of the uncut body (.vtu/.vtk/.msh)")->required();
  app.add_option("-c,--cut", cut_path, "the sweep: cut triangles with cell array 'time' in s (.vtp/.vtu/.vtk)")->required();
  app.add_option("-p,--problem", problem_path, "problem.json (material, integration, Dirichlet conditions with fixed "
                                               "values, Neumann, body force)")->required();
  app.add_option("--steps", steps, "number of steps K (>= 1)")->required();
  app.add_option("-o,--output", dir, "directory of the frames (created; files of the same names are replaced)")->required();
  app.add_option("--report", report_path, "JSON report: the factorization once, per step the time, counts and DOFs");
  app.add_flag("--solutions", solutions, "also write each step's solution DIR/u_NNN.mtx (3N values, m, as xfem-solve's u.mtx, "
                                         "with the fingerprints of the body, the step's cut and the problem)");
  app.add_flag("--cuts", cuts, "also write each step's cut DIR/cut_NNN.vtp (the triangles with time <= t_k)");
  app.add_flag("--png", png, "also render each step as DIR/step_NNN.png with one camera and one colour range for the "
                             "whole sweep (those of the last step; needs an X display: run under xvfb-run -a)");
  app.add_option("--scale", scale, "displacement magnification in the pictures, dimensionless")
      ->check(xfem::cli::range(1e-6, 1e6));
  app.add_option("--width", width, "picture width, pixels")->check(xfem::cli::range(64, 8192));
  app.add_option("--height", height, "picture height, pixels")->check(xfem::cli::range(64, 8192));
  app.add_option("--solver", solver,
                 "how each step is solved (the same solution every way): incremental (default: block elimination "
                 "on the enriched DOFs, the Schur complement kept from step to step, only what the cut's growth "
                 "changed computed anew, after a one-time computation of the uncut body's response on the DOFs the "
                 "whole sweep touches), schur (the Schur complement formed anew each step: a solve with the factor "
                 "per enriched DOF), refactor (the uncut K_ss, reused, with the enriched rows and columns, "
                 "factorized anew) or auto (schur while the enriched DOFs times one solve take less than the "
                 "factorization did, else refactor)")
      ->check(CLI::IsMember({"incremental", "auto", "schur", "refactor"}));
  app.add_option("--backend", backend,
                 "linear solver of the uncut body: cholmod (the only one: the sweep reuses one Cholesky factorization "
                 "for every step; petsc is refused, see docs/PERFORMANCE.md)")
      ->check(CLI::IsMember({"cholmod", "petsc"}));
  app.add_option("--compression", compression,
                 "compression of the frames' VTK XML files: lz4 (default: VTK's LZ4 compressor, written ~9x faster "
                 "than zlib for files ~1.25x larger; ParaView >= 5.5 and every xfem tool read it), zlib (level 1, as "
                 "the other tools write: for readers without LZ4) or none (docs/FORMATS.md, \"Conventions\")")
      ->check(CLI::IsMember({"lz4", "zlib", "none"}));
  app.add_option("--ordering", ordering, "CHOLMOD fill-reducing ordering: metis (default) or amd")
      ->check(CLI::IsMember({"metis", "amd"}));
  return xfem::cli::run(*tool, argc, argv, [&] {
    using xfem::cli::three_digits;
    if (backend == "petsc")
      throw xfem::Error("--backend petsc: not available in xfem-sweep: a step reuses the uncut body's one Cholesky "
                        "factorization for thousands of solves, which an iterative solver would pay for in full each "
                        "time; for a body too large for CHOLMOD run the tools per step with xfem-solve --backend petsc");
    if (steps < 1) throw xfem::Error("--steps " + std::to_string(steps) + ": the number of steps must be at least 1");
    if (std::filesystem::exists(dir) && !std::filesystem::is_directory(dir))
      throw xfem::Error(dir + ": exists and is not a directory");
    if (!report_path.empty()) xfem::cli::check_output(report_path, {".json"}, true);
    if (png && (!std::getenv("DISPLAY") || !*std::getenv("DISPLAY")))
      throw xfem::Error("--png: rendering needs an X display; run under 'xvfb-run -a' (DISPLAY is unset)");
    std::vector<std::string> warnings;
    const xfem::TetMesh mesh = xfem::read_tet_mesh(body_path, &warnings);
    const xfem::TriangleMesh sweep = xfem::read_triangle_mesh(cut_path, &warnings);
    for (const auto& w : warnings) xfem::cli::warn(w);
    const std::vector<double> times = xfem::cut_times(sweep, cut_path);
    const std::vector<double> t = xfem::step_times(times, steps);
    const xfem::Problem problem = xfem::read_problem(problem_path);
    std::filesystem::create_directories(dir);
    const auto in_dir = [&](const std::string& name) { return (std::filesystem::path(dir) / name).string(); };

    double start = xfem::cli::now();
    const xfem::UncutBody body = xfem::factorize_uncut(mesh, problem, ordering == "amd" ? xfem::Ordering::Amd
                                                                                         : xfem::Ordering::Metis);
    const double setup = xfem::cli::now() - start;
    xfem::cli::info(xfem::describe_uncut_body(body));
    xfem::Json report;
    report["generator"] = std::string("xfem-sweep ") + xfem::version;
    report["body"] = body_path;
    report["cut"] = cut_path;
    report["problem"] = problem_path;
    const xfem::Fingerprint body_fingerprint = xfem::fingerprint(mesh),
                            problem_fingerprint = xfem::fingerprint_json_file(problem_path);
    report["fingerprints"] = xfem::provenance_json({{"body", body_fingerprint},
                                                    {"cut", xfem::fingerprint(sweep)},
                                                    {"problem", problem_fingerprint}});
    report["factorization"] = xfem::factorization_json(body, setup);
    xfem::SweepSteps sweep_steps(body, sweep, cut_path, times, t, solver);
    // Incremental: the body's response on the DOFs the whole sweep touches, once.
    start = xfem::cli::now();
    const long region = sweep_steps.prepare(xfem::cli::progress("the body's response on the sweep's region"));
    const double region_seconds = sweep_steps.incremental() ? xfem::cli::now() - start : 0.0;
    if (sweep_steps.incremental())
      xfem::cli::info("the uncut body's response on the " + std::to_string(region) + " free DOFs the sweep touches: " +
                      three_digits(region_seconds) + " s (once)");
    report["factorization"]["region_dofs"] = region;
    report["factorization"]["region_seconds"] = region_seconds;
    report["steps"] = xfem::Json::array();
    std::vector<xfem::CollectionEntry> collection;
    // Pictures: the camera, framing and colour range of the last step (the largest cut), for all.
    xfem::SnapshotOptions picture;
    std::unique_ptr<xfem::CutSolution> last;
    double last_solved = 0;
    if (png) {
      start = xfem::cli::now();
      last = std::make_unique<xfem::CutSolution>(sweep_steps.solve(steps));
      xfem::complete_solution(body, *last);
      last_solved = xfem::cli::now() - start;
      const xfem::DeformedBody frame = xfem::sweep_frame(*last, problem);
      // The incremental solver's step K follows step K - 1 like every other step: solve it again there.
      if (sweep_steps.incremental()) last.reset();
      report["factorization"]["picture_setup_seconds"] = xfem::cli::now() - start;
      picture = xfem::sweep_pictures(frame, scale, width, height);
    }
    const xfem::Compression packing = xfem::compression_named(compression);
    // A step's frame is built and written in the background while the next steps are solved
    // (BackgroundQueue: a worker thread at the lowest priority, on the CPU the steps leave idle;
    // at the same priority it would slow every parallel section of the steps). The frame is a
    // third of a step, and much of it (the split along the cut, the compression, the files)
    // keeps only one core busy. Its picture is rendered in the main thread, which owns VTK's
    // rendering.
    struct Framed {
      int k = 0;
      std::unique_ptr<xfem::CutSolution> step;
      xfem::DeformedBody frame;
      xfem::StepTimes times;
    };
    const auto write_frame = [&](int k, std::unique_ptr<xfem::CutSolution> step, double solved) {
      Framed out;
      const double begin = xfem::cli::now();
      const xfem::EnrichedMesh& em = step->em;
      xfem::complete_solution(body, *step);
      out.frame = xfem::sweep_frame(*step, problem);
      out.times.built = xfem::cli::now() - begin;
      xfem::write_tet_mesh(out.frame.volume, in_dir(xfem::numbered("step_", k, ".vtu")), packing);
      xfem::write_triangle_mesh(out.frame.wound, in_dir(xfem::numbered("step_", k, "_wound.vtp")), packing);
      out.times.written = xfem::cli::now() - begin;  // what xfem-visualize does
      if (solutions) {  // with the fingerprints xfem-solve writes, so xfem-visualize/-rmserror can check a frame's inputs
        xfem::Provenance made_for{{"enriched", body_fingerprint}, {"problem", problem_fingerprint}};
        if (em.cut) made_for["cut"] = xfem::fingerprint(em.cut->mesh());
        xfem::write_vector(step->u, in_dir(xfem::numbered("u_", k, ".mtx")), xfem::provenance_comments(made_for));
      }
      if (cuts && em.cut) xfem::write_triangle_mesh(em.cut->mesh(), in_dir(xfem::numbered("cut_", k, ".vtp")));
      out.k = k;
      out.step = std::move(step);
      out.times.solved = solved;
      return out;
    };
    // A written frame, in the main thread: its picture, its entries in the collection, the progress
    // line and the report's row (its step_seconds filled in at the end).
    const auto finish = [&](const Framed& f) {
      const int k = f.k;
      const double picture_start = xfem::cli::now();
      if (png) {
        picture.title = "t = " + three_digits(t[k - 1]) + " s (step " + std::to_string(k) + " of " + std::to_string(steps) + ")";
        xfem::write_snapshot(f.frame.volume, f.frame.wound, in_dir(xfem::numbered("step_", k, ".png")), picture);
      }
      xfem::StepTimes times = f.times;
      times.pictured = png ? xfem::cli::now() - picture_start : 0.0;
      collection.push_back({t[k - 1], 0, xfem::numbered("step_", k, ".vtu")});
      collection.push_back({t[k - 1], 1, xfem::numbered("step_", k, "_wound.vtp")});
      xfem::cli::info(xfem::describe_step(*f.step, k, steps, t[k - 1], sweep_steps.incremental(), times, png));
      report["steps"].push_back(xfem::step_json(*f.step, k, t[k - 1], sweep_steps.incremental(), times));
      if (f.step->unsupported_dofs > 0)
        xfem::cli::detail(std::to_string(f.step->unsupported_dofs) + " enriched DOFs without support fixed to 0");
    };
    // Step k's wall time: from the start of its solution to the start of the next one's (for the
    // last, to every frame written), its share of the sweep's whole time.
    std::vector<double> wall(static_cast<std::size_t>(steps), 0.0);
    // The steps' and the frames' BLAS on one thread each (IncrementalSchur::update splits its
    // products between threads of ours): OpenBLAS's own threads would have their caller spin on
    // sched_yield while it waits for them, on the core the frames and the next step's element
    // matrices need. Declared before the frames: it is restored only once no frame task runs.
    const xfem::BlasThreads steps_blas(1);
    // Declared after everything its tasks use: its destructor waits for a running one.
    xfem::BackgroundQueue<Framed> frames;
    // More frames waiting than this and the main thread builds the oldest itself: the worker has
    // fallen behind (a loaded machine), and unwritten frames hold their steps' solutions.
    const std::size_t most_waiting = 2;
    for (int k = 1; k <= steps; ++k) {
      start = xfem::cli::now();
      const bool solved_first = k == steps && last;  // for the pictures' camera, above
      auto step = solved_first ? std::move(last) : std::make_unique<xfem::CutSolution>(sweep_steps.solve(k));
      const double solved = solved_first ? last_solved : xfem::cli::now() - start;
      auto task = std::make_shared<std::unique_ptr<xfem::CutSolution>>(std::move(step));
      frames.push([&write_frame, k, task, solved] { return write_frame(k, std::move(*task), solved); });
      while (frames.waiting() > most_waiting) frames.run_oldest_waiting();
      while (frames.ready()) finish(frames.take());
      if (k == steps)
        while (frames.size() > 0) finish(frames.take());
      wall[k - 1] = xfem::cli::now() - start;
    }
    for (int k = 1; k <= steps; ++k) report["steps"][k - 1]["step_seconds"] = wall[k - 1];
    xfem::write_paraview_collection(collection, in_dir("sweep.pvd"));
    if (!report_path.empty()) xfem::write_json(report, report_path);
  });
}
