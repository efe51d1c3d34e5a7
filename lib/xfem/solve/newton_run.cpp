// SPDX-License-Identifier: MIT
#include "xfem/solve/newton_run.h"

#include <chrono>

#include "xfem/core/cli.h"
#include "xfem/core/error.h"
#include "xfem/core/seconds_since.h"
#include "xfem/io/matrix_market.h"
#include "xfem/solve/contact_pressure_file.h"
#include "xfem/solve/newton.h"
#include "xfem/solve/newton_follower_load.h"
#include "xfem/system/contact_operator.h"
#include "xfem/system/cut_loads.h"
#include "xfem/system/assembly.h"
#include "xfem/system/deformed_volume_at_points.h"
#include "xfem/system/dirichlet_data.h"
#include "xfem/system/pieces.h"
#include "xfem/system/reactions.h"
#include "xfem/system/solution_provenance.h"

namespace xfem {

namespace {

Json steps_json(const std::vector<LoadStep>& steps) {
  Json out = Json::array();
  for (const LoadStep& s : steps) {
    Json residuals = Json::array(), lengths = Json::array();
    for (const NewtonIteration& it : s.iterations) {
      residuals.push_back(it.residual);
      lengths.push_back(it.step);
    }
    out.push_back({{"load", s.load},
                   {"converged", s.converged},
                   {"iterations", static_cast<long>(s.iterations.size()) - 1 - s.multiplier_updates},
                   {"relative_residuals", residuals},
                   {"line_search_steps", lengths},
                   {"projected_tangents", s.projected},
                   {"tangents", s.tangents},
                   {"factorizations", s.factorizations},
                   {"linear_iterations", s.linear_iterations},
                   {"assemble_seconds", s.assemble_seconds},
                   {"factor_seconds", s.factor_seconds},
                   {"solve_seconds", s.solve_seconds}});
    if (s.has_contact)
      out.back()["contact"] = {{"active_points", s.active_points},
                               {"multiplier_updates", s.multiplier_updates},
                               {"max_penetration", s.max_penetration},
                               {"tolerance", s.contact_tolerance},
                               {"force", s.contact_force}};
  }
  return out;
}

void require_constrained_pieces(const EnrichedMesh& em, const Problem& problem, const std::vector<long>& fixed) {
  const std::vector<Piece> pieces = find_pieces_held_by(em, fixed);
  for (std::size_t i = 0; i < pieces.size(); ++i)
    if (!pieces[i].constrained)
      throw Error(problem.file + ": piece " + std::to_string(i + 1) + " of " + std::to_string(pieces.size()) + " (" +
                  std::to_string(pieces[i].tets) + " tets) has no Dirichlet condition: it can move rigidly");
}

}  // namespace

void run_newton(const EnrichedMesh& em, const Problem& problem, const NewtonRun& run, Json& report) {
  if (problem.rule != Problem::Rule::Conforming)
    throw Error(problem.file + ": xfem-newton integrates with the conforming rule only (integration.rule \"conforming\", "
                "the default)");
  const MaterialLaw law{problem.model, lame(problem.E, problem.nu)};
  auto clock = std::chrono::steady_clock::now();
  NonlinearProblem p;
  p.em = &em;
  p.law = law;
  p.f = load_vector(em, problem);
  // The cuts' faces: tractions dead on the reference faces, pressures following the deformed faces.
  add_dead_cut_tractions(em, problem, p.f);
  const FollowerCutLoad follower = follower_cut_load(em, problem);
  NewtonFollowerLoad follower_term(em, follower);
  if (!follower.empty()) p.terms.push_back(&follower_term);
  ContactOperator contact;
  if (problem.contact.on) contact = run.materials ? contact_operator(em, problem, *run.materials) : contact_operator(em, problem);
  NewtonContact contact_term(contact, em.np, run.contact);
  if (problem.contact.on) p.terms.push_back(&contact_term);
  p.dirichlet = [&](double s, std::vector<long>& fixed, std::vector<double>& values) {
    dirichlet_data(em, problem, fixed, values, s);
  };
  {
    std::vector<long> fixed;
    std::vector<double> values;
    p.dirichlet(1.0, fixed, values);
    require_constrained_pieces(em, problem, fixed);
  }
  BodyIntegration body = integrate_body(em, problem.order);
  body.materials = run.materials;
  p.body = &body;
  const double integrate_seconds = seconds_since(clock);
  cli::info(std::string("material ") + material_model_name(problem.model) + ", " + std::to_string(body.points) +
            " integration points in " + std::to_string(em.tets()) + " tets (" + cli::three_digits(integrate_seconds) +
            " s), " + std::to_string(problem.load_steps) + " load step(s)");
  NewtonOptions o;
  o.load_steps = problem.load_steps;
  o.max_iterations = run.max_iterations;
  o.rtol = run.rtol;
  o.ordering = run.ordering;
  o.solver = run.solver;
  o.info = [](const std::string& m) { cli::info(m); };
  o.detail = [](const std::string& m) { cli::detail(m); };
  clock = std::chrono::steady_clock::now();
  const NewtonResult result = solve_newton(p, o);
  const double solve_seconds = seconds_since(clock);
  if (!result.u.allFinite()) throw Error(problem.file + ": the solution is not finite; no output written");

  // Reactions: r(u) - f on the constrained DOFs, 0 on the free ones (the residual there).
  // The loads at u: the follower pressure's at the deformed faces.
  Eigen::VectorXd f = p.f;
  add_follower_forces(em, follower, result.u, 1.0, f, nullptr);
  Eigen::VectorXd reactions = Eigen::VectorXd::Zero(3 * em.n);
  for (long d : result.fixed) reactions[d] = result.r[d] - f[d];
  // Forces balance in the deformed body: moments about the origin at the nodes' current places.
  Eigen::MatrixXd coordinates = em.mesh.points;
  for (long k = 0; k < em.np; ++k) coordinates.row(k) += result.u.segment<3>(3 * k).transpose();
  const std::vector<Resultant> conditions =
      condition_reactions(dirichlet_groups(em.mesh, problem), reactions, coordinates);
  for (const Resultant& r : conditions) cli::info(describe_reaction(r, true));
  long iterations = 0;
  for (const LoadStep& s : result.steps) iterations += static_cast<long>(s.iterations.size()) - 1 - s.multiplier_updates;
  // The volume the body keeps, on the solve's own points (deformed.vtu's straight-edged cells
  // differ where F varies: docs/VERIFICATION.md "Large deformation").
  const PointVolume volume = deformed_volume_at_points(em, body, result.u);
  const auto change = [](const PointVolume::Part& p) { return p.before > 0 ? p.after / p.before - 1.0 : 0.0; };
  cli::info("volume on the integration points " + cli::three_digits(volume.body.before) + " m^3 -> " +
            cli::three_digits(volume.body.after) + " m^3 (" + cli::three_digits(100 * change(volume.body)) +
            " %; plain tets " + cli::three_digits(100 * change(volume.plain)) + " %, sign-enriched " +
            cli::three_digits(100 * change(volume.sign)) + " %, branch-enriched " +
            cli::three_digits(100 * change(volume.branch)) + " %); largest det F " + cli::three_digits(volume.body.max_J) +
            " in tet " + std::to_string(volume.body.max_J_tet) + ", in a plain tet " +
            cli::three_digits(volume.plain.max_J));
  const auto part_json = [&](const PointVolume::Part& p) {
    return Json{{"tets", p.tets}, {"before", p.before}, {"after", p.after}, {"relative_change", change(p)},
                {"max_det_F", p.max_J}, {"max_det_F_tet", p.max_J_tet},
                {"max_det_F_centroid", {p.max_J_at.x(), p.max_J_at.y(), p.max_J_at.z()}}};
  };
  report["volume"] = {{"body", part_json(volume.body)},
                      {"plain_tets", part_json(volume.plain)},
                      {"sign_tets", part_json(volume.sign)},
                      {"branch_tets", part_json(volume.branch)}};
  report["backend"] = run.backend;
  report["processes"] = run.processes;
  report["n"] = em.n;
  report["dofs"] = 3 * em.n;
  report["fixed_dofs"] = static_cast<long>(result.fixed.size());
  report["material_model"] = material_model_name(problem.model);
  report["load_steps"] = problem.load_steps;
  report["integration_points"] = body.points;
  report["newton_iterations"] = iterations;
  report["factorizations"] = result.factorizations;
  report["steps"] = steps_json(result.steps);
  report["relative_residual"] = result.steps.back().final_residual;
  report["strain_energy"] = result.energy;
  report["min_det_F"] = result.min_J;
  report["reactions"] = reactions_json(conditions, applied_load(f, coordinates), true);
  ContactOutcome touching;
  if (!follower.empty()) {
    const Eigen::Vector3d above = follower_face_force(follower, em, result.u);
    report["cut_pressure"] = {{"points", static_cast<long>(follower.points.size())},
                              {"reference_area", follower.area},
                              {"force_on_faces_above", {above.x(), above.y(), above.z()}}};
  }
  if (problem.contact.on) {
    touching = contact_term.outcome(result.u);
    cli::info("contact: " + std::to_string(touching.active) + " of " + std::to_string(contact.points()) +
              " contact nodes in contact (area " + cli::three_digits(touching.active_area) + " m^2), " +
              std::to_string(touching.updates) + " multiplier updates; largest penetration " +
              cli::three_digits(touching.max_penetration) + " m (tolerance " + cli::three_digits(touching.tolerance) +
              " m), normal force " + cli::three_digits(touching.force) + " N");
    const long M = contact.points();
    report["contact"] = Json{{"points", M},
                             {"area", M > 0 ? contact.weight.sum() : 0.0},
                             {"active_points", touching.active},
                             {"active_area", touching.active_area},
                             {"multiplier_updates", touching.updates},
                             {"max_penetration", touching.max_penetration},
                             {"tolerance", touching.tolerance},
                             {"opened_volume", touching.opened_volume},
                             {"force", touching.force},
                             {"max_pressure", M > 0 ? touching.pressure.maxCoeff() : 0.0},
                             {"gap", "reference configuration (small sliding)"}};
  }
  report["integrate_seconds"] = integrate_seconds;
  report["analyze_seconds"] = result.analyze_seconds;
  report["solve_seconds"] = solve_seconds;
  if (!run.root) return;  // rank 0 writes
  if (!run.reactions_path.empty()) write_vector(reactions, run.reactions_path);
  if (!run.contact_pressure_path.empty()) write_contact_pressure(contact, touching.pressure, em.np, run.contact_pressure_path);
  write_vector(result.u, run.output, provenance_comments(solution_provenance(em, run.problem_path)));
  if (!run.report_path.empty()) write_json(report, run.report_path);
}

}  // namespace xfem
