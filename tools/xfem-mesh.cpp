// SPDX-License-Identifier: MIT
// Makes every input the pipelines need: structured and unstructured tet meshes, cut surfaces.
#include <array>
#include <cmath>
#include <vector>

#include "xfem/generate/box_mesh.h"
#include "xfem/core/cli.h"
#include "xfem/generate/cut_generation.h"
#include "xfem/generate/cut_sweep.h"
#include "xfem/core/error.h"
#include "xfem/generate/organ_shape.h"
#include "xfem/generate/unstructured_mesh.h"
#include "xfem/io/vtk_io.h"

namespace {

using V3 = std::array<double, 3>;
Eigen::Vector3d vec(const V3& a) { return {a[0], a[1], a[2]}; }
Eigen::Vector2i pair(const std::vector<int>& n) { return {n[0], n.size() > 1 ? n[1] : n[0]}; }

bool allow_large = false;  // --allow-large, on every command

CLI::App* command(CLI::App& app, const char* name, const char* what, const char* example, std::string& out) {
  CLI::App* sub = app.add_subcommand(name, what);
  sub->footer(std::string("Example:\n  xfem-mesh ") + example);
  sub->add_option("-o,--output", out, "output file (.vtu for meshes; .vtp, or .vtu, for cuts)")->required();
  sub->add_flag("--allow-large", allow_large, "run even when the estimate exceeds 2e7 tets or triangles");
  return sub;
}

void write_mesh(const xfem::TetMesh& m, const std::string& out) {
  xfem::write_tet_mesh(m, out);
  xfem::cli::info(std::to_string(m.tets.rows()) + " tets, " + std::to_string(m.points.rows()) + " points -> " + out);
}

void write_cut(const xfem::TriangleMesh& m, const std::string& out) {
  xfem::write_triangle_mesh(m, out);
  xfem::cli::info(std::to_string(m.triangles.rows()) + " triangles, area " + std::to_string(xfem::surface_area(m)) +
                  " m^2 -> " + out);
}

// Cost guard: meshes beyond this many tets (or cuts beyond this many triangles) take hours or
// exhaust memory; refused with the estimate unless --allow-large.
constexpr double kMaxElements = 2e7;

void guard(double estimate, const char* what, bool allowed) {
  if (!(estimate <= kMaxElements) && !allowed)
    throw xfem::Error("about " + xfem::short_number(estimate) + " " + what + " requested (limit " +
                      xfem::short_number(kMaxElements) + "; a larger --size or fewer divisions, or --allow-large)");
}

// Regular tets of edge `size` fill a volume V with about 6 sqrt(2) V / size^3 tets.
double tets_for(double volume, double size) { return 6 * std::sqrt(2.0) * volume / (size * size * size); }

// Coordinates beyond 1e6 m are not a body this tool meshes (and overflow volumes and CGAL).
void check_extent(const V3& a, const char* option) {
  for (double v : a)
    if (!(std::fabs(v) <= 1e6))
      throw xfem::Error(std::string(option) + " " + xfem::short_number(v) + ": coordinates must lie within 1e6 m of the origin");
}

}  // namespace

int main(int argc, char** argv) {
  auto tool = xfem::cli::make_tool(
      "xfem-mesh", "Makes inputs: tetrahedral meshes (.vtu) and cut surfaces (.vtp). Same arguments, same bytes.",
      "xfem-mesh unstructured-box --hi 0.03 0.06 0.2 --size 0.006 -o beam.vtu\n"
      "  xfem-mesh cut-rect --beam-cut -o cut.vtp\n  (xfem-mesh <command> --help for each command's options)");
  auto& app = tool->app;
  app.require_subcommand(1);
  std::string out, input;
  V3 lo{0, 0, 0}, hi{0, 0, 0}, corner{0, 0, 0}, edge1{0, 0, 0}, edge2{0, 0, 0}, center{0, 0, 0}, normal{0, 0, 1};
  std::array<int, 3> cells{0, 0, 0};
  std::vector<int> divisions{1};
  double size = 0, split_z = 0, split_x = 0, z0 = 0.005, amplitude = 0.01, wavelength = 0.1, radius = 0.03;
  std::array<double, 2> sine_lo{-0.1, -0.07}, sine_hi{0.1, 0.01};
  int rings = 8;
  bool beam = false;

  auto* box = command(app, "box", "structured box: NX x NY x NZ cubes of 6 tets; optionally cut by duplicated nodes",
                      "box --cells 18 36 120 --hi 0.03 0.06 0.2 --beam-cut -o reference.vtu", out);
  box->add_option("--cells", cells, "cubes along x, y, z")->required();
  box->add_option("--lo", lo, "lower corner, m (default 0 0 0)");
  box->add_option("--hi", hi, "upper corner, m")->required();
  auto* sz = box->add_option("--split-z", split_z, "cut the grid plane z = Z for x < --split-x-max by duplicating "
                                                   "its nodes (point array cut_side); must be a grid plane");
  auto* sx = box->add_option("--split-x-max", split_x, "x of the cut's straight front (a grid plane), m");
  sz->needs(sx);
  sx->needs(sz);
  box->add_flag("--beam-cut", beam, "the paper's beam cut: --split-z 0.1 --split-x-max 0.015")->excludes(sz)->excludes(sx);

  auto* ubox = command(app, "unstructured-box", "unstructured tet mesh of a box (CGAL Mesh_3), edges kept sharp",
                       "unstructured-box --hi 0.03 0.06 0.2 --size 0.006 -o beam.vtu", out);
  ubox->add_option("--lo", lo, "lower corner, m (default 0 0 0)");
  ubox->add_option("--hi", hi, "upper corner, m")->required();
  const char* size_help = "target edge length, m (tet count grows like 1/size^3)";
  ubox->add_option("--size", size, size_help)->required()->check(xfem::cli::positive());

  auto* organ = command(app, "organ", "unstructured tet mesh of an organ-like smooth body 0.15 m long centred at the "
                                      "origin (a bent, tapered ellipsoid; docs/FORMATS.md)",
                        "organ --size 0.008 -o organ.vtu", out);
  organ->add_option("--size", size, size_help)->required()->check(xfem::cli::positive());

  auto* surf = command(app, "surface", "unstructured tet mesh of the volume inside a closed triangle surface",
                       "surface body.stl --size 0.005 -o body.vtu", out);
  surf->add_option("input", input, "closed surface (.stl/.off/.obj/.vtp/.vtu/.vtk/.msh)")->required();
  surf->add_option("--size", size, size_help)->required()->check(xfem::cli::positive());

  auto* rect = command(app, "cut-rect", "planar cut: the parallelogram corner, corner+edge1, corner+edge2; normal "
                                        "along edge1 x edge2",
                       "cut-rect --corner 0 0 0.1 --edge1 0.03 0 0 --edge2 0 0.06 0 --divisions 4 -o cut.vtp", out);
  auto* oc = rect->add_option("--corner", corner, "first corner, m");
  auto* o1 = rect->add_option("--edge1", edge1, "first edge vector, m");
  auto* o2 = rect->add_option("--edge2", edge2, "second edge vector, m");
  rect->add_flag("--beam-cut", beam, "the paper's beam cut: z = 0.1, x in [-0.01, 0.015], y in [-0.01, 0.07], normal +z")
      ->excludes(oc)->excludes(o1)->excludes(o2);
  rect->add_option("--divisions", divisions, "quads along edge1 [and edge2], 2 triangles each (default 1)")->expected(1, 2);
  rect->parse_complete_callback([&] {
    if (!beam && (!*oc || !*o1 || !*o2)) throw CLI::RequiredError("cut-rect needs --corner, --edge1 and --edge2, or --beam-cut");
  });

  auto* sine = command(app, "cut-sine", "sinusoidal sheet z = z0 + A sin(2 pi x / L) over a rectangle, normal +z; the "
                                        "defaults cut the organ from y = -0.07 (outside) to a front at y = 0.01 (inside)",
                       "cut-sine --amplitude 0.01 --wavelength 0.1 --divisions 80 40 -o blade.vtp", out);
  sine->add_option("--lo", sine_lo, "x, y of the rectangle's low corner, m (default -0.1 -0.07)");
  sine->add_option("--hi", sine_hi, "x, y of the rectangle's high corner, m (default 0.1 0.01)");
  sine->add_option("--z0", z0, "mean height z0, m (default 0.005)");
  sine->add_option("--amplitude", amplitude, "amplitude A, m (default 0.01)");
  sine->add_option("--wavelength", wavelength, "wavelength L, m (default 0.1)");
  sine->add_option("--divisions", divisions, "quads along x [and y] (default 80 40)")->expected(1, 2);

  auto* disc = command(app, "cut-disc", "flat disc: a cut whose front lies inside the body all round",
                       "cut-disc --center 0 0 0 --normal 0 0 1 --radius 0.03 --rings 8 -o disc.vtp", out);
  disc->add_option("--center,--centre", center, "centre, m (default 0 0 0)");
  disc->add_option("--normal", normal, "normal, the cut's +1 side (default 0 0 1)");
  disc->add_option("--radius", radius, "radius, m (default 0.03)")->check(xfem::cli::positive());
  disc->add_option("--rings", rings, "concentric rings of 6, 12, 18, ... points: 6 rings^2 triangles (default 8)");

  double zz_z0 = 0.1, zz_amplitude = 0.02;
  std::array<double, 2> zz_lo{-0.01, -0.01}, zz_hi{0.04, 0.07};
  int folds = 3;
  auto* zigzag = command(app, "cut-zigzag", "folded sheet: piecewise planar zig-zag z = f(x), fold lines along y, "
                                            "normal +z; the defaults cut the paper's beam through, outside it on all sides",
                         "cut-zigzag --folds 3 --amplitude 0.02 --z0 0.1 --lo -0.01 -0.01 --hi 0.04 0.07 -o zigzag.vtp", out);
  zigzag->add_option("--lo", zz_lo, "x, y of the rectangle's low corner, m (default -0.01 -0.01)");
  zigzag->add_option("--hi", zz_hi, "x, y of the rectangle's high corner, m (default 0.04 0.07)");
  zigzag->add_option("--z0", zz_z0, "mean height z0, m (default 0.1)");
  zigzag->add_option("--amplitude", zz_amplitude, "half the height difference between neighbouring folds, m: z = z0 - A "
                                                  "at x = lo, then z0 + A, z0 - A, ... at the folds (default 0.02)");
  zigzag->add_option("--folds", folds, "fold lines, equally spaced in x (default 3: four flat strips)");
  zigzag->add_option("--divisions", divisions, "quads along y per strip (default 1)")->expected(1);

  std::vector<std::string> merge_inputs;
  auto* merge = command(app, "cut-merge", "several cut surfaces as one file (e.g. two disjoint pieces), each piece "
                                          "keeping its orientation; arrays are dropped",
                        "cut-merge upper.vtp lower.vtp -o two_pieces.vtp", out);
  merge->add_option("inputs", merge_inputs, "cut surfaces (.vtp/.vtk/.stl/.obj/.off)")->required()->expected(2, -1);
  bool merge_cut_id = false;
  merge->add_flag("--cut-id", merge_cut_id, "store the cell array cut_id (Int32: 0 for the first input's triangles, "
                                            "1 for the second's, ...): the file then holds several cuts, each with "
                                            "its own side function (docs/FORMATS.md \"Several cuts\")");

  std::vector<double> sweep_path;
  V3 arc_centre{0, 0, 0}, arc_axis{0, 0, 1}, down{0, 0, -1};
  std::array<double, 2> arc_angles{0, 0};
  double arc_radius = 0, depth = 0, tilt = 0, resolution = 0, duration = 1;
  auto* sweep = command(app, "cut-sweep", "a blade's sweep: a segment hanging from a point moving along a polyline or a "
                                          "circular arc; cell array 'time' = when the blade makes each triangle "
                                          "(xfem-sweep; docs/FORMATS.md)",
                        "cut-sweep --arc-centre 0 0.09 0.05 --arc-radius 0.09 --arc-angles -150 -30 --depth 0.06 "
                        "--resolution 0.003 -o sweep.vtp", out);
  auto* op = sweep->add_option("--path", sweep_path, "the blade's top end moves along the polyline X1 Y1 Z1 X2 Y2 Z2 ... "
                                                     "(m, at least 2 points)");
  auto* oa = sweep->add_option("--arc-centre,--arc-center", arc_centre, "or along a circular arc about this centre, m");
  sweep->add_option("--arc-radius", arc_radius, "the arc's radius, m")->check(xfem::cli::positive());
  sweep->add_option("--arc-angles", arc_angles, "the arc from angle A0 to A1, degrees, counter-clockwise about --arc-axis "
                                                "from the plane direction closest to +x");
  sweep->add_option("--arc-axis", arc_axis, "the arc's axis (default 0 0 1: a horizontal arc)");
  sweep->add_option("--depth", depth, "the blade's length, m")->required()->check(xfem::cli::positive());
  sweep->add_option("--down", down, "the blade's direction from its top end (default 0 0 -1)");
  sweep->add_option("--tilt", tilt, "the blade turned by this angle about the path's tangent, degrees (default 0)")
      ->check(xfem::cli::range(-89.0, 89.0));
  sweep->add_option("--resolution", resolution, "triangle size along the path and the blade, m")->required()
      ->check(xfem::cli::positive());
  sweep->add_option("--duration", duration, "the time at the end of the path, s (default 1); the blade moves at constant "
                                            "speed")->check(xfem::cli::positive());
  op->excludes(oa);
  sweep->parse_complete_callback([&] {
    if (!*op && !*oa) throw CLI::RequiredError("cut-sweep: --path (or --arc-centre with --arc-radius and --arc-angles)");
    if (*op && (sweep_path.size() < 6 || sweep_path.size() % 3 != 0))
      throw CLI::ValidationError("--path", "needs X Y Z of at least 2 points (a multiple of 3 numbers), got " +
                                               std::to_string(sweep_path.size()) + " numbers");
    if (*oa && (sweep->count("--arc-radius") == 0 || sweep->count("--arc-angles") == 0))
      throw CLI::RequiredError("--arc-centre needs --arc-radius and --arc-angles");
  });

  return xfem::cli::run(*tool, argc, argv, [&] {
    const bool mesh_out = box->parsed() || ubox->parsed() || organ->parsed() || surf->parsed();
    xfem::cli::check_output(out, mesh_out ? std::vector<std::string>{".vtu"} : std::vector<std::string>{".vtp", ".vtu"});
    for (const auto& [a, name] : {std::pair<const V3*, const char*>{&lo, "--lo"}, {&hi, "--hi"}, {&corner, "--corner"},
                                  {&edge1, "--edge1"}, {&edge2, "--edge2"}, {&center, "--center"}})
      check_extent(*a, name);
    check_extent({sine_lo[0], sine_lo[1], z0}, "cut-sine --lo/--z0");
    check_extent({sine_hi[0], sine_hi[1], amplitude}, "cut-sine --hi/--amplitude");
    if (box->parsed()) {
      guard(6.0 * cells[0] * cells[1] * cells[2], "tets", allow_large);
    } else if (ubox->parsed()) {
      guard(tets_for((hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]), size), "tets", allow_large);
    } else if (organ->parsed()) {
      const double r = xfem::organ_bounding_radius;
      guard(tets_for(4.0 / 3.0 * M_PI * r * r * r, size), "tets", allow_large);
    } else if (rect->parsed() || sine->parsed()) {
      const std::vector<int> d = sine->parsed() && sine->count("--divisions") == 0 ? std::vector<int>{80, 40} : divisions;
      guard(2.0 * d[0] * (d.size() > 1 ? d[1] : d[0]), "triangles", allow_large);
    } else if (disc->parsed()) {
      guard(6.0 * rings * rings, "triangles", allow_large);
    }
    if (box->parsed()) {
      const Eigen::Vector3i n(cells[0], cells[1], cells[2]);
      if (beam || *sz) write_mesh(xfem::box_mesh(n, vec(lo), vec(hi), beam ? xfem::BoxCut{0.1, 0.015} : xfem::BoxCut{split_z, split_x}), out);
      else write_mesh(xfem::box_mesh(n, vec(lo), vec(hi)), out);
    } else if (ubox->parsed()) {
      write_mesh(xfem::unstructured_box_mesh(vec(lo), vec(hi), size), out);
    } else if (organ->parsed()) {
      write_mesh(xfem::implicit_mesh(xfem::organ_function, xfem::organ_bounding_radius, size), out);
    } else if (surf->parsed()) {
      std::vector<std::string> warnings;
      const xfem::TriangleMesh s = xfem::read_triangle_mesh(input, &warnings);
      for (const auto& w : warnings) xfem::cli::warn(w);
      const Eigen::RowVector3d extent = s.points.colwise().maxCoeff() - s.points.colwise().minCoeff();
      guard(tets_for(extent.prod(), size), "tets", allow_large);
      write_mesh(xfem::surface_mesh(s, size, input), out);
    } else if (rect->parsed()) {
      write_cut(beam ? xfem::beam_cut(pair(divisions))
                     : xfem::cut_parallelogram(vec(corner), vec(corner) + vec(edge1), vec(corner) + vec(edge2), pair(divisions)),
                out);
    } else if (sine->parsed()) {
      if (sine->count("--divisions") == 0) divisions = {80, 40};
      write_cut(xfem::cut_sine({sine_lo[0], sine_lo[1]}, {sine_hi[0], sine_hi[1]}, z0, amplitude, wavelength,
                               pair(divisions)),
                out);
    } else if (disc->parsed()) {
      write_cut(xfem::cut_disc(vec(center), vec(normal), radius, rings), out);
    } else if (zigzag->parsed()) {
      write_cut(xfem::cut_zigzag({zz_lo[0], zz_lo[1]}, {zz_hi[0], zz_hi[1]}, zz_z0, zz_amplitude, folds, divisions[0]), out);
    } else if (sweep->parsed()) {
      xfem::BladePath path;
      for (std::size_t k = 0; k + 2 < sweep_path.size(); k += 3) {
        check_extent({sweep_path[k], sweep_path[k + 1], sweep_path[k + 2]}, "--path");
        path.polyline.emplace_back(sweep_path[k], sweep_path[k + 1], sweep_path[k + 2]);
      }
      check_extent(arc_centre, "--arc-centre");
      path.centre = vec(arc_centre);
      path.axis = vec(arc_axis);
      path.radius = arc_radius;
      path.a0 = arc_angles[0];
      path.a1 = arc_angles[1];
      write_cut(xfem::cut_sweep(path, depth, vec(down), tilt, resolution, duration), out);
    } else if (merge->parsed()) {
      std::vector<xfem::TriangleMesh> pieces;
      for (const auto& in : merge_inputs) {
        std::vector<std::string> warnings;
        pieces.push_back(xfem::read_triangle_mesh(in, &warnings));
        for (const auto& w : warnings) xfem::cli::warn(w);
      }
      xfem::TriangleMesh merged = xfem::merge_surfaces(pieces);
      if (merge_cut_id) {
        xfem::DataArray id = xfem::make_array(xfem::DataArray::Type::Int32, 1, merged.triangles.rows());
        for (std::size_t p = 0, t = 0; p < pieces.size(); ++p)
          for (Eigen::Index f = 0; f < pieces[p].triangles.rows(); ++f) id.values[t++] = static_cast<double>(p);
        merged.cell_data["cut_id"] = std::move(id);
      }
      write_cut(merged, out);
    }
  });
}
