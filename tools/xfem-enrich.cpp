// SPDX-License-Identifier: MIT
// Numbers the DOFs of a classified mesh and builds each element's extended connectivity (paper 3.3).
#include <string>

#include "xfem/core/cli.h"
#include "xfem/geometry/crack_front.h"
#include "xfem/enrich/dof_numbering.h"
#include "xfem/core/error.h"
#include "xfem/enrich/classification_several_cuts.h"
#include "xfem/io/vtk_io.h"

int main(int argc, char** argv) {
  auto tool = xfem::cli::make_tool(
      "xfem-enrich",
      "Number the displacements of a classified mesh as the paper does (originals 0..NP-1, sign\n"
      "NP..NP+NS-1, branch NP+NS..N-1, 4 per branch node) and store every element's extended\n"
      "connectivity C and local ids L (docs/FORMATS.md, enriched.vtu). A mesh classified with several\n"
      "cuts is numbered cut after cut: the sign DOFs of cut 0, 1, ..., the junction (product) DOFs, then\n"
      "the branch DOFs of cut 0, 1, ... (docs/FORMATS.md \"Several cuts\").",
      "xfem-enrich classified.vtu -o enriched.vtu");
  std::string input, output, cut_path;
  auto& app = tool->app;
  app.add_option("classified", input, "xfem-classify output (.vtu)")->required();
  app.add_option("-o,--output", output, "enriched mesh (.vtu)")->required();
  app.add_option("-c,--cut", cut_path, "accepted for symmetry with the later stages and ignored: the numbering needs "
                                       "only the classification");
  xfem::cli::add_threads_option(*tool);
  return xfem::cli::run(*tool, argc, argv, [&] {
    xfem::cli::check_output(output, {".vtu"});
    std::vector<std::string> warnings;
    xfem::TetMesh mesh = xfem::read_tet_mesh(input, &warnings);
    for (const auto& w : warnings) xfem::cli::warn(w);
    const xfem::DofNumbering d = xfem::number_classified_mesh(mesh, input);
    xfem::write_tet_mesh(mesh, output);
    const int cuts = xfem::cut_count(mesh);
    xfem::cli::info((cuts > 1 ? std::to_string(cuts) + " cuts: " : std::string()) + "NP " + std::to_string(d.np) +
                    ", NS " + std::to_string(d.ns) + (cuts > 1 ? " (sign and junction)" : "") + ", NB " +
                    std::to_string(d.nb) + ": N = " + std::to_string(d.n) + " displacements, " +
                    std::to_string(3 * d.n) + " unknowns");
  });
}
