// SPDX-License-Identifier: MIT
// The deformed body with the cut opened (paper 4.1): split mesh, wound surface, optional PNG.
#include <cstdlib>
#include <string>

#include "xfem/core/cli.h"
#include "xfem/core/regions.h"
#include "xfem/post/deformed_mesh.h"
#include "xfem/post/deformed_volume.h"
#include "xfem/post/solution_provenance_check.h"
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
  std::string input, solution, problem_path, output, faces, png, title, reactions_path, script, edges = "auto",
              compression = "zlib";
  double scale = 1.0;
  int width = 1200, height = 900;
  auto& app = tool->app;
  app.add_option("enriched", input, "xfem-enrich output (.vtu)")->required();
  std::vector<std::string> cut_paths;
  app.add_option("-c,--cut", cut_paths, "the cut surface the mesh was classified with (.vtp/.vtu/.vtk/.stl/.obj/.off/.msh); "
                                        "omit for a mesh without enriched DOFs; several cuts: once per cut, as given "
                                        "to xfem-classify")
      ->allow_extra_args(false);
  app.add_option("-s,--solution", solution, "xfem-solve output: Matrix Market vector of 3N values, m")->required();
  app.add_option("-p,--problem", problem_path, "problem.json (material, materials per region: stresses)")->required();
  app.add_option("-o,--output", output, "deformed split mesh (.vtu)")->required();
  app.add_option("-f,--faces", faces, "also write both faces of the cut inside the body (.vtp, or .vtu: a grid of triangles)");
  app.add_option("--reactions", reactions_path, "xfem-solve --reactions output (3N x 1, N): written as the point "
                                                "array 'reaction' of the output");
  app.add_option("--png", png, "also render a picture (needs an X display: run under xvfb-run -a)");
  app.add_option("--paraview", script, "also write a ParaView Python script (.py) that opens the output warped by "
                                       "--scale and coloured like the picture (paraview --script=FILE)");
  app.add_option("--scale", scale, "displacement magnification in the picture and script only, dimensionless "
                                   "(files keep the true displacement)")->check(xfem::cli::range(1e-6, 1e6));
  std::vector<double> view;
  app.add_option("--view", view, "direction from the body towards the eye (3 numbers, any length) for the picture and "
                                 "script, instead of the one chosen from the cut (docs/FORMATS.md \"PNG snapshot\")")
      ->expected(3);
  app.add_option("--width", width, "picture width, pixels")->check(xfem::cli::range(64, 8192));
  app.add_option("--height", height, "picture height, pixels")->check(xfem::cli::range(64, 8192));
  app.add_option("--edges", edges, "element edges in the picture: auto (light grey below 20,000 visible faces, "
                                   "default), on or off")->check(CLI::IsMember({"auto", "on", "off"}));
  double wound_offset = 1e-4;
  app.add_option("--wound-offset", wound_offset, "move the wound (--faces) this fraction of the body's diagonal out of "
                                                 "its pieces so that it does not z-fight with the cut faces of the "
                                                 "output (dimensionless, default 1e-4; 0 keeps the cut's exact geometry)")
      ->check(xfem::cli::range(0.0, 0.1));
  bool no_edges = false;
  app.add_flag("--no-edges", no_edges, "same as --edges off");
  app.add_option("--compression", compression,
                 "compression of the .vtu/.vtp written: zlib (level 1, default: read by every VTK XML reader, "
                 "meshio included), lz4 (VTK's LZ4 compressor: ~10x faster to write and ~3x faster to read on large "
                 "bodies, files ~1.3x larger; VTK and ParaView >= 5.5 read it, meshio does not) or none")
      ->check(CLI::IsMember({"zlib", "lz4", "none"}));
  app.add_option("--title", title, "first caption line of the picture (default: the output's name)");
  return xfem::cli::run(*tool, argc, argv, [&] {
    xfem::cli::check_output(output, {".vtu"});
    if (!faces.empty()) xfem::cli::check_output(faces, {".vtp", ".vtu"});
    if (!png.empty()) xfem::cli::check_output(png, {".png"});
    if (!png.empty() && !std::getenv("DISPLAY"))
      throw xfem::Error(png + ": rendering needs an X display; run under 'xvfb-run -a' (DISPLAY is unset)");
    const xfem::Problem problem = xfem::read_problem(problem_path);
    std::vector<std::string> warnings;
    const xfem::EnrichedMesh em = xfem::read_enriched_mesh_cuts(input, cut_paths, &warnings);
    const std::string cut_path = cut_paths.empty() ? std::string() : cut_paths[0];
    for (const auto& w : warnings) xfem::cli::warn(w);
    if (cut_path.empty() && em.n > em.np)
      throw xfem::Error(input + ": " + std::to_string(em.n - em.np) +
                        " enriched displacements (NS + 4 NB > 0) need the cut surface: give --cut");
    const Eigen::VectorXd u = xfem::read_vector(solution);
    if (u.size() != 3 * em.n)
      throw xfem::Error(solution + ": " + std::to_string(u.size()) + " values, expected 3N = " +
                        std::to_string(3 * em.n) + " for " + input);
    Eigen::VectorXd reactions;
    if (!reactions_path.empty()) {
      reactions = xfem::read_vector(reactions_path);
      if (reactions.size() != 3 * em.n)
        throw xfem::Error(reactions_path + ": " + std::to_string(reactions.size()) + " values, expected 3N = " +
                          std::to_string(3 * em.n) + " for " + input);
    }
    xfem::check_solution_provenance({solution, input, cut_paths, problem_path}, em);

    const xfem::SplitMesh split = xfem::split_mesh(em);
    xfem::cli::info(std::to_string(split.split_complete) + " elements split through, " +
                    std::to_string(split.split_partial) + " split behind the front: " +
                    std::to_string(split.tets.rows()) + " tets, " + std::to_string(split.points.rows()) + " points, " +
                    std::to_string(split.wound.rows() / 2) + " wound triangles per side");
    if (split.degenerate_faces > 0)
      xfem::cli::warn(std::to_string(split.degenerate_faces) + " faces with one split edge but no front point: "
                      "split at that edge only (the cut grazes a node or the front misses the face)");
    const xfem::TetMaterials materials = xfem::tet_materials(problem, em.mesh, input);
    xfem::DeformedBody body = xfem::deformed_body(split, em.cut_class, xfem::xfem_displacement(em, u), materials,
                                                  xfem::cli::progress("evaluating"), wound_offset);
    xfem::inherit_regions(em.mesh, split.parent, body.volume);  // each cell's tissue, for ParaView
    const xfem::DeformedVolume volume = xfem::deformed_volume(body.volume, body.det_F);
    xfem::cli::info(xfem::describe(volume));
    if (const std::string w = xfem::inverted_warning(volume, problem.model); !w.empty()) xfem::cli::warn(w);
    if (!reactions_path.empty()) body.volume.point_data["reaction"] = xfem::reaction_array(reactions, em.np, split.points.rows());
    if (em.cut && em.cuts.empty()) {  // several cuts: the pieces carry side codes, no +-1 pairs
      const auto opening = xfem::cut_opening(split, body.volume.point_data.at("displacement"),
                                             [&](const Eigen::Vector3d& x) {
                                               return em.cut->unit_normal(em.cut->closest(x).triangle);
                                             });
      xfem::cli::info("cut opening (u+ - u-) . n at " + std::to_string(opening.pairs) + " points: min " +
                      std::to_string(opening.min_normal) + " m, mean " + std::to_string(opening.mean_normal) +
                      " m, max " + std::to_string(opening.max_normal) + " m; max |u+ - u-| " +
                      std::to_string(opening.max_jump) + " m");
    }
    xfem::SnapshotOptions o;
    o.scale = scale;
    o.width = width;
    o.height = height;
    o.title = title.empty() ? output : title;
    if (problem.model != xfem::MaterialModel::Linear) o.stress_model = xfem::material_model_name(problem.model);
    o.edges = no_edges || edges == "off" ? xfem::SnapshotOptions::Edges::Off
              : edges == "on"            ? xfem::SnapshotOptions::Edges::On
                                         : xfem::SnapshotOptions::Edges::Auto;
    xfem::CutView camera = xfem::cut_view(body.wound);
    if (!view.empty()) {
      const Eigen::Vector3d eye(view[0], view[1], view[2]);
      if (!(eye.norm() > 0) || !eye.allFinite()) throw xfem::Error("--view: the direction must be a non-zero vector");
      camera.eye = eye.normalized();
      camera.interior = false;  // a chosen view shows the whole body
      o.view = camera;
    }
    if (!png.empty()) xfem::write_snapshot(body.volume, body.wound, png, o);
    const xfem::Compression packing = xfem::compression_named(compression);
    xfem::write_tet_mesh(body.volume, output, packing);
    if (!faces.empty()) xfem::write_triangle_mesh(body.wound, faces, packing);
    if (!script.empty())
      xfem::write_paraview_script(script, output, faces, camera, xfem::colour_top(body.volume), scale);
  });
}
