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
  return xfem::cli::run(*tool, argc, argv, [&] {
    xfem::cli::check_output(output, {".vtu"});
    std::vector<std::string> warnings;
    xfem::TetMesh mesh = xfem::read_tet_mesh(input, &warnings);
    for (const auto& w : warnings) xfem::cli::warn(w);
    if (xfem::cut_count(mesh) > 1) {  // several cuts (docs/FORMATS.md "Several cuts")
      const xfem::DofNumbering d = xfem::number_several_cuts(mesh, input);
      xfem::write_tet_mesh(mesh, output);
      xfem::cli::info(std::to_string(xfem::cut_count(mesh)) + " cuts: NP " + std::to_string(d.np) + ", NS " +
                      std::to_string(d.ns) + " (sign and junction), NB " + std::to_string(d.nb) + ": N = " +
                      std::to_string(d.n) + " displacements, " + std::to_string(3 * d.n) + " unknowns");
      return;
    }
    const std::size_t V = mesh.points.rows(), T = mesh.tets.rows();
    auto ints = [](const xfem::DataArray& a) { return std::vector<int>(a.values.begin(), a.values.end()); };
    const auto& enrichment = xfem::require_array(mesh.point_data, "enrichment", "point", 1, V, input, "xfem-classify");
    const auto& cut_class = xfem::require_array(mesh.cell_data, "cut_class", "cell", 1, T, input, "xfem-classify");
    xfem::require_array(mesh.point_data, "side", "point", 1, V, input, "xfem-classify");
    const xfem::CrackFront front = xfem::read_front(mesh, input);
    xfem::DofNumbering d;
    try {
      d = xfem::dof_numbering(mesh.tets, static_cast<long>(V), ints(enrichment), ints(cut_class));
    } catch (const xfem::Error& e) {
      throw xfem::Error(input + ": " + e.what());
    }
    if (d.nb > 0 && front.empty())
      throw xfem::Error(input + ": " + std::to_string(d.nb) + " branch nodes but field array 'front_segments' is empty");
    xfem::store_dof_numbering(d, mesh);
    xfem::write_tet_mesh(mesh, output);
    xfem::cli::info("NP " + std::to_string(d.np) + ", NS " + std::to_string(d.ns) + ", NB " + std::to_string(d.nb) +
                    ": N = " + std::to_string(d.n) + " displacements, " + std::to_string(3 * d.n) + " unknowns");
  });
}
