// SPDX-License-Identifier: MIT
// Progressive cutting (issue 20): a blade's sweep as a time series, the uncut body factorized once
// and each step solved on the enriched DOFs alone (DESIGN.md, "Cutting does not touch the
// standard block").
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "xfem/core/background_queue.h"
#include "xfem/core/blas_threads.h"
#include "xfem/core/cli.h"
#include "xfem/geometry/cut_surface.h"
#include "xfem/generate/cut_sweep.h"
#include "xfem/post/deformed_mesh.h"
#include "xfem/geometry/element_split.h"
#include "xfem/core/error.h"
#include "xfem/core/fingerprint.h"
#include "xfem/io/matrix_market.h"
#include "xfem/io/paraview_collection.h"
#include "xfem/system/problem.h"
#include "xfem/progressive/progressive_cut.h"
#include "xfem/io/snapshot.h"
#include "xfem/core/version.h"
#include "xfem/io/vtk_io.h"

namespace {
std::string g(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}
std::string numbered(const std::string& stem, int k, const std::string& ext) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%03d", k);
  return stem + buf + ext;
}
}  // namespace

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

    double start = xfem::cli::now();
    const xfem::UncutBody body = xfem::factorize_uncut(mesh, problem, ordering == "amd" ? xfem::Ordering::Amd
                                                                                         : xfem::Ordering::Metis);
    const double setup = xfem::cli::now() - start;
    xfem::cli::info("uncut body: " + std::to_string(body.free_dofs.size()) + " free DOFs, assembled in " +
                    g(body.assemble_seconds) + " s, factorized once (CHOLMOD, " + body.factor->ordering + ", " +
                    std::to_string(static_cast<long>(body.factor->factor_nonzeros)) + " non-zeros in L) in " +
                    g(body.factor->analyze_seconds + body.factor->factor_seconds) + " s");
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
    report["factorization"] = {{"free_dofs", static_cast<long>(body.free_dofs.size())},
                               {"ordering", body.factor->ordering},
                               {"factor_nonzeros", static_cast<long>(body.factor->factor_nonzeros)},
                               {"assemble_seconds", body.assemble_seconds},
                               {"analyze_seconds", body.factor->analyze_seconds},
                               {"factor_seconds", body.factor->factor_seconds},
                               {"solve_seconds", body.solve_seconds},
                               {"seconds", setup}};
    // Incremental: the body's response on the DOFs the whole sweep touches, once.
    std::unique_ptr<xfem::ProgressiveCut> progressive;
    double region_seconds = 0;
    if (solver == "incremental") {
      start = xfem::cli::now();
      progressive = std::make_unique<xfem::ProgressiveCut>(body);
      std::vector<std::shared_ptr<const xfem::CutSurface>> cuts;
      for (double tk : t) cuts.push_back(std::make_shared<const xfem::CutSurface>(xfem::cut_until(sweep, times, tk)));
      progressive->prepare(cuts, xfem::cli::progress("the body's response on the sweep's region"));
      region_seconds = xfem::cli::now() - start;
      xfem::cli::info("the uncut body's response on the " + std::to_string(progressive->region_size()) +
                      " free DOFs the sweep touches: " + g(region_seconds) + " s (once)");
    }
    report["factorization"]["region_dofs"] = progressive ? progressive->region_size() : 0L;
    report["factorization"]["region_seconds"] = region_seconds;
    report["steps"] = xfem::Json::array();
    std::vector<xfem::CollectionEntry> collection;
    const auto solve_step = [&](int k) {
      auto cut = std::make_shared<const xfem::CutSurface>(xfem::cut_until(sweep, times, t[k - 1]));
      try {
        // The original DOFs' last solve is left to the frame, built off the steps' path (below).
        if (progressive) return progressive->step(cut, xfem::cut_until_ids(times, t[k - 1]), false);
        return xfem::solve_cut(body, cut, {},
                               solver == "schur"      ? xfem::CutSolver::Schur
                               : solver == "refactor" ? xfem::CutSolver::Refactor
                                                      : xfem::CutSolver::Auto);
      } catch (const xfem::Error& e) {
        std::string m = e.what();
        if (m.rfind("cut: ", 0) == 0) m = m.substr(5);
        throw xfem::Error(cut_path + ": step " + std::to_string(k) + " (t = " + g(t[k - 1]) + " s): " + m);
      }
    };
    const auto make_frame = [&](const xfem::CutSolution& step) {
      const xfem::EnrichedMesh& em = step.em;
      const xfem::SplitMesh split = em.cut ? xfem::split_mesh(em.mesh, em.side, em.cut_class, *em.cut, em.front.segments())
                                           : xfem::unsplit_mesh(em.mesh, em.side);
      return xfem::deformed_body(split, em.cut_class, xfem::xfem_displacement(em, step.u), problem.E, problem.nu);
    };
    // Pictures: the camera, framing and colour range of the last step (the largest cut), for all.
    xfem::SnapshotOptions picture;
    std::unique_ptr<xfem::CutSolution> last;
    double last_solved = 0;
    if (png) {
      start = xfem::cli::now();
      last = std::make_unique<xfem::CutSolution>(solve_step(steps));
      xfem::complete_solution(body, *last);
      last_solved = xfem::cli::now() - start;
      const xfem::DeformedBody frame = make_frame(*last);
      // The incremental solver's step K follows step K - 1 like every other step: solve it again there.
      if (progressive) last.reset();
      report["factorization"]["picture_setup_seconds"] = xfem::cli::now() - start;
      picture.view = xfem::cut_view(frame.wound);
      picture.colour_max = xfem::colour_top(frame.volume);
      const auto& u = frame.volume.point_data.at("displacement");
      std::array<double, 6> box{1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
      for (Eigen::Index p = 0; p < frame.volume.points.rows(); ++p)
        for (int i = 0; i < 3; ++i) {
          const double x = frame.volume.points(p, i) + scale * u(static_cast<std::size_t>(p), i);
          box[2 * i] = std::min(box[2 * i], x);
          box[2 * i + 1] = std::max(box[2 * i + 1], x);
        }
      picture.frame = box;
      picture.scale = scale;
      picture.width = width;
      picture.height = height;
      picture.edges = xfem::SnapshotOptions::Edges::Off;  // Auto would switch them off as the cut adds faces
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
      double solved = 0, built = 0, written = 0;  // s
    };
    const auto write_frame = [&](int k, std::unique_ptr<xfem::CutSolution> step, double solved) {
      Framed out;
      const double begin = xfem::cli::now();
      const xfem::EnrichedMesh& em = step->em;
      xfem::complete_solution(body, *step);
      out.frame = make_frame(*step);
      out.built = xfem::cli::now() - begin;
      xfem::write_tet_mesh(out.frame.volume, (std::filesystem::path(dir) / numbered("step_", k, ".vtu")).string(), packing);
      xfem::write_triangle_mesh(out.frame.wound, (std::filesystem::path(dir) / numbered("step_", k, "_wound.vtp")).string(),
                                packing);
      out.written = xfem::cli::now() - begin;  // what xfem-visualize does
      if (solutions) {  // with the fingerprints xfem-solve writes, so xfem-visualize/-rmserror can check a frame's inputs
        xfem::Provenance made_for{{"enriched", body_fingerprint}, {"problem", problem_fingerprint}};
        if (em.cut) made_for["cut"] = xfem::fingerprint(em.cut->mesh());
        xfem::write_vector(step->u, (std::filesystem::path(dir) / numbered("u_", k, ".mtx")).string(),
                           xfem::provenance_comments(made_for));
      }
      if (cuts && em.cut) xfem::write_triangle_mesh(em.cut->mesh(), (std::filesystem::path(dir) / numbered("cut_", k, ".vtp")).string());
      out.k = k;
      out.step = std::move(step);
      out.solved = solved;
      return out;
    };
    // A written frame, in the main thread: its picture, its entries in the collection, the progress
    // line and the report's row (its step_seconds filled in at the end).
    const auto finish = [&](const Framed& f) {
      const int k = f.k;
      const xfem::CutSolution& step = *f.step;
      const xfem::EnrichedMesh& em = step.em;
      const double picture_start = xfem::cli::now();
      if (png) {
        picture.title = "t = " + g(t[k - 1]) + " s (step " + std::to_string(k) + " of " + std::to_string(steps) + ")";
        xfem::write_snapshot(f.frame.volume, f.frame.wound,
                             (std::filesystem::path(dir) / numbered("step_", k, ".png")).string(), picture);
      }
      const double pictured = png ? xfem::cli::now() - picture_start : 0.0;
      collection.push_back({t[k - 1], 0, numbered("step_", k, ".vtu")});
      collection.push_back({t[k - 1], 1, numbered("step_", k, "_wound.vtp")});
      const long triangles = em.cut ? static_cast<long>(em.cut->mesh().triangles.rows()) : 0;
      xfem::cli::info("step " + std::to_string(k) + "/" + std::to_string(steps) + ", t = " + g(t[k - 1]) + " s: " +
                      std::to_string(triangles) + " cut triangles, " +
                      std::to_string(step.counts.partial + step.counts.complete) + " cut tets, " +
                      std::to_string(step.enriched_dofs) + " enriched DOFs; solved in " + g(f.solved) +
                      " s (classify " + g(step.classify_seconds) + ", assemble " + g(step.assemble_seconds) +
                      (progressive ? ", incremental Schur " : step.schur_used ? ", Schur " : ", refactorization ") +
                      g(step.solve_seconds) + "), frame written in " + g(f.written) + " s" +
                      (png ? ", picture in " + g(pictured) + " s" : ""));
      report["steps"].push_back({{"step", k},
                                 {"time", t[k - 1]},
                                 {"cut_triangles", triangles},
                                 {"partial", step.counts.partial},
                                 {"complete", step.counts.complete},
                                 {"sign", step.counts.sign},
                                 {"branch", step.counts.branch},
                                 {"n", em.n},
                                 {"dofs", 3 * em.n},
                                 {"enriched_dofs", step.enriched_dofs},
                                 {"unsupported_dofs", step.unsupported_dofs},
                                 {"enriched_tets", step.enriched_tets},
                                 {"classify_seconds", step.classify_seconds},
                                 {"assemble_seconds", step.assemble_seconds},
                                 {"solver", progressive ? "incremental" : step.schur_used ? "schur" : "refactor"},
                                 {"recomputed_tets", step.recomputed_tets},
                                 {"keys_seconds", step.keys_seconds},
                                 {"elements_seconds", step.elements_seconds},
                                 {"kept_dofs", step.incremental.kept},
                                 {"added_dofs", step.incremental.added},
                                 {"refactored_rows", step.incremental.refactored},
                                 {"region_added", step.incremental.region_added},
                                 {"schur_seconds", step.schur.schur_seconds},
                                 {"dense_seconds", step.schur.dense_seconds},
                                 {"solve_seconds", step.solve_seconds},
                                 {"seconds", f.solved},
                                 {"frame_seconds", f.written},
                                 {"frame_build_seconds", f.built},
                                 {"schur_columns_seconds", step.incremental.columns_seconds},
                                 {"schur_factor_seconds", step.incremental.factor_seconds},
                                 {"picture_seconds", pictured}});
      if (step.unsupported_dofs > 0)
        xfem::cli::detail(std::to_string(step.unsupported_dofs) + " enriched DOFs without support fixed to 0");
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
      auto step = solved_first ? std::move(last) : std::make_unique<xfem::CutSolution>(solve_step(k));
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
    xfem::write_paraview_collection(collection, (std::filesystem::path(dir) / "sweep.pvd").string());
    if (!report_path.empty()) xfem::write_json(report, report_path);
  });
}
