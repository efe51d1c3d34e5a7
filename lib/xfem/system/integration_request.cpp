// SPDX-License-Identifier: MIT
#include "xfem/system/integration_request.h"

namespace xfem {

void apply_integration_request(IntegrationRequest& request, Problem& problem) {
  if (!request.rule.empty()) {
    problem.rule = request.rule == "oversampling" ? Problem::Rule::Oversampling : Problem::Rule::Conforming;
    problem.closed_form = request.rule != "pieces";
    problem.graded = request.rule == "graded";
    problem.uniform = request.rule == "uniform";
    problem.fast = request.rule == "fast";
  } else if (request.points > 0 || request.refine >= 0) {
    problem.rule = Problem::Rule::Oversampling;
  }
  if (request.order > 0) problem.order = request.order;
  if (request.points == 0) request.points = problem.points;
  if (request.refine < 0) request.refine = problem.refine;
}

std::string describe_integration(const Problem& problem, int points, int refine) {
  if (problem.rule != Problem::Rule::Conforming)
    return "--points " + std::to_string(points) + ", --refine " + std::to_string(refine);
  if (problem.graded) return "--rule graded";
  if (problem.fast) return "--rule fast";
  if (problem.uniform) return "--rule uniform --order " + std::to_string(problem.order);
  return std::string(problem.closed_form ? "--rule conforming" : "--rule pieces") + " --order " +
         std::to_string(problem.order);
}

}  // namespace xfem
