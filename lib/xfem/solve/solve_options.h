// SPDX-License-Identifier: MIT
#pragma once
#include <string>

#include "xfem/core/cli.h"
#include "xfem/solve/contact_solve.h"

namespace xfem {

/// xfem-solve's command line (README, --help): what to solve, where to write, which backend.
struct SolveOptions {
  std::string dir, output, report_path, reactions_path, contact_pressure_path;
  std::string backend = "auto", ordering = "metis", near_null = "rigid", enriched_block = "auto";
  double rtol = 1e-10, drop_tol = 0;
  int max_iterations = 10000, processes = 0;
  ContactIteration contact;
};

/// Declares every option of xfem-solve on `app`, filling `o`.
void add_solve_options(CLI::App& app, SolveOptions& o);

/// Checks the output paths (cli::check_output) and refuses what the system cannot do with them:
/// --contact-pressure for a system without a contact operator ("<dir>: ..."). Returns whether the
/// system holds a contact operator (iterated on either backend).
bool check_solve_options(SolveOptions& o);

}  // namespace xfem
