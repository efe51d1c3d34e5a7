// SPDX-License-Identifier: MIT
// Makes every input the pipelines need: structured and unstructured tet meshes, cut surfaces.
#include <vector>

#include "xfem/core/cli.h"
#include "xfem/generate/cut_commands.h"
#include "xfem/generate/mesh_commands.h"

int main(int argc, char** argv) {
  auto tool = xfem::cli::make_tool(
      "xfem-mesh", "Makes inputs: tetrahedral meshes (.vtu; also of segmented scans: xfem-mesh image), cut surfaces (.vtp) "
      "and synthetic label maps (.nrrd). Same arguments, same bytes.",
      "xfem-mesh unstructured-box --hi 0.03 0.06 0.2 --size 0.006 -o beam.vtu\n"
      "  xfem-mesh cut-rect --beam-cut -o cut.vtp\n  (xfem-mesh <command> --help for each command's options)");
  auto& app = tool->app;
  app.require_subcommand(1);
  std::vector<xfem::MeshCommand> commands = xfem::add_volume_mesh_commands(app);
  for (auto& c : xfem::add_cut_commands(app)) commands.push_back(std::move(c));
  xfem::cli::add_threads_option(*tool);
  return xfem::cli::run(*tool, argc, argv, [&] {
    for (const auto& c : commands)
      if (c.app->parsed()) c.run();
  });
}
