// SPDX-License-Identifier: MIT
#pragma once
#include <string>

#include "xfem/system/problem.h"

namespace xfem {

/// How the tets with enriched DOFs are to be integrated, as xfem-assemble's command line asks on
/// top of problem.json's `integration` (docs/FORMATS.md): empty / 0 / -1 = not given.
struct IntegrationRequest {
  std::string rule;  ///< "oversampling", "conforming", "graded", "pieces", "uniform", "fast" or empty
  int points = 0;    ///< oversampling points per enriched tet (> 0: implies oversampling)
  int refine = -1;   ///< oversampling refinement levels at the cut (>= 0: implies oversampling)
  int order = 0;     ///< conforming rule's order (> 0)
};

/// Applies `request` to `problem` (rule, closed_form, graded, order: a given rule wins, else
/// --points / --refine imply the oversampling rule) and fills the request's points and refine from
/// problem.json where the command line gave none (problem.points, problem.refine).
void apply_integration_request(IntegrationRequest& request, Problem& problem);

/// The rule in the command line's words, for the log: "--rule conforming --order 3",
/// "--rule graded", "--rule fast", "--points 30, --refine 0", ...
std::string describe_integration(const Problem& problem, int points, int refine);

}  // namespace xfem
