// SPDX-License-Identifier: MIT
#pragma once
#include <memory>
#include <string>

#include "xfem/core/fingerprint.h"
#include "xfem/io/snapshot.h"
#include "xfem/io/vtk_io.h"
#include "xfem/post/deformed_mesh.h"
#include "xfem/progressive/progressive_cut.h"
#include "xfem/progressive/sweep_report.h"
#include "xfem/system/problem.h"

namespace xfem {

/// A sweep's step as a frame: the body split along the step's cut and deformed by its solution
/// (`step.u` complete: complete_solution), as xfem-visualize's deformed.vtu and wound.vtp.
DeformedBody sweep_frame(const CutSolution& step, const Problem& problem);

/// The name of step k's file in a sweep's directory: `stem`, k on three digits, `extension`
/// ("step_" 7 ".vtu": "step_007.vtu").
std::string numbered(const std::string& stem, int k, const std::string& extension);

/// The pictures of a sweep, one camera, framing and colour range for all: those of `frame` (the
/// last step's, the largest cut), its displacement magnified `scale` times, `width` x `height`
/// pixels, no element edges (Auto would switch them off as the cut adds faces).
SnapshotOptions sweep_pictures(const DeformedBody& frame, double scale, int width, int height);

/// What a sweep writes of each step, where: DIR/step_NNN.vtu and DIR/step_NNN_wound.vtp
/// compressed with `packing`; with `solutions` DIR/u_NNN.mtx (with the fingerprints of the body,
/// the step's cut and the problem, as xfem-solve's u.mtx); with `cuts` DIR/cut_NNN.vtp.
struct FrameFiles {
  std::string dir;
  Compression packing = Compression::LZ4;
  bool solutions = false, cuts = false;
  Fingerprint body = 0, problem = 0;

  /// DIR/name.
  std::string in_dir(const std::string& name) const;
};

/// Step k's frame, written: the step (its solution complete), the deformed body (for its picture)
/// and the times of its solution, its frame built and written.
struct WrittenFrame {
  int k = 0;
  std::unique_ptr<CutSolution> step;
  DeformedBody frame;
  StepTimes times;
};

/// Completes step k's solution (complete_solution), builds its frame (sweep_frame) and writes
/// `files`; `solved`: the step's solution time, s. What xfem-visualize does for one cut.
WrittenFrame write_frame(const UncutBody& body, const Problem& problem, const FrameFiles& files, int k,
                         std::unique_ptr<CutSolution> step, double solved);

}  // namespace xfem
