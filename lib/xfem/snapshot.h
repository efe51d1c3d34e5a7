// SPDX-License-Identifier: MIT
#pragma once
#include <string>

#include "xfem/mesh.h"

namespace xfem {

/// How write_snapshot draws the deformed body (docs/FORMATS.md, "PNG snapshot").
struct SnapshotOptions {
  double scale = 1.0;     ///< displacement magnification (1 = true deformation)
  int width = 1200;       ///< pixels
  int height = 900;       ///< pixels
  std::string title;      ///< first line of the caption (e.g. the file name); may be empty
  bool edges = true;      ///< draw the surface's element edges (thin, dark)
};

/// Renders `deformed` (an output of deformed_body: point array `displacement`, cell array
/// `von_mises`) to a PNG with VTK offscreen rendering: the outer surface of the split mesh (so the
/// opened cut shows as a gap) at x + scale * u, coloured by von Mises stress (blue 0 to red at the
/// 95th percentile of the cells' values, so the singular peak at the cut front does not wash the
/// picture out), thin dark element edges (unless `edges` is false), a colour bar and a caption with the scale. The camera is
/// fixed: parallel projection looking at the centre of the deformed bounding box from the
/// direction (-1, -1, 1) (isometric: the faces x = min, y = min and z = max face the viewer), z up, scaled so that
/// the box's corners fit with a 5 % margin. Needs an X display (run under `xvfb-run -a`): throws xfem::Error when DISPLAY is
/// unset, or when the arrays are missing. Pixels may differ between GPUs and drivers.
void write_snapshot(const TetMesh& deformed, const std::string& png, const SnapshotOptions& options);

}  // namespace xfem
