// SPDX-License-Identifier: MIT
#pragma once
#include <CLI/CLI.hpp>
#include <vector>

#include "xfem/generate/mesh_commands.h"

namespace xfem {

/// xfem-mesh's label-map commands: `image` (a tet mesh of a segmented scan, one region per label)
/// and `phantom-image` (a synthetic label map in NRRD for tests and examples).
std::vector<MeshCommand> add_image_commands(CLI::App& app);

}  // namespace xfem
