// SPDX-License-Identifier: MIT
#include "xfem/generate/mesh_commands.h"

#include <array>
#include <cmath>
#include <memory>

#include "xfem/core/cli.h"
#include "xfem/generate/box_mesh.h"
#include "xfem/generate/generation_limits.h"
#include "xfem/generate/image_commands.h"
#include "xfem/generate/organ_shape.h"
#include "xfem/generate/unstructured_mesh.h"
#include "xfem/io/vtk_io.h"

namespace xfem {

CLI::App* add_mesh_command(CLI::App& app, const char* name, const char* what, const char* example,
                           MeshCommandOutput& output) {
  CLI::App* sub = app.add_subcommand(name, what);
  sub->footer(std::string("Example:\n  xfem-mesh ") + example);
  sub->add_option("-o,--output", output.path, "output file (.vtu for meshes; .vtp, or .vtu, for cuts)")->required();
  sub->add_flag("--allow-large", output.allow_large, "run even when the estimate exceeds 2e7 tets or triangles");
  return sub;
}

namespace {

using V3 = std::array<double, 3>;
Eigen::Vector3d vec(const V3& a) { return {a[0], a[1], a[2]}; }

const char* const size_help = "target edge length, m (tet count grows like 1/size^3)";

void write_mesh(const TetMesh& m, const std::string& out) {
  write_tet_mesh(m, out);
  cli::info(std::to_string(m.tets.rows()) + " tets, " + std::to_string(m.points.rows()) + " points -> " + out);
}

// The options of each command, bound to its CLI11 options.
struct BoxOptions {
  MeshCommandOutput out;
  std::array<int, 3> cells{0, 0, 0};
  V3 lo{0, 0, 0}, hi{0, 0, 0};
  double split_z = 0, split_x = 0;
  bool beam = false;
};

struct UnstructuredBoxOptions {
  MeshCommandOutput out;
  V3 lo{0, 0, 0}, hi{0, 0, 0};
  double size = 0;
};

struct SizedOptions {
  MeshCommandOutput out;
  std::string input;
  double size = 0;
};

void make_box(const BoxOptions& o, bool split) {
  cli::check_output(o.out.path, {".vtu"});
  check_extent(o.lo, "--lo");
  check_extent(o.hi, "--hi");
  check_element_estimate(6.0 * o.cells[0] * o.cells[1] * o.cells[2], "tets", o.out.allow_large);
  const Eigen::Vector3i n(o.cells[0], o.cells[1], o.cells[2]);
  if (o.beam || split)
    write_mesh(box_mesh(n, vec(o.lo), vec(o.hi), o.beam ? BoxCut{0.1, 0.015} : BoxCut{o.split_z, o.split_x}), o.out.path);
  else
    write_mesh(box_mesh(n, vec(o.lo), vec(o.hi)), o.out.path);
}

MeshCommand box_command(CLI::App& app) {
  auto o = std::make_shared<BoxOptions>();
  auto* box = add_mesh_command(app, "box", "structured box: NX x NY x NZ cubes of 6 tets; optionally cut by duplicated nodes",
                               "box --cells 18 36 120 --hi 0.03 0.06 0.2 --beam-cut -o reference.vtu", o->out);
  box->add_option("--cells", o->cells, "cubes along x, y, z")->required();
  box->add_option("--lo", o->lo, "lower corner, m (default 0 0 0)");
  box->add_option("--hi", o->hi, "upper corner, m")->required();
  auto* sz = box->add_option("--split-z", o->split_z, "cut the grid plane z = Z for x < --split-x-max by duplicating "
                                                      "its nodes (point array cut_side); must be a grid plane");
  auto* sx = box->add_option("--split-x-max", o->split_x, "x of the cut's straight front (a grid plane), m");
  sz->needs(sx);
  sx->needs(sz);
  box->add_flag("--beam-cut", o->beam, "the paper's beam cut: --split-z 0.1 --split-x-max 0.015")->excludes(sz)->excludes(sx);
  return {box, [o, sz] { make_box(*o, static_cast<bool>(*sz)); }};
}

MeshCommand unstructured_box_command(CLI::App& app) {
  auto o = std::make_shared<UnstructuredBoxOptions>();
  auto* ubox = add_mesh_command(app, "unstructured-box", "unstructured tet mesh of a box (CGAL Mesh_3), edges kept sharp",
                                "unstructured-box --hi 0.03 0.06 0.2 --size 0.006 -o beam.vtu", o->out);
  ubox->add_option("--lo", o->lo, "lower corner, m (default 0 0 0)");
  ubox->add_option("--hi", o->hi, "upper corner, m")->required();
  ubox->add_option("--size", o->size, size_help)->required()->check(cli::positive());
  return {ubox, [o] {
            const V3 &lo = o->lo, &hi = o->hi;
            cli::check_output(o->out.path, {".vtu"});
            check_extent(lo, "--lo");
            check_extent(hi, "--hi");
            check_element_estimate(tets_for((hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]), o->size), "tets",
                                   o->out.allow_large);
            write_mesh(unstructured_box_mesh(vec(lo), vec(hi), o->size), o->out.path);
          }};
}

MeshCommand organ_command(CLI::App& app) {
  auto o = std::make_shared<SizedOptions>();
  auto* organ = add_mesh_command(app, "organ", "unstructured tet mesh of an organ-like smooth body 0.15 m long centred at "
                                               "the origin (a bent, tapered ellipsoid; docs/FORMATS.md)",
                                 "organ --size 0.008 -o organ.vtu", o->out);
  organ->add_option("--size", o->size, size_help)->required()->check(cli::positive());
  return {organ, [o] {
            cli::check_output(o->out.path, {".vtu"});
            const double r = organ_bounding_radius;
            check_element_estimate(tets_for(4.0 / 3.0 * M_PI * r * r * r, o->size), "tets", o->out.allow_large);
            write_mesh(implicit_mesh(organ_function, organ_bounding_radius, o->size), o->out.path);
          }};
}

MeshCommand surface_command(CLI::App& app) {
  auto o = std::make_shared<SizedOptions>();
  auto* surf = add_mesh_command(app, "surface", "unstructured tet mesh of the volume inside a closed triangle surface",
                                "surface body.stl --size 0.005 -o body.vtu", o->out);
  surf->add_option("input", o->input, "closed surface (.stl/.off/.obj/.vtp/.vtu/.vtk/.msh)")->required();
  surf->add_option("--size", o->size, size_help)->required()->check(cli::positive());
  return {surf, [o] {
            cli::check_output(o->out.path, {".vtu"});
            std::vector<std::string> warnings;
            const TriangleMesh s = read_triangle_mesh(o->input, &warnings);
            for (const auto& w : warnings) cli::warn(w);
            const Eigen::RowVector3d extent = s.points.colwise().maxCoeff() - s.points.colwise().minCoeff();
            check_element_estimate(tets_for(extent.prod(), o->size), "tets", o->out.allow_large);
            write_mesh(surface_mesh(s, o->size, o->input), o->out.path);
          }};
}

}  // namespace

std::vector<MeshCommand> add_volume_mesh_commands(CLI::App& app) {
  std::vector<MeshCommand> commands = {box_command(app), unstructured_box_command(app), organ_command(app),
                                       surface_command(app)};
  for (auto& c : add_image_commands(app)) commands.push_back(std::move(c));
  return commands;
}

}  // namespace xfem
