// SPDX-License-Identifier: MIT
#pragma once
#include <string>

#include "xfem/io/snapshot.h"
#include "xfem/post/deformed_mesh.h"
#include "xfem/progressive/progressive_cut.h"
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

}  // namespace xfem
