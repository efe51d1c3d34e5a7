// SPDX-License-Identifier: MIT
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "xfem/core/mesh.h"
#include "xfem/progressive/progressive_cut.h"

namespace xfem {

/// The steps of a blade's sweep (xfem-sweep): step k's cut is the sweep's triangles made by time
/// t[k - 1] (cut_until), solved on the factorized uncut body.
class SweepSteps {
 public:
  /// `times`: the sweep's triangles' times (cut_times); `t`: the steps' times (step_times);
  /// `solver`: "incremental" (ProgressiveCut, the Schur complement kept from step to step) or
  /// solve_cut's "schur", "refactor" or "auto" anew each step; `sweep_path` names the sweep in
  /// errors. Keeps references to `body` and `sweep`.
  SweepSteps(const UncutBody& body, const TriangleMesh& sweep, const std::string& sweep_path, std::vector<double> times,
             std::vector<double> t, const std::string& solver);

  bool incremental() const { return solver_ == "incremental"; }
  int steps() const { return static_cast<int>(t_.size()); }
  double time(int k) const { return t_[k - 1]; }

  /// Incremental: the body's response on the DOFs the whole sweep touches, once
  /// (ProgressiveCut::prepare); returns their number. Nothing, and 0, for the other solvers.
  long prepare(const std::function<void(double)>& progress);

  /// Solves step k (1..K); the steps of the incremental solver in order, each once. The
  /// incremental solver leaves the original DOFs' last solve to complete_solution (the frame,
  /// built off the steps' path, does it). Throws xfem::Error "<sweep>: step k (t = T s): <why>".
  CutSolution solve(int k);

 private:
  const UncutBody& body_;
  const TriangleMesh& sweep_;
  std::string sweep_path_;
  std::vector<double> times_, t_;
  std::string solver_;
  std::unique_ptr<ProgressiveCut> progressive_;
};

}  // namespace xfem
