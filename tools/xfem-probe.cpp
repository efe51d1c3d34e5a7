// SPDX-License-Identifier: MIT
// A solution sampled at arbitrary points (crack openings, corner values), each on its side of the cut.
#include <string>

#include "xfem/core/cli.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/core/error.h"
#include "xfem/io/matrix_market.h"
#include "xfem/post/point_probe.h"
#include "xfem/post/rms_error.h"
#include "xfem/post/solution_provenance_check.h"
#include "xfem/io/vtk_io.h"

int main(int argc, char** argv) {
  auto tool = xfem::cli::make_tool(
      "xfem-probe",
      "Samples a solution at arbitrary points and writes x,y,z,side,ux,uy,uz as CSV. The solution is X-FEM\n"
      "(an xfem-enrich mesh with --cut and --solution) or plain (any tet mesh; point array 'cut_side' marks\n"
      "doubled nodes along a cut). A point on the cut gives the face to evaluate in its 'side' (+1: where the\n"
      "cut's normal points, -1: the other face). Points: CSV with header x,y,z[,side], or .vtp (point array\n"
      "'side' optional). A point outside the mesh is an error.",
      "xfem-probe out/enriched.vtu --cut cut.vtp --solution out/u.mtx --points probes.csv -o values.csv");
  std::string mesh_path, cut_path, solution, points_path, output = "-";
  double radius = -1;
  auto& app = tool->app;
  app.add_option("mesh", mesh_path, "mesh of the solution: xfem-enrich output (.vtu) or a plain tet mesh")->required();
  app.add_option("--cut", cut_path, "cut surface, required for an X-FEM solution");
  app.add_option("-s,--solution", solution, "solution vector u.mtx (3N x 1)")->required();
  app.add_option("-p,--points", points_path, "points to sample: .csv (x,y,z[,side]) or .vtp")->required();
  app.add_option("-o,--output", output, "CSV of the sampled displacements ('-' = stdout, the default)");
  app.add_option("--radius", radius, "points outside the mesh but this close are evaluated at the nearest tet "
                                     "(metres; default 1e-6 of the mesh's bounding-box diagonal)");
  xfem::cli::add_threads_option(*tool);
  return xfem::cli::run(*tool, argc, argv, [&] {
    const auto points = xfem::read_probe_points(points_path);
    const xfem::TetMesh plain = xfem::read_tet_mesh(mesh_path);
    const bool is_xfem = plain.field_data.count("extended_offsets") > 0;
    if (radius < 0) radius = 1e-6 * (plain.points.colwise().maxCoeff() - plain.points.colwise().minCoeff()).norm();
    const Eigen::VectorXd u = xfem::read_vector(solution);
    xfem::EnrichedMesh enriched;
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> nodal;
    xfem::FieldAt field;
    if (is_xfem) {
      if (cut_path.empty()) throw xfem::Error(mesh_path + ": an X-FEM mesh needs its cut (--cut)");
      enriched = xfem::read_enriched_mesh(mesh_path, cut_path);
      if (u.size() != 3 * enriched.n)
        throw xfem::Error(solution + ": " + std::to_string(u.size()) + " values, expected 3N = " +
                          std::to_string(3 * enriched.n) + " for " + mesh_path);
      xfem::check_solution_provenance({solution, mesh_path, {cut_path}}, enriched);
      field = xfem::xfem_field(enriched, u, radius);
    } else {
      const Eigen::Index np = plain.points.rows();
      if (u.size() != 3 * np)
        throw xfem::Error(solution + ": " + std::to_string(u.size()) + " values, expected 3 x " +
                          std::to_string(np) + " for the points of " + mesh_path);
      xfem::check_solution_provenance({solution, mesh_path}, plain, {});
      nodal = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(u.data(), np, 3);
      field = xfem::plain_field(plain, nodal, radius);
    }
    const auto values = xfem::probe(field, points, points_path);
    xfem::write_probe_csv(points, values, output);
    xfem::cli::info(std::to_string(points.size()) + " points sampled");
  });
}
