// SPDX-License-Identifier: MIT
#pragma once
#include <CLI/CLI.hpp>
#include <vector>

#include "xfem/generate/mesh_commands.h"

namespace xfem {

/// xfem-mesh's cut surfaces (.vtp, or .vtu), in this order: cut-rect, cut-sine, cut-disc,
/// cut-zigzag, cut-merge, cut-sweep.
std::vector<MeshCommand> add_cut_commands(CLI::App& app);

}  // namespace xfem
