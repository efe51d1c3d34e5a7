// SPDX-License-Identifier: MIT
#include "xfem/post/sweep_run.h"

#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <vector>

#include "xfem/core/background_queue.h"
#include "xfem/core/blas_threads.h"
#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/core/fingerprint.h"
#include "xfem/core/median.h"
#include "xfem/core/thread_limit.h"
#include "xfem/core/version.h"
#include "xfem/generate/cut_sweep.h"
#include "xfem/io/paraview_collection.h"
#include "xfem/io/vtk_io.h"
#include "xfem/post/sweep_frame.h"
#include "xfem/progressive/sweep_report.h"
#include "xfem/progressive/sweep_steps.h"

namespace xfem {
namespace {

void check_options(const SweepOptions& o) {
  if (o.backend == "petsc")
    throw Error("--backend petsc: not available in xfem-sweep: a step reuses the uncut body's one Cholesky "
                "factorization for thousands of solves, which an iterative solver would pay for in full each "
                "time; for a body too large for CHOLMOD run the tools per step with xfem-solve --backend petsc");
  if (o.steps < 1) throw Error("--steps " + std::to_string(o.steps) + ": the number of steps must be at least 1");
  if (o.steps > kMaxSweepSteps && !o.allow_large)
    throw Error("--steps " + std::to_string(o.steps) + ": " + std::to_string(o.steps) + " solves and " +
                std::to_string(2L * o.steps) +
                " frame files requested (limit " + std::to_string(kMaxSweepSteps) + " steps; fewer --steps, or --allow-large)");
  if (std::filesystem::exists(o.dir) && !std::filesystem::is_directory(o.dir))
    throw Error(o.dir + ": exists and is not a directory");
  if (!o.report_path.empty()) cli::check_output(o.report_path, {".json"}, true);
  if (o.png && (!std::getenv("DISPLAY") || !*std::getenv("DISPLAY")))
    throw Error("--png: rendering needs an X display; run under 'xvfb-run -a' (DISPLAY is unset)");
}

// The steps' times go into sweep.pvd and the report: times spanning more than double precision
// holds (-1e308 to 1e308) make t1 - t0 overflow.
void check_finite_times(const std::vector<double>& times, const std::vector<double>& t, const std::string& cut_path) {
  const auto [lo, hi] = std::minmax_element(times.begin(), times.end());
  for (std::size_t k = 0; k < t.size(); ++k)
    if (!std::isfinite(t[k]))
      throw Error(cut_path + ": the time of step " + std::to_string(k + 1) + " is not a finite number (cell array "
                  "'time' from " + short_number(*lo) + " to " + short_number(*hi) +
                  " s: the span overflows double precision; shift or scale the times)");
}

}  // namespace

void run_sweep(const SweepOptions& o) {
  using cli::three_digits;
  check_options(o);
  const int steps = o.steps;
  std::vector<std::string> warnings;
  const TetMesh mesh = read_tet_mesh(o.body_path, &warnings);
  const TriangleMesh sweep = read_triangle_mesh(o.cut_path, &warnings);
  for (const auto& w : warnings) cli::warn(w);
  const std::vector<double> times = cut_times(sweep, o.cut_path);
  const std::vector<double> t = step_times(times, steps);
  check_finite_times(times, t, o.cut_path);
  const Problem problem = read_problem(o.problem_path);
  require_linear_material(problem, "xfem-sweep solves linear systems only");
  tet_materials(problem, mesh, o.body_path);  // an unknown region is named with the body's file before any work
  refuse_cut_loads_and_contact(problem, "xfem-sweep's steps leave the cut's faces free (each step's cut differs)");
  std::filesystem::create_directories(o.dir);

  double start = cli::now();
  const UncutBody body = factorize_uncut(mesh, problem, o.ordering == "amd" ? Ordering::Amd : Ordering::Metis);
  const double setup = cli::now() - start;
  cli::info(describe_uncut_body(body));
  Json report;
  report["generator"] = std::string("xfem-sweep ") + version;
  report["body"] = o.body_path;
  report["cut"] = o.cut_path;
  report["problem"] = o.problem_path;
  FrameFiles files{o.dir, compression_named(o.compression), o.solutions, o.cuts, fingerprint(mesh),
                   fingerprint_json_file(o.problem_path)};
  report["fingerprints"] =
      provenance_json({{"body", files.body}, {"cut", fingerprint(sweep)}, {"problem", files.problem}});
  report["factorization"] = factorization_json(body, setup);
  SweepSteps sweep_steps(body, sweep, o.cut_path, times, t, o.solver);
  // Incremental: the body's response on the DOFs the whole sweep touches, once.
  start = cli::now();
  const long region = sweep_steps.prepare(cli::progress("the body's response on the sweep's region"));
  const double region_seconds = sweep_steps.incremental() ? cli::now() - start : 0.0;
  if (sweep_steps.incremental())
    cli::info("the uncut body's response on the " + std::to_string(region) + " free DOFs the sweep touches: " +
              three_digits(region_seconds) + " s (once)");
  report["factorization"]["region_dofs"] = region;
  report["factorization"]["region_seconds"] = region_seconds;
  report["steps"] = Json::array();
  std::vector<CollectionEntry> collection;
  // Pictures: the camera, framing and colour range of the last step (the largest cut), for all.
  SnapshotOptions picture;
  std::unique_ptr<CutSolution> last;
  double last_solved = 0;
  if (o.png) {
    start = cli::now();
    last = std::make_unique<CutSolution>(sweep_steps.solve(steps));
    complete_solution(body, *last);
    last_solved = cli::now() - start;
    const DeformedBody frame = sweep_frame(*last, problem);
    // The incremental solver's step K follows step K - 1 like every other step: solve it again there.
    if (sweep_steps.incremental()) last.reset();
    report["factorization"]["picture_setup_seconds"] = cli::now() - start;
    picture = sweep_pictures(frame, o.scale, o.width, o.height);
  }
  std::vector<std::pair<int, StepSplit>> cutting;  // the steps that cut something, their time split
  // A written frame, in the main thread: its picture, its entries in the collection, the progress
  // line and the report's row (its step_seconds filled in at the end).
  const auto finish = [&](const WrittenFrame& f) {
    const int k = f.k;
    const double picture_start = cli::now();
    if (o.png) {
      picture.title = "t = " + three_digits(t[k - 1]) + " s (step " + std::to_string(k) + " of " + std::to_string(steps) + ")";
      write_snapshot(f.frame.volume, f.frame.wound, files.in_dir(numbered("step_", k, ".png")), picture);
    }
    StepTimes times = f.times;
    times.pictured = o.png ? cli::now() - picture_start : 0.0;
    collection.push_back({t[k - 1], 0, numbered("step_", k, ".vtu")});
    collection.push_back({t[k - 1], 1, numbered("step_", k, "_wound.vtp")});
    cli::info(describe_step(*f.step, k, steps, t[k - 1], sweep_steps.incremental(), times, o.png));
    report["steps"].push_back(step_json(*f.step, k, t[k - 1], sweep_steps.incremental(), times));
    if (f.step->enriched_dofs > 0) cutting.push_back({k, step_split(*f.step, times)});
    if (f.step->unsupported_dofs > 0)
      cli::detail(std::to_string(f.step->unsupported_dofs) + " enriched DOFs without support fixed to 0");
  };
  // Step k's wall time: from the start of its solution to the start of the next one's (for the
  // last, to every frame written), its share of the sweep's whole time.
  std::vector<double> wall(static_cast<std::size_t>(steps), 0.0);
  // And the CPU time the process spent meanwhile (every thread: the step's, the frames'): the
  // step's work, which unlike its wall time does not grow with the other programs' load on the
  // machine (docs/PERFORMANCE.md measures on a shared one).
  const auto process_cpu = [] {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  };
  std::vector<double> cpu(static_cast<std::size_t>(steps), 0.0);
  // The steps' and the frames' BLAS on one thread each (IncrementalSchur::update splits its
  // products between threads of ours): OpenBLAS's own threads would have their caller spin on
  // sched_yield while it waits for them, on the core the frames and the next step's element
  // matrices need. Declared before the frames: it is restored only once no frame task runs.
  const BlasThreads steps_blas(1);
  // A step's frame is built and written in the background while the next steps are solved
  // (BackgroundQueue: a worker thread at the lowest priority, on the CPU the steps leave idle;
  // at the same priority it would slow every parallel section of the steps). The frame is a
  // third of a step, and much of it (the split along the cut, the compression, the files)
  // keeps only one core busy. Its picture is rendered in the main thread, which owns VTK's
  // rendering.
  // Declared after everything its tasks use: its destructor waits for a running one.
  // Held to one thread (--threads 1, OMP_NUM_THREADS=1), the frames are built in the main thread.
  const bool background = thread_limit() > 1;
  BackgroundQueue<WrittenFrame> frames(background);
  // More frames waiting than this and the main thread builds the oldest itself: the worker has
  // fallen behind (a loaded machine), and unwritten frames hold their steps' solutions.
  const std::size_t most_waiting = background ? 2 : 0;
  for (int k = 1; k <= steps; ++k) {
    start = cli::now();
    const double cpu_start = process_cpu();
    const bool solved_first = k == steps && last;  // for the pictures' camera, above
    auto step = solved_first ? std::move(last) : std::make_unique<CutSolution>(sweep_steps.solve(k));
    const double solved = solved_first ? last_solved : cli::now() - start;
    auto task = std::make_shared<std::unique_ptr<CutSolution>>(std::move(step));
    frames.push([&body, &problem, &files, k, task, solved] {
      return write_frame(body, problem, files, k, std::move(*task), solved);
    });
    while (frames.waiting() > most_waiting) frames.run_oldest_waiting();
    while (frames.ready()) finish(frames.take());
    if (k == steps)
      while (frames.size() > 0) finish(frames.take());
    wall[k - 1] = cli::now() - start;
    cpu[k - 1] = process_cpu() - cpu_start;
  }
  for (int k = 1; k <= steps; ++k) {
    report["steps"][k - 1]["step_seconds"] = wall[k - 1];
    report["steps"][k - 1]["step_cpu_seconds"] = cpu[k - 1];
  }
  if (!cutting.empty()) {  // the sweep's time split: per part, its median over the steps that cut
    std::vector<StepSplit> splits;
    std::vector<double> walls, cpus;
    for (const auto& [k, split] : cutting) {
      splits.push_back(split);
      walls.push_back(wall[k - 1]);
      cpus.push_back(cpu[k - 1]);
    }
    const double median_wall = median(walls);
    const StepSplit parts = median_split(splits);
    cli::info(describe_median_split(parts, static_cast<long>(splits.size()), median_wall));
    report["median_step"] = split_json(parts);
    report["median_step"]["steps"] = static_cast<long>(splits.size());
    report["median_step"]["wall_seconds"] = median_wall;
    report["median_step"]["cpu_seconds"] = median(cpus);
  }
  write_paraview_collection(collection, files.in_dir("sweep.pvd"));
  if (!o.report_path.empty()) write_json(report, o.report_path);
}

}  // namespace xfem
