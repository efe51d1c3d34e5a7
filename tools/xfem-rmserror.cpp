// SPDX-License-Identifier: MIT
// RMS error of a solution against a reference solution (DESIGN.md, "The benchmark", RMS (5.1)).
#include <cstdio>

#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/post/solution_comparison.h"

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
  bool standard_dofs_only = false;
  app.add_flag("--standard-dofs-only", standard_dofs_only,
               "a solution or reference solution of more than 3 NP values given for a mesh without its cut: compare "
               "its first 3 NP values (the standard DOFs), the enrichment left out (a regression check of the solve's "
               "values, not the error of a displacement field); without it such a solution is an error");
  app.add_option("-o,--output", output, "JSON report");
  app.add_option("--max", max_rms, "exit 1 when the RMS error exceeds this (metres): a golden-file check");
  app.add_option("--radius", radius, "reference nodes outside the mesh but this close are evaluated at the nearest "
                                     "tet (metres; default 1e-6 of the mesh's bounding-box diagonal)")
      ->check(xfem::cli::non_negative());
  app.get_option("--max")->check(xfem::cli::non_negative());
  app.callback([&] {  // during parsing, so that a missing one is a usage error (exit 2)
    if (reference.empty() && exact_path.empty()) throw CLI::RequiredError("--reference or --exact");
  });
  xfem::cli::add_threads_option(*tool);
  return xfem::cli::run(*tool, argc, argv, [&] {
    if (!output.empty()) xfem::cli::check_output(output, {".json"}, true);
    const xfem::ComparedSolution compared{mesh_path, cut_path, solution, standard_dofs_only};
    const xfem::Json report = exact_path.empty()
                                  ? xfem::compare_with_reference(compared, reference, reference_solution, radius)
                                  : xfem::compare_with_exact(compared, exact_path, samples);
    if (!output.empty()) xfem::write_json(report, output);
    const double rms = report["rms"].get<double>();
    std::printf("%.17g\n", rms);
    if (max_rms >= 0 && !(rms <= max_rms))  // a NaN fails too
      throw xfem::Error("RMS error " + std::to_string(rms) + " exceeds --max " + std::to_string(max_rms));
  });
}
