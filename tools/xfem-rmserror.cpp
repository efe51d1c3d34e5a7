// SPDX-License-Identifier: MIT
// RMS error of a solution against a reference solution (DESIGN.md, "The benchmark", RMS (5.1)).
#include <cmath>
#include <cstdio>

#include "xfem/core/cli.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/core/error.h"
#include "xfem/post/exact_error.h"
#include "xfem/core/fingerprint.h"
#include "xfem/system/problem.h"
#include "xfem/core/json_io.h"
#include "xfem/io/matrix_market.h"
#include "xfem/post/rms_error.h"
#include "xfem/core/version.h"
#include "xfem/io/vtk_io.h"

namespace {

using Field = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

// Nodal displacements of a plain mesh: the first NP 3-vectors of a solution vector, or the point
// array `displacement` when no solution file is given.
Field nodal_displacements(const xfem::TetMesh& mesh, const std::string& mesh_path, const std::string& solution) {
  const Eigen::Index np = mesh.points.rows();
  Field u(np, 3);
  if (!solution.empty()) {
    xfem::check_provenance(xfem::read_mtx_provenance(solution), solution, "enriched", xfem::fingerprint(mesh), mesh_path);
    const Eigen::VectorXd v = xfem::read_vector(solution);
    if (v.size() < 3 * np || v.size() % 3 != 0)
      throw xfem::Error(solution + ": " + std::to_string(v.size()) + " values, expected 3 per vector and at least " +
                        std::to_string(3 * np) + " for the " + std::to_string(np) + " points of " + mesh_path);
    for (Eigen::Index k = 0; k < np; ++k) u.row(k) = v.segment<3>(3 * k).transpose();
    return u;
  }
  const auto& a = xfem::require_array(mesh.point_data, "displacement", "point", 3, np, mesh_path,
                                      "xfem-visualize (or give --solution)");
  for (Eigen::Index k = 0; k < np; ++k) u.row(k) << a(k, 0), a(k, 1), a(k, 2);
  return u;
}

std::vector<int> sides_of(const xfem::TetMesh& mesh) {
  std::vector<int> side(mesh.points.rows(), 0);
  const auto it = mesh.point_data.find("cut_side");
  if (it != mesh.point_data.end() && it->second.components == 1)
    for (std::size_t k = 0; k < side.size(); ++k) side[k] = static_cast<int>(it->second(k));
  return side;
}

}  // namespace

int main(int argc, char** argv) {
  auto tool = xfem::cli::make_tool(
      "xfem-rmserror",
      "RMS and max error of a solution against a reference solution, over the reference's nodes, or\n"
      "against an exact field (--exact: a Williams crack field or rigid pieces, docs/FORMATS.md \"Exact\n"
      "fields\"): then RMS over the solution's own nodes, each on its side of the cut, plus relative L2 and\n"
      "H1-seminorm errors over the volume (--samples points per tet). The solution is X-FEM (an\n"
      "xfem-enrich mesh, with --cut) or plain (any tet mesh; --reference only). Prints the RMS on stdout.",
      "xfem-rmserror out/enriched.vtu --cut cut.vtp --solution out/u.mtx \\\n"
      "      --reference ref/enriched.vtu --reference-solution ref/u.mtx -o out/rms.json\n"
      "  xfem-rmserror out/enriched.vtu --cut cut.vtp --solution out/u.mtx --exact mode1.json -o out/error.json");
  std::string mesh_path, cut_path, solution, reference, reference_solution, output, exact_path;
  double max_rms = -1, radius = -1;
  int samples = 26;
  auto& app = tool->app;
  app.add_option("mesh", mesh_path, "mesh of the solution: xfem-enrich output (.vtu) or a plain tet mesh")->required();
  app.add_option("--cut", cut_path, "cut surface, required for an X-FEM solution");
  app.add_option("-s,--solution", solution, "solution vector u.mtx (default: the mesh's point array 'displacement')");
  auto* ref_option = app.add_option("-r,--reference", reference,
                                    "reference mesh (.vtu/.vtk/.msh); point array 'cut_side' gives the side of duplicated nodes");
  auto* exact_option = app.add_option("--exact", exact_path,
                                      "exact field instead of a reference: JSON {\"williams\": {origin, ahead, normal, K1, K2, "
                                      "K3, E, nu}}, {\"penny\": {centre, normal, radius, sigma, E, nu}}, {\"rigid\": {above, below}} or "
                                      "{\"linear\": {gradient, translation}} "
                                      "(docs/FORMATS.md \"Exact fields\")");
  ref_option->excludes(exact_option);
  app.add_option("--samples", samples, "with --exact: oversampling points per tet for the L2/H1 errors (m^3 > N, "
                                       "one at each sub-tet centroid; default 26: 27 points)")
      ->check(xfem::cli::range(1, 1000));
  app.add_option("--reference-solution", reference_solution,
                 "reference solution u.mtx (default: the reference's point array 'displacement')");
  app.add_option("-o,--output", output, "JSON report");
  app.add_option("--max", max_rms, "exit 1 when the RMS error exceeds this (metres): a golden-file check");
  app.add_option("--radius", radius, "reference nodes outside the mesh but this close are evaluated at the nearest "
                                     "tet (metres; default 1e-6 of the mesh's bounding-box diagonal)")
      ->check(xfem::cli::non_negative());
  app.get_option("--max")->check(xfem::cli::non_negative());
  app.callback([&] {  // during parsing, so that a missing one is a usage error (exit 2)
    if (reference.empty() && exact_path.empty()) throw CLI::RequiredError("--reference or --exact");
  });
  // Checks a solution against the X-FEM mesh and cut it is evaluated on (its recorded fingerprints).
  const auto check_solution = [&](const xfem::EnrichedMesh& em) {
    xfem::check_cut_matches(em.mesh, mesh_path, em.cut->mesh(), cut_path);
    const xfem::Provenance made_for = xfem::read_mtx_provenance(solution);
    xfem::check_provenance(made_for, solution, "enriched", xfem::fingerprint(em.mesh), mesh_path);
    xfem::check_provenance(made_for, solution, "cut", xfem::fingerprint(em.cut->mesh()), cut_path);
  };
  const auto finite = [&](double v, const char* what) {  // names the solution (or the mesh holding it)
    if (!std::isfinite(v))
      throw xfem::Error((solution.empty() ? mesh_path : solution) + ": the " + what +
                        " is not finite (overflow in the solution?)");
  };
  return xfem::cli::run(*tool, argc, argv, [&] {
    if (!output.empty()) xfem::cli::check_output(output, {".json"}, true);
    if (!exact_path.empty()) {
      const xfem::ExactField exact = xfem::read_exact_field(exact_path);
      if (exact.kind == xfem::ExactField::Kind::Penny && exact.penny.shear.squaredNorm() > 0)
        throw xfem::Error(exact_path + ": a penny with shear is not available as an exact field for errors (its shear "
                          "part is a displacement by quadrature away from the disc, for Dirichlet data; no gradient)");
      if (cut_path.empty()) throw xfem::Error(mesh_path + ": --exact needs the X-FEM mesh's cut (--cut)");
      if (solution.empty()) throw xfem::Error(mesh_path + ": --exact needs the solution (--solution)");
      const xfem::EnrichedMesh em = xfem::read_enriched_mesh(mesh_path, cut_path);
      check_solution(em);
      const Eigen::VectorXd u = xfem::read_vector(solution);
      if (u.size() != 3 * em.n)
        throw xfem::Error(solution + ": " + std::to_string(u.size()) + " values, expected 3N = " +
                          std::to_string(3 * em.n) + " for " + mesh_path);
      const xfem::ExactErrorReport e = xfem::exact_error(em, u, exact, samples);
      finite(e.nodes.rms, "RMS error");
      finite(e.l2, "L2 error");
      finite(e.h1, "H1 error");
      const auto rel = [](double a, double b) { return b > 0 ? a / b : 0.0; };
      xfem::cli::info("RMS " + std::to_string(e.nodes.rms) + " m over " + std::to_string(e.nodes.compared) +
                      " nodes, relative L2 " + std::to_string(rel(e.l2, e.l2_exact)) + ", relative H1 " +
                      std::to_string(rel(e.h1, e.h1_exact)));
      xfem::Json report;
      report["generator"] = std::string("xfem-rmserror ") + xfem::version;
      report["mesh"] = mesh_path;
      report["exact"] = exact_path;
      report["rms"] = e.nodes.rms;
      report["max"] = e.nodes.max;
      report["max_node"] = e.nodes.max_node;
      report["relative_rms"] = rel(e.nodes.rms, e.nodes.reference_rms);
      report["nodes"] = e.nodes.compared;
      report["l2"] = e.l2;
      report["relative_l2"] = rel(e.l2, e.l2_exact);
      report["h1"] = e.h1;
      report["relative_h1"] = rel(e.h1, e.h1_exact);
      report["max_strain_error"] = e.max_strain;
      report["max_gap_error"] = e.max_gap_error;
      report["samples"] = e.samples;
      report["volume"] = e.volume;
      report["n_vectors"] = em.n;
      report["n_unknowns"] = 3 * em.n;
      report["np"] = em.np;
      report["ns"] = em.ns;
      report["nb"] = em.nb;
      if (!output.empty()) xfem::write_json(report, output);
      std::printf("%.17g\n", e.nodes.rms);
      if (max_rms >= 0 && !(e.nodes.rms <= max_rms))  // a NaN fails too
        throw xfem::Error("RMS error " + std::to_string(e.nodes.rms) + " exceeds --max " + std::to_string(max_rms));
      return;
    }
    const xfem::TetMesh ref_mesh = xfem::read_tet_mesh(reference);
    const xfem::ReferenceSamples ref{ref_mesh.points, nodal_displacements(ref_mesh, reference, reference_solution),
                                     sides_of(ref_mesh)};

    xfem::TetMesh plain;
    xfem::EnrichedMesh enriched;
    Field plain_u;
    Eigen::VectorXd u;
    xfem::FieldAt field;
    const bool is_xfem = [&] {
      plain = xfem::read_tet_mesh(mesh_path);
      return plain.field_data.count("extended_offsets") > 0;
    }();
    const double diagonal = (plain.points.colwise().maxCoeff() - plain.points.colwise().minCoeff()).norm();
    if (radius < 0) radius = 1e-6 * diagonal;
    if (is_xfem) {
      if (cut_path.empty()) throw xfem::Error(mesh_path + ": an X-FEM mesh needs its cut (--cut)");
      if (solution.empty()) throw xfem::Error(mesh_path + ": an X-FEM mesh needs its solution (--solution)");
      enriched = xfem::read_enriched_mesh(mesh_path, cut_path);
      check_solution(enriched);
      u = xfem::read_vector(solution);
      if (u.size() != 3 * enriched.n)
        throw xfem::Error(solution + ": " + std::to_string(u.size()) + " values, expected 3N = " +
                          std::to_string(3 * enriched.n) + " for " + mesh_path);
      field = xfem::xfem_field(enriched, u, radius);
    } else {
      plain_u = nodal_displacements(plain, mesh_path, solution);
      field = xfem::plain_field(plain, plain_u, radius);
    }
    const xfem::RmsReport r = xfem::rms_error(ref, field);
    finite(r.rms, "RMS error");
    finite(r.max, "max error");
    if (r.compared == 0) throw xfem::Error(reference + ": no reference node lies in " + mesh_path);
    if (r.outside > 0)
      xfem::cli::warn(std::to_string(r.outside) + " reference nodes lie outside " + mesh_path +
                      " beyond --radius and were left out");
    xfem::cli::info("RMS " + std::to_string(r.rms) + " m, max " + std::to_string(r.max) + " m at reference node " +
                    std::to_string(r.max_node) + "; " + std::to_string(r.compared) + " nodes compared, " +
                    std::to_string(r.snapped) + " snapped");
    xfem::Json report;
    report["generator"] = std::string("xfem-rmserror ") + xfem::version;
    report["mesh"] = mesh_path;
    report["kind"] = is_xfem ? "xfem" : "plain";
    report["reference"] = reference;
    report["rms"] = r.rms;
    report["max"] = r.max;
    report["max_node"] = r.max_node;
    report["relative_rms"] = r.reference_rms > 0 ? r.rms / r.reference_rms : 0.0;
    report["reference_nodes"] = ref.points.rows();
    report["compared"] = r.compared;
    report["snapped"] = r.snapped;
    report["outside"] = r.outside;
    report["radius"] = radius;
    report["n_vectors"] = is_xfem ? enriched.n : static_cast<long>(plain.points.rows());
    report["n_unknowns"] = 3 * (is_xfem ? enriched.n : static_cast<long>(plain.points.rows()));
    if (!output.empty()) xfem::write_json(report, output);
    std::printf("%.17g\n", r.rms);
    if (max_rms >= 0 && !(r.rms <= max_rms))  // a NaN fails too
      throw xfem::Error("RMS error " + std::to_string(r.rms) + " exceeds --max " + std::to_string(max_rms));
  });
}
