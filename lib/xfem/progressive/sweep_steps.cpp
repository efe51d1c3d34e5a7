// SPDX-License-Identifier: MIT
#include "xfem/progressive/sweep_steps.h"

#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/generate/cut_sweep.h"

namespace xfem {

SweepSteps::SweepSteps(const UncutBody& body, const TriangleMesh& sweep, const std::string& sweep_path,
                       std::vector<double> times, std::vector<double> t, const std::string& solver)
    : body_(body), sweep_(sweep), sweep_path_(sweep_path), times_(std::move(times)), t_(std::move(t)), solver_(solver) {}

long SweepSteps::prepare(const std::function<void(double)>& progress) {
  if (!incremental()) return 0;
  progressive_ = std::make_unique<ProgressiveCut>(body_);
  std::vector<std::shared_ptr<const CutSurface>> cuts;
  std::vector<std::vector<int>> ids;
  for (double tk : t_) {
    cuts.push_back(std::make_shared<const CutSurface>(cut_until(sweep_, times_, tk)));
    ids.push_back(cut_until_ids(times_, tk));
  }
  progressive_->prepare(cuts, progress, &ids);
  return progressive_->region_size();
}

CutSolution SweepSteps::solve(int k) {
  auto cut = std::make_shared<const CutSurface>(cut_until(sweep_, times_, t_[k - 1]));
  try {
    // The original DOFs' last solve is left to the frame, built off the steps' path.
    if (incremental()) {
      if (!progressive_) progressive_ = std::make_unique<ProgressiveCut>(body_);  // prepare() is optional
      return progressive_->step(cut, cut_until_ids(times_, t_[k - 1]), false);
    }
    return solve_cut(body_, cut, {},
                     solver_ == "schur"      ? CutSolver::Schur
                     : solver_ == "refactor" ? CutSolver::Refactor
                                             : CutSolver::Auto);
  } catch (const Error& e) {
    std::string m = e.what();
    if (m.rfind("cut: ", 0) == 0) m = m.substr(5);
    throw Error(sweep_path_ + ": step " + std::to_string(k) + " (t = " + cli::three_digits(t_[k - 1]) + " s): " + m);
  }
}

}  // namespace xfem
