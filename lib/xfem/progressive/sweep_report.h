// SPDX-License-Identifier: MIT
#pragma once
#include <string>

#include "xfem/core/json_io.h"
#include "xfem/progressive/progressive_cut.h"

namespace xfem {

/// xfem-sweep's line on the uncut body: its free DOFs, assembly and factorization.
std::string describe_uncut_body(const UncutBody& body);

/// The report's "factorization" object: the uncut body's free DOFs, ordering, factor size and
/// timings; `seconds` the whole set-up's wall time.
Json factorization_json(const UncutBody& body, double seconds);

/// Wall times of a sweep's step, s: its solution, its frame built (deformed body) and written
/// (with the files), its picture.
struct StepTimes {
  double solved = 0, built = 0, written = 0, pictured = 0;
};

/// xfem-sweep's progress line for step k of `steps` at time `t` (s): the cut's size, the enriched
/// DOFs and where the time went; `incremental`: solved by ProgressiveCut; `picture`: one was drawn.
std::string describe_step(const CutSolution& step, int k, int steps, double t, bool incremental, const StepTimes& times,
                          bool picture);

/// The report's row of step k (docs/FORMATS.md, xfem-sweep's report), without step_seconds (the
/// wall time, known only once the next step starts).
Json step_json(const CutSolution& step, int k, double t, bool incremental, const StepTimes& times);

}  // namespace xfem
