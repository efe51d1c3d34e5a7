// SPDX-License-Identifier: MIT
// The deformed body with the cut opened (paper 4.1): split mesh, wound surface, optional PNG.
#include <cstdlib>
#include <string>

#include "xfem/cli.h"
#include "xfem/deformed_mesh.h"
#include "xfem/element_split.h"
#include "xfem/enriched_mesh.h"
#include "xfem/error.h"
#include "xfem/fingerprint.h"
#include "xfem/matrix_market.h"
#include "xfem/problem.h"
#include "xfem/snapshot.h"
#include "xfem/vtk_io.h"

int main(int argc, char** argv) {
  auto tool = xfem::cli::make_tool(
      "xfem-visualize",
      "Write the deformed body with the cut opened: every cut element split along the cut into its\n"
      "parts above and below (ahead of the cut front it stays joined), each part moved by the X-FEM\n"
      "displacement of its own side; with strain, stress and von Mises stress per cell\n"
      "(docs/FORMATS.md: deformed.vtu, wound.vtp, PNG snapshot). Positions are undeformed: apply\n"
      "ParaView's Warp By Vector with 'displacement' to see the deformation.",
      "xvfb-run -a xfem-visualize enriched.vtu --cut cut.vtp --solution u.mtx --problem problem.json \\\n"
      "      -o deformed.vtu --faces wound.vtp --png beam.png --scale 2");
  std::string input, cut_path, solution, problem_path, output, faces, png, title;
  double scale = 1.0;
  int width = 1200, height = 900;
  auto& app = tool->app;
  app.add_option("enriched", input, "xfem-enrich output (.vtu)")->required();
  app.add_option("-c,--cut", cut_path, "the cut surface the mesh was classified with (.vtp/.vtk/.stl/.obj/.off)")
      ->required();
  app.add_option("-s,--solution", solution, "xfem-solve output: Matrix Market vector of 3N values")->required();
  app.add_option("-p,--problem", problem_path, "problem.json (material E, nu for the stresses)")->required();
  app.add_option("-o,--output", output, "deformed split mesh (.vtu)")->required();
  app.add_option("-f,--faces", faces, "also write both faces of the cut inside the body (.vtp)");
  app.add_option("--png", png, "also render a picture (needs an X display: run under xvfb-run -a)");
  app.add_option("--scale", scale, "displacement magnification in the picture only (files keep the true "
                                   "displacement)")->check(xfem::cli::range(1e-6, 1e6));
  app.add_option("--width", width, "picture width, pixels")->check(xfem::cli::range(64, 8192));
  app.add_option("--height", height, "picture height, pixels")->check(xfem::cli::range(64, 8192));
  bool no_edges = false;
  app.add_flag("--no-edges", no_edges, "picture without element edges (clearer for fine meshes)");
  app.add_option("--title", title, "first caption line of the picture (default: the output's name)");
  return xfem::cli::run(*tool, argc, argv, [&] {
    xfem::cli::check_output(output, {".vtu"});
    if (!faces.empty()) xfem::cli::check_output(faces, {".vtp"});
    if (!png.empty()) xfem::cli::check_output(png, {".png"});
    if (!png.empty() && !std::getenv("DISPLAY"))
      throw xfem::Error(png + ": rendering needs an X display; run under 'xvfb-run -a' (DISPLAY is unset)");
    const xfem::Problem problem = xfem::read_problem(problem_path);
    std::vector<std::string> warnings;
    const xfem::EnrichedMesh em = xfem::read_enriched_mesh(input, cut_path, &warnings);
    for (const auto& w : warnings) xfem::cli::warn(w);
    xfem::check_cut_matches(em.mesh, input, em.cut->mesh(), cut_path);
    const Eigen::VectorXd u = xfem::read_vector(solution);
    if (u.size() != 3 * em.n)
      throw xfem::Error(solution + ": " + std::to_string(u.size()) + " values, expected 3N = " +
                        std::to_string(3 * em.n) + " for " + input);
    const xfem::Provenance made_for = xfem::read_mtx_provenance(solution);
    xfem::check_provenance(made_for, solution, "enriched", xfem::fingerprint(em.mesh), input);
    xfem::check_provenance(made_for, solution, "cut", xfem::fingerprint(em.cut->mesh()), cut_path);
    xfem::check_provenance(made_for, solution, "problem", xfem::fingerprint_json_file(problem_path), problem_path);

    const xfem::SplitMesh split = xfem::split_mesh(em.mesh, em.side, em.cut_class, em.cut->mesh(), em.front.segments());
    xfem::cli::info(std::to_string(split.split_complete) + " elements split through, " +
                    std::to_string(split.split_partial) + " split behind the front: " +
                    std::to_string(split.tets.rows()) + " tets, " + std::to_string(split.points.rows()) + " points, " +
                    std::to_string(split.wound.rows() / 2) + " wound triangles per side");
    if (split.degenerate_faces > 0)
      xfem::cli::warn(std::to_string(split.degenerate_faces) + " faces with one split edge but no front point: "
                      "split at that edge only (the cut grazes a node or the front misses the face)");
    const xfem::DeformedBody body = xfem::deformed_body(split, em.cut_class, xfem::xfem_displacement(em, u), problem.E,
                                                        problem.nu, xfem::cli::progress("evaluating"));
    const auto opening = xfem::cut_opening(split, body.volume.point_data.at("displacement"),
                                           [&](const Eigen::Vector3d& x) {
                                             return em.cut->unit_normal(em.cut->closest(x).triangle);
                                           });
    xfem::cli::info("cut opening (u+ - u-) . n at " + std::to_string(opening.pairs) + " points: min " +
                    std::to_string(opening.min_normal) + " m, mean " + std::to_string(opening.mean_normal) +
                    " m, max " + std::to_string(opening.max_normal) + " m; max |u+ - u-| " +
                    std::to_string(opening.max_jump) + " m");
    if (!png.empty()) {
      xfem::SnapshotOptions o;
      o.scale = scale;
      o.width = width;
      o.height = height;
      o.title = title.empty() ? output : title;
      o.edges = !no_edges;
      xfem::write_snapshot(body.volume, png, o);
    }
    xfem::write_tet_mesh(body.volume, output);
    if (!faces.empty()) xfem::write_triangle_mesh(body.wound, faces);
  });
}
