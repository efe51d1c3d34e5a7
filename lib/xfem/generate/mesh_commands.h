// SPDX-License-Identifier: MIT
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace xfem {

/// One of xfem-mesh's commands: its subcommand, with its options, and what it does once parsed
/// (checks the output and the cost, makes the mesh or cut, writes it and says so).
struct MeshCommand {
  CLI::App* app = nullptr;
  std::function<void()> run;
};

/// The options every xfem-mesh command has: -o/--output and --allow-large.
struct MeshCommandOutput {
  std::string path;
  bool allow_large = false;
};

/// Adds the subcommand `name` (`what`; "Example:\n  xfem-mesh <example>" as its footer) to `app`,
/// with -o/--output and --allow-large bound to `output`.
CLI::App* add_mesh_command(CLI::App& app, const char* name, const char* what, const char* example,
                           MeshCommandOutput& output);

/// xfem-mesh's tetrahedral meshes (.vtu), in this order: box, unstructured-box, organ, surface, and
/// the label-map commands image and phantom-image (image_commands.h).
std::vector<MeshCommand> add_volume_mesh_commands(CLI::App& app);

}  // namespace xfem
