// SPDX-License-Identifier: MIT
#include "xfem/system/integration_request.h"

#include <catch2/catch.hpp>

#include "xfem/core/json_io.h"

namespace {
xfem::Problem problem_with(const std::string& integration) {
  return xfem::parse_problem(
      xfem::Json::parse(R"({"material": {"E": 1, "nu": 0.3}, "integration": )" + integration + "}"), "p.json");
}
}  // namespace

TEST_CASE("integration_request: the command line's rule over problem.json's", "[integration_request]") {
  SECTION("nothing given: problem.json's rule, points and refine") {
    xfem::Problem p = problem_with(R"({"rule": "pieces", "order": 5, "points": 40, "refine": 2})");
    xfem::IntegrationRequest r;
    xfem::apply_integration_request(r, p);
    CHECK((p.rule == xfem::Problem::Rule::Conforming && !p.closed_form && !p.graded && p.order == 5));
    CHECK((r.points == 40 && r.refine == 2));
    CHECK(xfem::describe_integration(p, r.points, r.refine) == "--rule pieces --order 5");
  }
  SECTION("a rule given wins; --order replaces the order") {
    xfem::Problem p = problem_with(R"({"rule": "oversampling"})");
    xfem::IntegrationRequest r;
    r.rule = "conforming";
    r.order = 4;
    xfem::apply_integration_request(r, p);
    CHECK((p.rule == xfem::Problem::Rule::Conforming && p.closed_form && !p.graded && p.order == 4));
    CHECK(xfem::describe_integration(p, r.points, r.refine) == "--rule conforming --order 4");
    r.rule = "graded";
    xfem::apply_integration_request(r, p);
    CHECK((p.closed_form && p.graded));
    CHECK(xfem::describe_integration(p, r.points, r.refine) == "--rule graded");
    r.rule = "fast";
    xfem::apply_integration_request(r, p);
    CHECK((p.closed_form && p.fast && !p.graded && !p.uniform));
    CHECK(xfem::describe_integration(p, r.points, r.refine) == "--rule fast");
  }
  SECTION("--points or --refine alone imply the oversampling rule") {
    xfem::Problem p = problem_with(R"({"rule": "conforming"})");
    xfem::IntegrationRequest r;
    r.refine = 1;
    xfem::apply_integration_request(r, p);
    CHECK(p.rule == xfem::Problem::Rule::Oversampling);
    CHECK((r.points == 30 && r.refine == 1));
    CHECK(xfem::describe_integration(p, r.points, r.refine) == "--points 30, --refine 1");
  }
}
