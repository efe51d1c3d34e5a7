// SPDX-License-Identifier: MIT
// The deformed body with the cut opened (paper 4.1): split mesh, wound surface, optional PNG.
#include <string>

#include "xfem/core/cli.h"
#include "xfem/core/regions.h"
#include "xfem/post/deformed_mesh.h"
#include "xfem/post/deformed_volume.h"
#include "xfem/post/solution_provenance_check.h"
#include "xfem/post/visualize_options.h"
#include "xfem/post/visualize_outputs.h"
#include "xfem/geometry/element_split.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/core/error.h"
#include "xfem/core/fingerprint.h"
#include "xfem/io/matrix_market.h"
#include "xfem/io/paraview_script.h"
#include "xfem/system/problem.h"
#include "xfem/post/split_enriched_mesh.h"
#include "xfem/system/reactions.h"
#include "xfem/io/snapshot.h"
#include "xfem/io/vtk_io.h"

int main(int argc, char** argv) {
  auto tool = xfem::cli::make_tool(
      "xfem-visualize",
      "Write the deformed body with the cut opened: every cut element split along the cut into its\n"
      "parts above and below (ahead of the cut front it stays joined), each part moved by the X-FEM\n"
      "displacement of its own side; with strain, stress (Pa; Cauchy for a material.model other than linear) and\n"
      "von Mises stress (Pa) per cell (docs/FORMATS.md: deformed.vtu, wound.vtp, PNG snapshot). Positions are undeformed (m): apply\n"
      "ParaView's Warp By Vector with 'displacement' (m) to see the deformation. Without --cut the mesh\n"
      "is shown as it is (plain CG-FEM meshes, doubled nodes included).",
      "xvfb-run -a xfem-visualize enriched.vtu --cut cut.vtp --solution u.mtx --problem problem.json \\\n"
      "      -o deformed.vtu --faces wound.vtp --png beam.png --scale 2 --reactions r.mtx --paraview deformed.py");
  xfem::VisualizeOptions o;
  xfem::add_visualize_options(tool->app, o);
  xfem::cli::add_threads_option(*tool);
  return xfem::cli::run(*tool, argc, argv, [&] {
    xfem::check_visualize_outputs(o);
    const xfem::Problem problem = xfem::read_problem(o.problem_path);
    std::vector<std::string> warnings;
    const xfem::EnrichedMesh em = xfem::read_enriched_mesh_cuts(o.input, o.cut_paths, &warnings);
    const std::string cut_path = o.cut_paths.empty() ? std::string() : o.cut_paths[0];
    for (const auto& w : warnings) xfem::cli::warn(w);
    if (cut_path.empty() && em.n > em.np)
      throw xfem::Error(o.input + ": " + std::to_string(em.n - em.np) +
                        " enriched displacements (NS + 4 NB > 0) need the cut surface: give --cut");
    const Eigen::VectorXd u = xfem::read_vector(o.solution);
    if (u.size() != 3 * em.n)
      throw xfem::Error(o.solution + ": " + std::to_string(u.size()) + " values, expected 3N = " +
                        std::to_string(3 * em.n) + " for " + o.input);
    Eigen::VectorXd reactions;
    if (!o.reactions_path.empty()) {
      reactions = xfem::read_vector(o.reactions_path);
      if (reactions.size() != 3 * em.n)
        throw xfem::Error(o.reactions_path + ": " + std::to_string(reactions.size()) + " values, expected 3N = " +
                          std::to_string(3 * em.n) + " for " + o.input);
    }
    xfem::check_solution_provenance({o.solution, o.input, o.cut_paths, o.problem_path}, em);

    const xfem::SplitMesh split = xfem::split_mesh(em);
    xfem::cli::info(std::to_string(split.split_complete) + " elements split through, " +
                    std::to_string(split.split_partial) + " split behind the front: " +
                    std::to_string(split.tets.rows()) + " tets, " + std::to_string(split.points.rows()) + " points, " +
                    std::to_string(split.wound.rows() / 2) + " wound triangles per side");
    if (split.degenerate_faces > 0)
      xfem::cli::warn(std::to_string(split.degenerate_faces) + " faces with one split edge but no front point: "
                      "split at that edge only (the cut grazes a node or the front misses the face)");
    const xfem::TetMaterials materials = xfem::tet_materials(problem, em.mesh, o.input);
    xfem::DeformedBody body = xfem::deformed_body(split, em.cut_class, xfem::xfem_displacement(em, u), materials,
                                                  xfem::cli::progress("evaluating"), o.wound_offset);
    xfem::inherit_regions(em.mesh, split.parent, body.volume);  // each cell's tissue, for ParaView
    const xfem::DeformedVolume volume = xfem::deformed_volume(body.volume, body.det_F);
    xfem::cli::info(xfem::describe(volume));
    if (const std::string w = xfem::inverted_warning(volume, problem.model); !w.empty()) xfem::cli::warn(w);
    if (!o.reactions_path.empty()) body.volume.point_data["reaction"] = xfem::reaction_array(reactions, em.np, split.points.rows());
    xfem::report_cut_opening(em, split, body);
    if (!o.contact_pressure.empty()) xfem::add_contact_pressure(o.contact_pressure, em, split, body);
    xfem::CutView camera;
    const xfem::SnapshotOptions options = xfem::snapshot_options(o, problem, body.wound, camera);
    if (!o.png.empty()) xfem::write_snapshot(body.volume, body.wound, o.png, options);
    xfem::write_visualize_outputs(body, o.output, o.faces, xfem::compression_named(o.compression),
                                  xfem::visualize_inputs_fingerprint(em, u, o.problem_path, o.wound_offset,
                                                                     xfem::wound_pressure_values(body)));
    if (!o.script.empty())
      xfem::write_paraview_script(o.script, o.output, o.faces, camera, xfem::colour_top(body.volume), o.scale);
  });
}
