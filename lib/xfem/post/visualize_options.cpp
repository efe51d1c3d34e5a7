// SPDX-License-Identifier: MIT
#include "xfem/post/visualize_options.h"

#include <algorithm>
#include <cstdlib>

#include "xfem/core/error.h"
#include "xfem/post/wound_pressure.h"
#include "xfem/solve/contact_pressure_file.h"
#include "xfem/system/cut_loads.h"

namespace xfem {

void add_visualize_options(CLI::App& app, VisualizeOptions& o) {
  app.add_option("enriched", o.input, "xfem-enrich output (.vtu)")->required();
  app.add_option("-c,--cut", o.cut_paths, "the cut surface the mesh was classified with (.vtp/.vtu/.vtk/.stl/.obj/.off/.msh); "
                                          "omit for a mesh without enriched DOFs; several cuts: once per cut, as given "
                                          "to xfem-classify")
      ->allow_extra_args(false);
  app.add_option("-s,--solution", o.solution, "xfem-solve output: Matrix Market vector of 3N values, m")->required();
  app.add_option("-p,--problem", o.problem_path, "problem.json (material, materials per region: stresses)")->required();
  app.add_option("-o,--output", o.output, "deformed split mesh (.vtu)")->required();
  app.add_option("-f,--faces", o.faces, "also write both faces of the cut inside the body (.vtp, or .vtu: a grid of triangles)");
  app.add_option("--reactions", o.reactions_path, "xfem-solve --reactions output (3N x 1, N): written as the point "
                                                  "array 'reaction' of the output");
  app.add_option("--contact-pressure", o.contact_pressure, "xfem-solve --contact-pressure output (NP x cuts, Pa): "
                                                           "written as the cell array 'contact_pressure' of --faces");
  app.add_option("--png", o.png, "also render a picture (needs an X display: run under xvfb-run -a)");
  app.add_option("--paraview", o.script, "also write a ParaView Python script (.py) that opens the output warped by "
                                         "--scale and coloured like the picture (paraview --script=FILE)");
  app.add_option("--scale", o.scale, "displacement magnification in the picture and script only, dimensionless "
                                     "(files keep the true displacement)")->check(cli::range(1e-6, 1e6));
  app.add_option("--view", o.view, "direction from the body towards the eye (3 numbers, any length) for the picture and "
                                   "script, instead of the one chosen from the cut (docs/FORMATS.md \"PNG snapshot\")")
      ->expected(3);
  app.add_option("--width", o.width, "picture width, pixels")->check(cli::range(64, 8192));
  app.add_option("--height", o.height, "picture height, pixels")->check(cli::range(64, 8192));
  app.add_option("--edges", o.edges, "element edges in the picture: auto (light grey below 20,000 visible faces, "
                                     "default), on or off")->check(CLI::IsMember({"auto", "on", "off"}));
  app.add_option("--wound-offset", o.wound_offset, "move the wound (--faces) this fraction of the body's diagonal out of "
                                                   "its pieces so that it does not z-fight with the cut faces of the "
                                                   "output (dimensionless, default 1e-4; 0 keeps the cut's exact geometry)")
      ->check(cli::range(0.0, 0.1));
  app.add_flag("--no-edges", o.no_edges, "same as --edges off");
  app.add_option("--compression", o.compression,
                 "compression of the .vtu/.vtp written: zlib (level 1, default: read by every VTK XML reader, "
                 "meshio included), lz4 (VTK's LZ4 compressor: ~10x faster to write and ~3x faster to read on large "
                 "bodies, files ~1.3x larger; VTK and ParaView >= 5.5 read it, meshio does not) or none")
      ->check(CLI::IsMember({"zlib", "lz4", "none"}));
  app.add_option("--title", o.title, "first caption line of the picture (default: the output's name)");
}

void check_visualize_outputs(const VisualizeOptions& o) {
  cli::check_output(o.output, {".vtu"});
  if (!o.faces.empty()) cli::check_output(o.faces, {".vtp", ".vtu"});
  if (o.faces == o.output) throw Error(o.output + ": given as both -o and --faces");
  if (!o.png.empty()) cli::check_output(o.png, {".png"});
  if (!o.png.empty() && !std::getenv("DISPLAY"))
    throw Error(o.png + ": rendering needs an X display; run under 'xvfb-run -a' (DISPLAY is unset)");
  if (!o.contact_pressure.empty() && o.faces.empty())
    throw Error(o.contact_pressure + ": --contact-pressure is shown on the wound: give --faces too");
}

SnapshotOptions snapshot_options(const VisualizeOptions& o, const Problem& problem, const TriangleMesh& wound,
                                 CutView& camera) {
  SnapshotOptions s;
  s.scale = o.scale;
  s.width = o.width;
  s.height = o.height;
  s.title = o.title.empty() ? o.output : o.title;
  if (problem.model != MaterialModel::Linear) s.stress_model = material_model_name(problem.model);
  s.edges = o.no_edges || o.edges == "off" ? SnapshotOptions::Edges::Off
            : o.edges == "on"              ? SnapshotOptions::Edges::On
                                           : SnapshotOptions::Edges::Auto;
  camera = cut_view(wound);
  if (!o.view.empty()) {
    const Eigen::Vector3d eye(o.view[0], o.view[1], o.view[2]);
    if (!(eye.norm() > 0) || !eye.allFinite()) throw Error("--view: the direction must be a non-zero vector");
    camera.eye = eye.normalized();
    camera.interior = false;  // a chosen view shows the whole body
    s.view = camera;
  }
  return s;
}

void report_cut_opening(const EnrichedMesh& em, const SplitMesh& split, const DeformedBody& body) {
  if (!em.cut || !em.cuts.empty()) return;
  const CutOpening opening = cut_opening(split, body.volume.point_data.at("displacement"), [&](const Eigen::Vector3d& x) {
    return em.cut->unit_normal(em.cut->closest(x).triangle);
  });
  cli::info("cut opening (u+ - u-) . n at " + std::to_string(opening.pairs) + " points: min " +
            std::to_string(opening.min_normal) + " m, mean " + std::to_string(opening.mean_normal) + " m, max " +
            std::to_string(opening.max_normal) + " m; max |u+ - u-| " + std::to_string(opening.max_jump) + " m");
  if (opening.pairs > 0)
    cli::info("largest penetration of the cut's faces: " + cli::three_digits(std::max(0.0, -opening.min_normal)) + " m");
}

void add_contact_pressure(const std::string& path, const EnrichedMesh& em, const SplitMesh& split, DeformedBody& body) {
  const SparseMatrix nodal = read_contact_pressure(path, em.mesh.points.rows(), cut_count(em));
  const std::vector<double> pressure = wound_contact_pressure(split, em, nodal);
  DataArray array = make_array(DataArray::Type::Float64, 1, pressure.size());
  for (std::size_t f = 0; f < pressure.size(); ++f) array.values[f] = pressure[f];
  body.wound.cell_data["contact_pressure"] = array;
  double largest = 0;
  for (double p : pressure) largest = std::max(largest, p);
  cli::info("contact pressure on the wound: largest " + cli::three_digits(largest) + " Pa (" + path + ")");
}

std::vector<double> wound_pressure_values(const DeformedBody& body) {
  const auto it = body.wound.cell_data.find("contact_pressure");
  return it == body.wound.cell_data.end() ? std::vector<double>() : it->second.values;
}

}  // namespace xfem
