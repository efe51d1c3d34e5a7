// SPDX-License-Identifier: MIT
#include "xfem/post/solution_comparison.h"

#include <cmath>
#include <vector>

#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/core/version.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/io/matrix_market.h"
#include "xfem/io/vtk_io.h"
#include "xfem/post/exact_error.h"
#include "xfem/post/rms_error.h"
#include "xfem/post/solution_provenance_check.h"
#include "xfem/system/problem.h"

namespace xfem {
namespace {

using Field = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

// Nodal displacements of a plain mesh: a solution vector of 3 NP values, or the point array
// `displacement` when no solution file is given. An X-FEM solution (N > NP) needs its mesh's cut
// to be evaluated: its first NP vectors alone are not the displacement, unless `standard_dofs_only`
// asks for exactly those (a regression check of the solve's values).
Field nodal_displacements(const TetMesh& mesh, const std::string& mesh_path, const std::string& solution,
                          bool standard_dofs_only) {
  const Eigen::Index np = mesh.points.rows();
  Field u(np, 3);
  if (!solution.empty()) {
    const Eigen::VectorXd v = read_vector(solution);
    if (v.size() < 3 * np || v.size() % 3 != 0)
      throw Error(solution + ": " + std::to_string(v.size()) + " values, expected 3 per vector and at least " +
                  std::to_string(3 * np) + " for the " + std::to_string(np) + " points of " + mesh_path);
    if (v.size() > 3 * np && !standard_dofs_only)
      throw Error(mesh_path + ": given without the cut its solution " + solution + " needs (" +
                  std::to_string(v.size() / 3 - np) + " enriched displacements beyond its " + std::to_string(np) +
                  " points would be dropped): compare the X-FEM mesh with its cut, or its xfem-visualize output");
    SolutionFiles files{solution, mesh_path};
    files.standard_dofs_only = standard_dofs_only;
    check_solution_provenance(files, mesh, {});
    for (Eigen::Index k = 0; k < np; ++k) u.row(k) = v.segment<3>(3 * k).transpose();
    return u;
  }
  const auto& a = require_array(mesh.point_data, "displacement", "point", 3, np, mesh_path,
                                "xfem-visualize (or give --solution)");
  for (Eigen::Index k = 0; k < np; ++k) u.row(k) << a(k, 0), a(k, 1), a(k, 2);
  return u;
}

std::vector<int> sides_of(const TetMesh& mesh) {
  std::vector<int> side(mesh.points.rows(), 0);
  const auto it = mesh.point_data.find("cut_side");
  if (it != mesh.point_data.end() && it->second.components == 1)
    for (std::size_t k = 0; k < side.size(); ++k) side[k] = static_cast<int>(it->second(k));
  return side;
}

// Checks a solution against the X-FEM mesh and cut it is evaluated on (its recorded fingerprints).
void check_solution(const ComparedSolution& s, const EnrichedMesh& em) {
  check_solution_provenance({s.solution, s.mesh, {s.cut}}, em);
}

// An X-FEM solution's u, which must hold 3N values.
Eigen::VectorXd read_xfem_solution(const ComparedSolution& s, const EnrichedMesh& em) {
  Eigen::VectorXd u = read_vector(s.solution);
  if (u.size() != 3 * em.n)
    throw Error(s.solution + ": " + std::to_string(u.size()) + " values, expected 3N = " + std::to_string(3 * em.n) +
                " for " + s.mesh);
  return u;
}

void require_finite(const ComparedSolution& s, double v, const char* what) {  // names the solution (or the mesh holding it)
  if (!std::isfinite(v))
    throw Error((s.solution.empty() ? s.mesh : s.solution) + ": the " + what +
                " is not finite (overflow in the solution?)");
}

}  // namespace

Json compare_with_exact(const ComparedSolution& s, const std::string& exact_path, int samples) {
  const ExactField exact = read_exact_field(exact_path);
  if (exact.kind == ExactField::Kind::Penny && exact.penny.shear.squaredNorm() > 0)
    throw Error(exact_path + ": a penny with shear is not available as an exact field for errors (its shear "
                "part is a displacement by quadrature away from the disc, for Dirichlet data; no gradient)");
  if (s.cut.empty()) throw Error(s.mesh + ": --exact needs the X-FEM mesh's cut (--cut)");
  if (s.solution.empty()) throw Error(s.mesh + ": --exact needs the solution (--solution)");
  const EnrichedMesh em = read_enriched_mesh(s.mesh, s.cut);
  check_solution(s, em);
  const Eigen::VectorXd u = read_xfem_solution(s, em);
  const ExactErrorReport e = exact_error(em, u, exact, samples);
  require_finite(s, e.nodes.rms, "RMS error");
  require_finite(s, e.l2, "L2 error");
  require_finite(s, e.h1, "H1 error");
  const auto rel = [](double a, double b) { return b > 0 ? a / b : 0.0; };
  cli::info("RMS " + std::to_string(e.nodes.rms) + " m over " + std::to_string(e.nodes.compared) +
            " nodes, relative L2 " + std::to_string(rel(e.l2, e.l2_exact)) + ", relative H1 " +
            std::to_string(rel(e.h1, e.h1_exact)));
  Json report;
  report["generator"] = std::string("xfem-rmserror ") + version;
  report["mesh"] = s.mesh;
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
  return report;
}

Json compare_with_reference(const ComparedSolution& s, const std::string& reference,
                            const std::string& reference_solution, double radius) {
  const TetMesh ref_mesh = read_tet_mesh(reference);
  const ReferenceSamples ref{ref_mesh.points, nodal_displacements(ref_mesh, reference, reference_solution, s.standard_dofs_only),
                             sides_of(ref_mesh)};

  TetMesh plain;
  EnrichedMesh enriched;
  Field plain_u;
  Eigen::VectorXd u;
  FieldAt field;
  const bool is_xfem = [&] {
    plain = read_tet_mesh(s.mesh);
    return plain.field_data.count("extended_offsets") > 0;
  }();
  const double diagonal = (plain.points.colwise().maxCoeff() - plain.points.colwise().minCoeff()).norm();
  if (radius < 0) radius = 1e-6 * diagonal;
  if (is_xfem) {
    if (s.cut.empty()) throw Error(s.mesh + ": an X-FEM mesh needs its cut (--cut)");
    if (s.solution.empty()) throw Error(s.mesh + ": an X-FEM mesh needs its solution (--solution)");
    enriched = read_enriched_mesh(s.mesh, s.cut);
    check_solution(s, enriched);
    u = read_xfem_solution(s, enriched);
    field = xfem_field(enriched, u, radius);
  } else {
    plain_u = nodal_displacements(plain, s.mesh, s.solution, s.standard_dofs_only);
    field = plain_field(plain, plain_u, radius);
  }
  const RmsReport r = rms_error(ref, field);
  require_finite(s, r.rms, "RMS error");
  require_finite(s, r.max, "max error");
  if (r.compared == 0) throw Error(reference + ": no reference node lies in " + s.mesh);
  if (r.outside > 0)
    cli::warn(std::to_string(r.outside) + " reference nodes lie outside " + s.mesh +
              " beyond --radius and were left out");
  cli::info("RMS " + std::to_string(r.rms) + " m, max " + std::to_string(r.max) + " m at reference node " +
            std::to_string(r.max_node) + "; " + std::to_string(r.compared) + " nodes compared, " +
            std::to_string(r.snapped) + " snapped");
  Json report;
  report["generator"] = std::string("xfem-rmserror ") + version;
  report["mesh"] = s.mesh;
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
  return report;
}

}  // namespace xfem
