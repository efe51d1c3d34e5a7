// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

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
  double back_substitution = 0;  ///< of `built`: the solve that completed the solution (complete_solution)
};

/// Where a step's time went, s, by part: classify, enrich (the DOF numbering and the check that
/// every piece is held), integrate (the element matrices computed anew), gather (which to compute,
/// and the enriched columns of K gathered from them), schur_update (incremental: the Schur
/// complement's new columns and its factor's update; the other solvers: forming S), solve (the
/// rest of the solution: the small solves with S's factor, the right-hand sides), back_substitution
/// (the solve with the uncut factor that completes the original DOFs' displacements: in the frame's
/// thread for xfem-sweep) and frame (building and writing it, without that solve).
struct StepSplit {
  double classify = 0, enrich = 0, integrate = 0, gather = 0, schur_update = 0, solve = 0, back_substitution = 0,
         frame = 0;
};
StepSplit step_split(const CutSolution& step, const StepTimes& times);
Json split_json(const StepSplit& split);

/// The median of each part over `splits` (the steps that cut something), and its line for the log.
StepSplit median_split(const std::vector<StepSplit>& splits);
std::string describe_median_split(const StepSplit& median, long steps, double median_wall);

/// xfem-sweep's progress line for step k of `steps` at time `t` (s): the cut's size, the enriched
/// DOFs and where the time went; `incremental`: solved by ProgressiveCut; `picture`: one was drawn.
std::string describe_step(const CutSolution& step, int k, int steps, double t, bool incremental, const StepTimes& times,
                          bool picture);

/// The report's row of step k (docs/FORMATS.md, xfem-sweep's report), without step_seconds (the
/// wall time, known only once the next step starts).
Json step_json(const CutSolution& step, int k, double t, bool incremental, const StepTimes& times);

}  // namespace xfem
