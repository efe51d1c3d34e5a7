// SPDX-License-Identifier: MIT
// Global stiffness matrix and load vector of the cut body with its Dirichlet data (paper 3.4-3.6).
#include <cstdio>
#include <filesystem>
#include <string>

#include "xfem/system/assembly.h"
#include "xfem/system/contact_operator.h"
#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/core/fingerprint.h"
#include "xfem/system/linear_system.h"
#include "xfem/system/problem.h"
#include "xfem/system/integration_cost.h"
#include "xfem/system/integration_request.h"
#include "xfem/system/solution_provenance.h"
#include "xfem/system/reactions.h"
#include "xfem/core/version.h"

namespace {
std::string fixed3(double v) { char b[32]; std::snprintf(b, sizeof b, "%.3f", v); return b; }
}  // namespace

int main(int argc, char** argv) {
  auto tool = xfem::cli::make_tool(
      "xfem-assemble",
      "Assemble K u = f for an enriched mesh: element stiffness of formula (5) with the enriched basis\n"
      "(closed form for plain tets; tets with enriched DOFs split exactly along the cut, Gauss rules\n"
      "collapsed onto the cut front where crack-tip functions live), loads on the\n"
      "original DOFs, loads on the cuts' faces on the enriched DOFs, and the Dirichlet data of problem.json\n"
      "(docs/FORMATS.md); with \"contact\": the cuts' gap operator. Writes the system/\n"
      "directory xfem-solve reads (written atomically; system.json last): K.petsc, f.petsc, coordinates.petsc\n"
      "(PETSc's binary format, loaded in parallel by each rank), dirichlet.mtx, system.json; with --format mtx\n"
      "K.mtx, f.mtx, coordinates.mtx (Matrix Market text, e.g. for scipy.io.mmread) instead; and\n"
      "dirichlet_conditions.json (which condition fixes which DOF, for reaction forces). Units SI: metres,\n"
      "pascals, newtons.",
      "xfem-assemble out/enriched.vtu --cut cut.vtp --problem problem.json -o out/system");
  std::string input, problem_path, output;
  std::vector<std::string> cut_paths;
  xfem::IntegrationRequest request;
  std::string format = "petsc";
  auto& app = tool->app;
  app.add_option("enriched", input, "xfem-enrich output (.vtu)")->required();
  app.add_option("-c,--cut", cut_paths, "the cut surface given to xfem-classify (.vtp/.vtu/.vtk/.stl/.obj/.off/.msh); "
                                        "needed when the mesh has enriched DOFs (N > NP); several cuts: once per "
                                        "cut, as given to xfem-classify")
      ->allow_extra_args(false);
  app.add_option("-p,--problem", problem_path, "problem description (problem.json: material, materials (one "
                                               "per region of the mesh), integration, dirichlet, neumann, body_force, "
                                               "cut_loads, contact)")->required();
  app.add_option("--points", request.points, "the paper's oversampling rule (implies --rule oversampling): points "
                                     "requested per enriched tet, which is split into m^3 sub-tets, m the smallest "
                                     "with m^3 > points, one centroid point each (default: problem.json's "
                                     "integration.points, else 30 as in the paper)")
      ->check(xfem::cli::range(1, 100000));
  app.add_option("--refine", request.refine, "oversampling rule (implies --rule oversampling): in cut tets, split sub-tets "
                                     "the cut crosses into 8, up to this many times "
                                     "(0 = the paper's uniform rule; default: problem.json's integration.refine, "
                                     "else 0); small pieces cut off a tet then get integration points")
      ->check(xfem::cli::range(0, 8));
  app.add_option("--rule", request.rule, "integration of tets with enriched DOFs: conforming (the default: cut elements "
                                 "split exactly along the cut, one point per piece for the sign enrichment, Gauss "
                                 "rules collapsed onto the cut front where branch functions live, the blocks without them in "
                                 "closed form), graded (the same, the branch functions' points graded toward the front, "
                                 "--order unused), pieces (the same points for every block), uniform (as conforming "
                                 "with the points of order n before issue 35: n per direction everywhere, for comparisons), fast (as conforming "
                                 "with fewer points where the integrand is smooth on a piece's scale, --order unused; "
                                 "docs/METHOD.md) or "
                                 "oversampling (the paper's; default: problem.json's integration.rule, else conforming)")
      ->check(CLI::IsMember({"oversampling", "conforming", "graded", "pieces", "uniform", "fast"}));
  app.add_option("--order", request.order, "conforming rule: its order n, Gauss points per direction of the sub-tets (n in the "
                                           "distance to the front, n + 1 on pieces near it, fewer along it and far from it; "
                                           "docs/METHOD.md) (default: problem.json's integration.order, else 3)")
      ->check(xfem::cli::range(1, 20));
  app.add_option("-o,--output", output, "system directory (created, or replaced as a whole when it holds an older "
                                       "system)")->required();
  app.add_option("--format", format, "how K, f and the coordinates are stored: petsc (binary, default; what xfem-solve "
                                     "loads fastest, in parallel) or mtx (Matrix Market text, for scipy and other "
                                     "readers; xfem-solve reads it too)")
      ->check(CLI::IsMember({"petsc", "mtx"}));
  bool allow_large = false;
  app.add_flag("--allow-large", allow_large, "run even when the integration points are estimated above 2e8");
  xfem::cli::add_threads_option(*tool);
  return xfem::cli::run(*tool, argc, argv, [&] {
    xfem::cli::check_output_directory(output);
    const double start = xfem::cli::now();
    xfem::Problem problem = xfem::read_problem(problem_path);
    // K u = f is the small-strain model's: another model needs xfem-newton's nonlinear solve.
    xfem::require_linear_material(problem, "xfem-assemble writes the linear system of the small-strain model");
    xfem::apply_integration_request(request, problem);
    const int points = request.points, refine = request.refine;
    const bool conforming = problem.rule == xfem::Problem::Rule::Conforming;
    const xfem::EnrichedMesh em = xfem::read_enriched_mesh_to_solve(input, cut_paths);
    const xfem::TetMaterials materials = xfem::tet_materials(problem, em.mesh, input);
    const double estimate = xfem::check_integration_cost(em, problem, points, refine, allow_large, input);
    if (estimate > 1e7) xfem::cli::info("about " + xfem::short_number(estimate) + " integration points: this takes minutes");
    xfem::cli::detail("E " + std::to_string(problem.E) + " Pa, nu " + std::to_string(problem.nu) + ", " +
                      std::to_string(problem.dirichlet.size()) + " Dirichlet and " +
                      std::to_string(problem.neumann.size()) + " Neumann conditions, " +
                      xfem::describe_integration(problem, points, refine));
    const double read = xfem::cli::now() - start;

    xfem::AssemblyStats s;
    const xfem::LinearSystem system = xfem::assemble_system(em, problem, materials, points, refine, &s, xfem::cli::progress("assembling"));
    const double write_start = xfem::cli::now();
    // What the system was made from, so that xfem-solve can record it in u.mtx and later stages
    // can check the solution against the mesh, cut and problem they are given.
    const xfem::Provenance provenance = xfem::solution_provenance(em, problem_path);
    const xfem::DirichletGroups groups = xfem::dirichlet_groups(em.mesh, problem);
    // Contact between the cuts' faces: the gap operator xfem-solve iterates with (contact_operator.h).
    const xfem::ContactOperator contact = problem.contact.on ? xfem::contact_operator(em, problem, materials) : xfem::ContactOperator();
    if (problem.contact.on) xfem::cli::info("contact: " + std::to_string(contact.points()) + " nodes on the cut faces (contact conditions)");
    const std::string generator = std::string("xfem-assemble ") + xfem::version;
    // Written into the temporary directory with the system, before system.json and its manifest
    // (a kill cannot leave a system without them): which condition fixes which DOF (xfem-solve
    // sums the reaction forces per condition) and the fingerprints.
    xfem::write_linear_system(system, output, generator,
                              format == "mtx" ? xfem::SystemFormat::MatrixMarket : xfem::SystemFormat::Petsc,
                              [&](const std::string& tmp) {
                                xfem::write_dirichlet_groups(groups, tmp, generator);
                                if (problem.contact.on) xfem::write_contact_operator(contact, tmp);
                                xfem::write_json(xfem::Json{{"fingerprints", xfem::provenance_json(provenance)}},
                                                 (std::filesystem::path(tmp) / "provenance.json").string());
                              });
    const double write = xfem::cli::now() - write_start;

    long constrained = 0;
    for (const auto& piece : system.pieces) constrained += piece.constrained;
    xfem::cli::info("N = " + std::to_string(system.n) + " displacements (NP " + std::to_string(system.np) + ", NS " +
                    std::to_string(system.ns) + ", NB " + std::to_string(system.nb) + "), 3N = " +
                    std::to_string(3 * system.n) + " unknowns, " + std::to_string(system.K.nonZeros()) +
                    " non-zeros in the lower triangle, " + std::to_string(system.fixed.size()) + " fixed; " +
                    std::to_string(system.pieces.size()) + " piece(s), " + std::to_string(constrained) + " constrained");
    xfem::cli::info("tets: " + std::to_string(s.standard_tets) + " plain (closed form), " +
                    std::to_string(s.enriched_tets) + " enriched (" + (conforming ? "conforming rule)" : "oversampled)"));
    xfem::cli::info("time: read " + fixed3(read) + " s, pattern " + fixed3(s.pattern_seconds) + " s, plain tets " +
                    fixed3(s.standard_seconds) + " s, enriched tets " + fixed3(s.enriched_seconds) + " s, loads " +
                    fixed3(s.load_seconds) + " s, write " + fixed3(write) + " s");
    const std::vector<long> unsupported = xfem::unsupported_dofs(system.K, system.np);
    if (!unsupported.empty())
      xfem::cli::warn(std::to_string(unsupported.size()) + " enriched displacements have no integration point in "
                      "their support: the cut stays closed there (xfem-solve fixes them to 0); use the default "
                      "--rule conforming, or more --points / --refine");
    for (std::size_t i = 0; i < system.pieces.size(); ++i)
      if (!system.pieces[i].constrained)
        xfem::cli::warn("piece " + std::to_string(i + 1) + " (" + std::to_string(system.pieces[i].tets) +
                        " tets) has no Dirichlet condition: it can move rigidly, K is singular");
  });
}
