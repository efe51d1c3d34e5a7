// SPDX-License-Identifier: MIT
#pragma once
#include <string>

namespace xfem {

/// xfem-sweep's options (its --help says what each is).
struct SweepOptions {
  std::string body_path, cut_path, problem_path, dir, report_path, ordering = "metis", solver = "incremental",
                                                                   backend = "cholmod", compression = "lz4";
  int steps = 0, width = 1200, height = 900;
  double scale = 1.0;
  bool solutions = false, cuts = false, png = false;
  bool allow_large = false;  ///< run even with more than kMaxSweepSteps steps
};

/// xfem-sweep's cost guard (the model of xfem-mesh's, generation_limits.h): each step is a solve
/// and two frame files (more with --png, --solutions, --cuts), so more steps than this (hours,
/// hundreds of thousands of files) are refused before any work unless --allow-large.
constexpr int kMaxSweepSteps = 1000;

/// xfem-sweep: checks the options, reads the body, the sweep and the problem, factorizes the
/// uncut body once, solves the K steps (SweepSteps) and writes their frames (write_frame, in the
/// background while the next steps are solved), DIR/sweep.pvd and the report; progress on stderr
/// (cli::info). Throws xfem::Error for bad options or inputs.
void run_sweep(const SweepOptions& options);

}  // namespace xfem
