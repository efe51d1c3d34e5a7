// SPDX-License-Identifier: MIT
#include "xfem/generate/cut_commands.h"

#include <array>
#include <memory>
#include <string>

#include "xfem/core/cli.h"
#include "xfem/generate/cut_generation.h"
#include "xfem/generate/cut_sweep.h"
#include "xfem/generate/generation_limits.h"
#include "xfem/io/vtk_io.h"

namespace xfem {
namespace {

using V3 = std::array<double, 3>;
Eigen::Vector3d vec(const V3& a) { return {a[0], a[1], a[2]}; }
Eigen::Vector2i pair(const std::vector<int>& n) { return {n[0], n.size() > 1 ? n[1] : n[0]}; }

void check_cut_output(const std::string& out) { cli::check_output(out, {".vtp", ".vtu"}); }

void write_cut(const TriangleMesh& m, const std::string& out) {
  write_triangle_mesh(m, out);
  cli::info(std::to_string(m.triangles.rows()) + " triangles, area " + std::to_string(surface_area(m)) + " m^2 -> " +
            out);
}

// The options of each command, bound to its CLI11 options.
struct RectOptions {
  MeshCommandOutput out;
  V3 corner{0, 0, 0}, edge1{0, 0, 0}, edge2{0, 0, 0};
  std::vector<int> divisions{1};
  bool beam = false;
};

struct SineOptions {
  MeshCommandOutput out;
  std::array<double, 2> lo{-0.1, -0.07}, hi{0.1, 0.01};
  double z0 = 0.005, amplitude = 0.01, wavelength = 0.1;
  std::vector<int> divisions{1};
};

struct DiscOptions {
  MeshCommandOutput out;
  V3 center{0, 0, 0}, normal{0, 0, 1};
  double radius = 0.03;
  int rings = 8;
};

struct ZigzagOptions {
  MeshCommandOutput out;
  double z0 = 0.1, amplitude = 0.02;
  std::array<double, 2> lo{-0.01, -0.01}, hi{0.04, 0.07};
  int folds = 3;
  std::vector<int> divisions{1};
};

struct MergeOptions {
  MeshCommandOutput out;
  std::vector<std::string> inputs;
  bool cut_id = false;
};

struct SweepOptions {
  MeshCommandOutput out;
  std::vector<double> path;
  V3 arc_centre{0, 0, 0}, arc_axis{0, 0, 1}, down{0, 0, -1};
  std::array<double, 2> arc_angles{0, 0};
  double arc_radius = 0, depth = 0, tilt = 0, resolution = 0, duration = 1;
};

MeshCommand rect_command(CLI::App& app) {
  auto o = std::make_shared<RectOptions>();
  auto* rect = add_mesh_command(app, "cut-rect", "planar cut: the parallelogram corner, corner+edge1, corner+edge2; "
                                                 "normal along edge1 x edge2",
                                "cut-rect --corner 0 0 0.1 --edge1 0.03 0 0 --edge2 0 0.06 0 --divisions 4 -o cut.vtp",
                                o->out);
  auto* oc = rect->add_option("--corner", o->corner, "first corner, m");
  auto* o1 = rect->add_option("--edge1", o->edge1, "first edge vector, m");
  auto* o2 = rect->add_option("--edge2", o->edge2, "second edge vector, m");
  rect->add_flag("--beam-cut", o->beam, "the paper's beam cut: z = 0.1, x in [-0.01, 0.015], y in [-0.01, 0.07], normal +z")
      ->excludes(oc)->excludes(o1)->excludes(o2);
  rect->add_option("--divisions", o->divisions, "quads along edge1 [and edge2], 2 triangles each (default 1)")->expected(1, 2);
  rect->parse_complete_callback([o, oc, o1, o2] {
    if (!o->beam && (!*oc || !*o1 || !*o2))
      throw CLI::RequiredError("cut-rect needs --corner, --edge1 and --edge2, or --beam-cut");
  });
  return {rect, [o] {
            check_cut_output(o->out.path);
            check_extent(o->corner, "--corner");
            check_extent(o->edge1, "--edge1");
            check_extent(o->edge2, "--edge2");
            const std::vector<int>& d = o->divisions;
            check_element_estimate(2.0 * d[0] * (d.size() > 1 ? d[1] : d[0]), "triangles", o->out.allow_large);
            const Eigen::Vector3d corner = vec(o->corner);
            write_cut(o->beam ? beam_cut(pair(d)) : cut_parallelogram(corner, corner + vec(o->edge1),
                                                                      corner + vec(o->edge2), pair(d)),
                      o->out.path);
          }};
}

MeshCommand sine_command(CLI::App& app) {
  auto o = std::make_shared<SineOptions>();
  auto* sine = add_mesh_command(app, "cut-sine", "sinusoidal sheet z = z0 + A sin(2 pi x / L) over a rectangle, normal "
                                                 "+z; the defaults cut the organ from y = -0.07 (outside) to a front at "
                                                 "y = 0.01 (inside)",
                                "cut-sine --amplitude 0.01 --wavelength 0.1 --divisions 80 40 -o blade.vtp", o->out);
  sine->add_option("--lo", o->lo, "x, y of the rectangle's low corner, m (default -0.1 -0.07)");
  sine->add_option("--hi", o->hi, "x, y of the rectangle's high corner, m (default 0.1 0.01)");
  sine->add_option("--z0", o->z0, "mean height z0, m (default 0.005)");
  sine->add_option("--amplitude", o->amplitude, "amplitude A, m (default 0.01)");
  sine->add_option("--wavelength", o->wavelength, "wavelength L, m (default 0.1)");
  sine->add_option("--divisions", o->divisions, "quads along x [and y] (default 80 40)")->expected(1, 2);
  return {sine, [o, sine] {
            check_cut_output(o->out.path);
            check_extent({o->lo[0], o->lo[1], o->z0}, "cut-sine --lo/--z0");
            check_extent({o->hi[0], o->hi[1], o->amplitude}, "cut-sine --hi/--amplitude");
            if (sine->count("--divisions") == 0) o->divisions = {80, 40};
            const std::vector<int>& d = o->divisions;
            check_element_estimate(2.0 * d[0] * (d.size() > 1 ? d[1] : d[0]), "triangles", o->out.allow_large);
            write_cut(cut_sine({o->lo[0], o->lo[1]}, {o->hi[0], o->hi[1]}, o->z0, o->amplitude, o->wavelength, pair(d)),
                      o->out.path);
          }};
}

MeshCommand disc_command(CLI::App& app) {
  auto o = std::make_shared<DiscOptions>();
  auto* disc = add_mesh_command(app, "cut-disc", "flat disc: a cut whose front lies inside the body all round",
                                "cut-disc --center 0 0 0 --normal 0 0 1 --radius 0.03 --rings 8 -o disc.vtp", o->out);
  disc->add_option("--center,--centre", o->center, "centre, m (default 0 0 0)");
  disc->add_option("--normal", o->normal, "normal, the cut's +1 side (default 0 0 1)");
  disc->add_option("--radius", o->radius, "radius, m (default 0.03)")->check(cli::positive());
  disc->add_option("--rings", o->rings, "concentric rings of 6, 12, 18, ... points: 6 rings^2 triangles (default 8)");
  return {disc, [o] {
            check_cut_output(o->out.path);
            check_extent(o->center, "--center");
            check_element_estimate(6.0 * o->rings * o->rings, "triangles", o->out.allow_large);
            write_cut(cut_disc(vec(o->center), vec(o->normal), o->radius, o->rings), o->out.path);
          }};
}

MeshCommand zigzag_command(CLI::App& app) {
  auto o = std::make_shared<ZigzagOptions>();
  auto* zigzag = add_mesh_command(
      app, "cut-zigzag", "folded sheet: piecewise planar zig-zag z = f(x), fold lines along y, normal +z; the defaults "
                         "cut the paper's beam through, outside it on all sides",
      "cut-zigzag --folds 3 --amplitude 0.02 --z0 0.1 --lo -0.01 -0.01 --hi 0.04 0.07 -o zigzag.vtp", o->out);
  zigzag->add_option("--lo", o->lo, "x, y of the rectangle's low corner, m (default -0.01 -0.01)");
  zigzag->add_option("--hi", o->hi, "x, y of the rectangle's high corner, m (default 0.04 0.07)");
  zigzag->add_option("--z0", o->z0, "mean height z0, m (default 0.1)");
  zigzag->add_option("--amplitude", o->amplitude, "half the height difference between neighbouring folds, m: z = z0 - "
                                                  "A at x = lo, then z0 + A, z0 - A, ... at the folds (default 0.02)");
  zigzag->add_option("--folds", o->folds, "fold lines, equally spaced in x (default 3: four flat strips)");
  zigzag->add_option("--divisions", o->divisions, "quads along y per strip (default 1)")->expected(1);
  return {zigzag, [o] {
            check_cut_output(o->out.path);
            write_cut(cut_zigzag({o->lo[0], o->lo[1]}, {o->hi[0], o->hi[1]}, o->z0, o->amplitude, o->folds,
                                 o->divisions[0]),
                      o->out.path);
          }};
}

void merge_cuts(const MergeOptions& o) {
  check_cut_output(o.out.path);
  std::vector<TriangleMesh> pieces;
  for (const auto& in : o.inputs) {
    std::vector<std::string> warnings;
    pieces.push_back(read_triangle_mesh(in, &warnings));
    for (const auto& w : warnings) cli::warn(w);
  }
  TriangleMesh merged = merge_surfaces(pieces);
  if (o.cut_id) {
    DataArray id = make_array(DataArray::Type::Int32, 1, merged.triangles.rows());
    for (std::size_t p = 0, t = 0; p < pieces.size(); ++p)
      for (Eigen::Index f = 0; f < pieces[p].triangles.rows(); ++f) id.values[t++] = static_cast<double>(p);
    merged.cell_data["cut_id"] = std::move(id);
  }
  write_cut(merged, o.out.path);
}

MeshCommand merge_command(CLI::App& app) {
  auto o = std::make_shared<MergeOptions>();
  auto* merge = add_mesh_command(app, "cut-merge", "several cut surfaces as one file (e.g. two disjoint pieces), each "
                                                   "piece keeping its orientation; arrays are dropped",
                                 "cut-merge upper.vtp lower.vtp -o two_pieces.vtp", o->out);
  merge->add_option("inputs", o->inputs, "cut surfaces (.vtp/.vtk/.stl/.obj/.off)")->required()->expected(2, -1);
  merge->add_flag("--cut-id", o->cut_id, "store the cell array cut_id (Int32: 0 for the first input's triangles, "
                                         "1 for the second's, ...): the file then holds several cuts, each with "
                                         "its own side function (docs/FORMATS.md \"Several cuts\")");
  return {merge, [o] { merge_cuts(*o); }};
}

void sweep_cut(const SweepOptions& o) {
  check_cut_output(o.out.path);
  BladePath path;
  for (std::size_t k = 0; k + 2 < o.path.size(); k += 3) {
    check_extent({o.path[k], o.path[k + 1], o.path[k + 2]}, "--path");
    path.polyline.emplace_back(o.path[k], o.path[k + 1], o.path[k + 2]);
  }
  check_extent(o.arc_centre, "--arc-centre");
  path.centre = vec(o.arc_centre);
  path.axis = vec(o.arc_axis);
  path.radius = o.arc_radius;
  path.a0 = o.arc_angles[0];
  path.a1 = o.arc_angles[1];
  write_cut(cut_sweep(path, o.depth, vec(o.down), o.tilt, o.resolution, o.duration), o.out.path);
}

MeshCommand sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  auto* sweep = add_mesh_command(
      app, "cut-sweep", "a blade's sweep: a segment hanging from a point moving along a polyline or a circular arc; "
                        "cell array 'time' = when the blade makes each triangle (xfem-sweep; docs/FORMATS.md)",
      "cut-sweep --arc-centre 0 0.09 0.05 --arc-radius 0.09 --arc-angles -150 -30 --depth 0.06 --resolution 0.003 "
      "-o sweep.vtp", o->out);
  auto* op = sweep->add_option("--path", o->path, "the blade's top end moves along the polyline X1 Y1 Z1 X2 Y2 Z2 ... "
                                                  "(m, at least 2 points)");
  auto* oa = sweep->add_option("--arc-centre,--arc-center", o->arc_centre, "or along a circular arc about this centre, m");
  sweep->add_option("--arc-radius", o->arc_radius, "the arc's radius, m")->check(cli::positive());
  sweep->add_option("--arc-angles", o->arc_angles, "the arc from angle A0 to A1, degrees, counter-clockwise about "
                                                   "--arc-axis from the plane direction closest to +x");
  sweep->add_option("--arc-axis", o->arc_axis, "the arc's axis (default 0 0 1: a horizontal arc)");
  sweep->add_option("--depth", o->depth, "the blade's length, m")->required()->check(cli::positive());
  sweep->add_option("--down", o->down, "the blade's direction from its top end (default 0 0 -1)");
  sweep->add_option("--tilt", o->tilt, "the blade turned by this angle about the path's tangent, degrees (default 0)")
      ->check(cli::range(-89.0, 89.0));
  sweep->add_option("--resolution", o->resolution, "triangle size along the path and the blade, m")->required()
      ->check(cli::positive());
  sweep->add_option("--duration", o->duration, "the time at the end of the path, s (default 1); the blade moves at "
                                               "constant speed")->check(cli::positive());
  op->excludes(oa);
  sweep->parse_complete_callback([o, op, oa, sweep] {
    if (!*op && !*oa) throw CLI::RequiredError("cut-sweep: --path (or --arc-centre with --arc-radius and --arc-angles)");
    if (*op && (o->path.size() < 6 || o->path.size() % 3 != 0))
      throw CLI::ValidationError("--path", "needs X Y Z of at least 2 points (a multiple of 3 numbers), got " +
                                               std::to_string(o->path.size()) + " numbers");
    if (*oa && (sweep->count("--arc-radius") == 0 || sweep->count("--arc-angles") == 0))
      throw CLI::RequiredError("--arc-centre needs --arc-radius and --arc-angles");
  });
  return {sweep, [o] { sweep_cut(*o); }};
}

}  // namespace

std::vector<MeshCommand> add_cut_commands(CLI::App& app) {
  return {rect_command(app), sine_command(app),  disc_command(app),
          zigzag_command(app), merge_command(app), sweep_command(app)};
}

}  // namespace xfem
