// SPDX-License-Identifier: MIT
#pragma once
#include <string>

#include "xfem/io/snapshot.h"

namespace xfem {

/// Writes (atomically) a ParaView Python script `path` that opens `deformed` (deformed.vtu) and
/// `wound` (wound.vtp; may be empty: not shown), warps both by `displacement` x `scale`, colours
/// the body by cell `von_mises` with ParaView's "Viridis (matplotlib)" preset over [0, `top`] Pa
/// (the picture's range, colour_top) and the wound red, clips an interior cut like the picture and
/// sets the picture's camera (`view`). Paths are written relative to the script's directory, so
/// the folder can be moved. Run with `paraview --script=FILE` or `pvpython FILE`. Deterministic.
void write_paraview_script(const std::string& path, const std::string& deformed, const std::string& wound,
                           const CutView& view, double top, double scale);

}  // namespace xfem
