// SPDX-License-Identifier: MIT
// Stress intensity factors K_I, K_II, K_III and the energy release rate G along the cut front, by
// the interaction integral in its domain form (lib/xfem/stress_intensity.h).
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "xfem/core/atomic_file.h"
#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/io/matrix_market.h"
#include "xfem/system/cut_loads.h"
#include "xfem/system/problem.h"
#include "xfem/enrich/enriched_mesh.h"
#include "xfem/fracture/stress_intensity.h"
#include "xfem/post/front_face_loads.h"
#include "xfem/post/solution_provenance_check.h"

namespace {

// K along the front, one curve per factor, by gnuplot (pngcairo), written under a temporary name.
void plot(const std::vector<xfem::FrontSif>& points, const std::string& png, const std::string& title) {
  xfem::write_atomically(png, [&](const std::string& tmp) {
    FILE* gp = popen("gnuplot", "w");
    if (!gp) throw xfem::Error(png + ": cannot run gnuplot");
    std::ostringstream s;
    s << "set terminal pngcairo size 900,600\nset output '" << tmp << "'\n"
      << "set title '" << title << "' noenhanced\nset xlabel 'arc length along the front (m)'\n"
      << "set ylabel 'K (Pa m^{1/2})'\nset key outside right\nset grid\n"
      << "plot '-' u 1:2 w lp pt 7 t 'K_I', '-' u 1:2 w lp pt 5 t 'K_{II}', '-' u 1:2 w lp pt 9 t 'K_{III}'\n";
    for (int m = 0; m < 3; ++m) {
      int chain = points.empty() ? 0 : points[0].chain;
      for (const auto& p : points) {
        if (p.chain != chain) s << "\n";  // a gap between chains
        chain = p.chain;
        s << p.s << " " << (m == 0 ? p.K1 : m == 1 ? p.K2 : p.K3) << "\n";
      }
      s << "e\n";
    }
    const std::string text = s.str();
    std::fwrite(text.data(), 1, text.size(), gp);
    if (pclose(gp) != 0) throw xfem::Error(png + ": gnuplot failed (is gnuplot with the pngcairo terminal installed?)");
  });
}

}  // namespace

int main(int argc, char** argv) {
  auto tool = xfem::cli::make_tool(
      "xfem-front",
      "Stress intensity factors K_I, K_II, K_III and the energy release rate G at points along the cut\n"
      "front, by the interaction integral in its 3D domain form (auxiliary Williams fields in the local\n"
      "front frame, round the front's osculating circle with the curvature terms of a curved front;\n"
      "weight q = radial ramp x tangential hat, interpolated from the nodes; with cut_loads on the\n"
      "evaluated cut or --contact-pressure, the crack-face term of the loaded faces). Plane strain\n"
      "at interior front points; points at an end of the front (on the body's surface) are marked.\n"
      "Writes the front as a polyline with point arrays K_I, K_II, K_III, G (SI units) and/or a CSV\n"
      "(docs/FORMATS.md \"front.vtp\", \"front.csv\").",
      "xfem-front enriched.vtu --cut cut.vtp --solution u.mtx --problem problem.json \\\n"
      "      -o front.vtp --csv front.csv --png front.png --radius 0.01");
  std::string input, solution, problem_path, output, csv, png, title, contact_path;
  std::vector<std::string> cut_paths;
  int front_of = 0;
  xfem::FrontSifOptions options;
  auto& app = tool->app;
  app.add_option("enriched", input, "xfem-enrich output (.vtu)")->required();
  app.add_option("-c,--cut", cut_paths, "the cut surface the mesh was classified with; several cuts: once per cut, "
                                        "as given to xfem-classify")
      ->required()
      ->allow_extra_args(false);
  app.add_option("--front-of", front_of, "with several cuts: the cut (0, 1, ...) whose front to evaluate (default 0)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("-s,--solution", solution, "xfem-solve output: Matrix Market vector of 3N values")->required();
  app.add_option("-p,--problem", problem_path, "problem.json (material E, nu, or each region's (materials): a "
                                               "front point's domain must lie in one; body force; cut_loads)")->required();
  app.add_option("--contact-pressure", contact_path, "xfem-solve --contact-pressure's file (the same solve): the contact "
                                                    "pressure on the evaluated cut's faces, a face load in K's crack-face term");
  app.add_option("-o,--output", output, "front polyline with K_I, K_II, K_III, G (.vtp)");
  app.add_option("--csv", csv, "front as CSV: chain, arc_length, x, y, z, K_I, K_II, K_III, G, end");
  app.add_option("--png", png, "plot K along the front (gnuplot)");
  app.add_option("--title", title, "plot title (default: the input's name)");
  app.add_option("--radius", options.radius, "domain radius R around the front, metres (default: 2.5 x the mean edge "
                                             "length of the tets the front crosses); keep it inside the body")
      ->check(CLI::PositiveNumber);
  app.add_option("--plateau", options.plateau, "fraction of R where the radial weight is 1 (default 0.4)")
      ->check(CLI::Range(0.0, 0.99));
  app.add_option("--spacing", options.spacing, "distance between front points, also the half-width of the "
                                               "tangential weight, metres (default: R)")
      ->check(CLI::PositiveNumber);
  std::string auxiliary = "curvilinear";
  app.add_option("--auxiliary", auxiliary,
                 "auxiliary fields: curvilinear (default: Williams fields round the front's osculating circle, "
                 "with the curvature terms), uncorrected (the same without the incompatibility and "
                 "non-equilibrium terms), tangent (the straight tangent line's fields); the last two for studies")
      ->check(CLI::IsMember({"curvilinear", "uncorrected", "tangent"}));
  app.add_option("--order", options.order, "Gauss points per direction of the conforming rule (default 4)")
      ->check(CLI::Range(1, 20));
  app.add_flag("--allow-large", options.allow_large, "run even when the front points, the evaluations of the weight "
                                                     "or the integrand evaluations are estimated beyond their limits "
                                                     "(1e5, 1e8, 3e8; docs/FORMATS.md \"front.csv\")");
  app.callback([&] {
    if (output.empty() && csv.empty() && png.empty()) throw CLI::RequiredError("-o, --csv or --png");
  });
  xfem::cli::add_threads_option(*tool);
  return xfem::cli::run(*tool, argc, argv, [&] {
    const xfem::Problem problem = xfem::read_problem(problem_path);
    xfem::require_linear_material(problem, "xfem-front's interaction integral is small-strain");
    std::vector<std::string> warnings;
    xfem::EnrichedMesh em = xfem::read_enriched_mesh_cuts(input, cut_paths, &warnings);
    xfem::check_solution_provenance({solution, input, cut_paths, problem_path}, em);  // before select_front_of
    xfem::check_cut_indices(problem, xfem::cut_count(em));
    xfem::select_front_of(em, front_of, input);
    // Loads on the evaluated cut's faces: the interaction integral's crack-face term.
    const xfem::FaceContactPressure contact = xfem::front_face_loads(problem, problem_path, em, front_of, contact_path, options);
    if (!contact.pressure.empty()) options.contact_pressure = &contact;
    for (const auto& w : warnings) xfem::cli::warn(w);
    if (em.front.empty()) throw xfem::Error(input + ": the cut has no front inside the body (nothing to compute)");
    const Eigen::VectorXd u = xfem::read_vector(solution);
    if (u.size() != 3 * em.n)
      throw xfem::Error(solution + ": " + std::to_string(u.size()) + " values, expected 3N = " +
                        std::to_string(3 * em.n) + " for " + input);
    options.auxiliary = auxiliary == "tangent"       ? xfem::FrontAuxiliary::Tangent
                        : auxiliary == "uncorrected" ? xfem::FrontAuxiliary::CurvilinearUncorrected
                                                     : xfem::FrontAuxiliary::Curvilinear;
    const double R = options.radius > 0 ? options.radius : xfem::default_domain_radius(em);
    options.radius = R;
    const xfem::TetMaterials materials = xfem::tet_materials(problem, em.mesh, input);
    options.materials = &materials;
    const auto points = xfem::front_stress_intensity(em, u, problem.E, problem.nu, problem.body_force, options,
                                                     xfem::cli::progress("interaction integrals"));
    int reaching = 0;
    for (const auto& p : points) reaching += p.reaches_surface;
    if (reaching > 0)
      xfem::cli::warn("the domains of " + std::to_string(reaching) + " of " + std::to_string(points.size()) +
                      " front points reach the body's surface away from the front's ends: their K miss a surface "
                      "term and may be wrong; reduce --radius (now " + std::to_string(R) + " m)");
    xfem::check_front_finite(points, solution);
    double kmin = 0, kmax = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      kmin = i == 0 ? points[i].K1 : std::min(kmin, points[i].K1);
      kmax = i == 0 ? points[i].K1 : std::max(kmax, points[i].K1);
    }
    xfem::cli::info(std::to_string(points.size()) + " front points, domain radius " + std::to_string(R) +
                    " m: K_I from " + std::to_string(kmin) + " to " + std::to_string(kmax) + " Pa m^0.5");
    if (!output.empty()) xfem::write_front_vtp(points, output);
    if (!csv.empty()) xfem::write_front_csv(points, csv);
    if (!png.empty()) plot(points, png, title.empty() ? input : title);
  });
}
