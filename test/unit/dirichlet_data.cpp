// SPDX-License-Identifier: MIT
#include "xfem/system/dirichlet_data.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "xfem/core/error.h"
#include "xfem/generate/box_mesh.h"
#include "xfem/system/assembly.h"
#include "xfem/system/reactions.h"
#include "enriched_test_meshes.h"

namespace {

// The box [0, 2]^3 of 2 x 2 x 2 cubes, uncut: node (i, j, k) is id i + 3 (j + 3 k), at (i, j, k).
xfem::EnrichedMesh cube() {
  return xfem_test::plain(xfem::box_mesh(Eigen::Vector3i(2, 2, 2), Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 2, 2)));
}

// A problem.json with the one Dirichlet condition `condition` (selector added: the whole box
// unless it has its own).
xfem::Problem problem_with(xfem::Json condition) {
  if (!condition.contains("selector")) condition["selector"] = {{"box", {{"lo", {0, 0, 0}}, {"hi", {2, 2, 2}}}}};
  xfem::Json j = {{"material", {{"E", 1e3}, {"nu", 0.3}}}, {"dirichlet", xfem::Json::array({condition})}};
  return xfem::parse_problem(j, "problem.json");
}

// The prescribed displacement of every node (3N, NaN where free).
Eigen::VectorXd prescribed(const xfem::EnrichedMesh& em, const xfem::Problem& p, double load = 1.0) {
  std::vector<long> fixed;
  std::vector<double> values;
  xfem::dirichlet_data(em, p, fixed, values, load);
  Eigen::VectorXd u = Eigen::VectorXd::Constant(3 * em.np, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < fixed.size(); ++i) u[fixed[i]] = values[i];
  return u;
}

Eigen::Vector3d node(const xfem::EnrichedMesh& em, long k) { return em.mesh.points.row(k).transpose(); }

std::string parse_error(const xfem::Json& condition) {
  try {
    problem_with(condition);
  } catch (const xfem::Error& e) {
    return e.what();
  }
  return "(no error)";
}

std::string data_error(const xfem::EnrichedMesh& em, const xfem::Problem& p, double load = 1.0) {
  try {
    prescribed(em, p, load);
  } catch (const xfem::Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("dirichlet_data: a rotation of 90 degrees about z through a centre, and half of it at load 0.5",
          "[dirichlet_data]") {
  const xfem::EnrichedMesh em = cube();
  const Eigen::Vector3d c(1, 1, 1);
  // The axis need not be a unit vector.
  const xfem::Problem p = problem_with(xfem::Json::parse(R"({"rotation": {"axis": [0, 0, 5], "angle_deg": 90, "center": [1, 1, 1]}})"));
  const Eigen::VectorXd u = prescribed(em, p);
  REQUIRE(u.allFinite());  // every component of every node fixed
  // Node (2, 1, 1): X - c = (1, 0, 0) turns to (0, 1, 0), so X moves to (1, 2, 1).
  CHECK((u.segment<3>(3 * (2 + 3 * (1 + 3 * 1))) - Eigen::Vector3d(-1, 1, 0)).norm() < 1e-15);
  const double h = std::sqrt(0.5);
  for (long k = 0; k < em.np; ++k) {
    const Eigen::Vector3d a = node(em, k) - c;
    // 90 degrees about z: (x, y, z) -> (-y, x, z); 45 degrees: the half-angle rotation.
    CHECK((u.segment<3>(3 * k) - (Eigen::Vector3d(-a.y(), a.x(), a.z()) - a)).norm() < 1e-15);
    const Eigen::Vector3d half = prescribed(em, p, 0.5).segment<3>(3 * k);
    CHECK((half - (Eigen::Vector3d(h * (a.x() - a.y()), h * (a.x() + a.y()), a.z()) - a)).norm() < 1e-15);
  }
}

TEST_CASE("dirichlet_data: a rotation of 120 degrees about (1, 1, 1) permutes the axes; the translation follows the load",
          "[dirichlet_data]") {
  const xfem::EnrichedMesh em = cube();
  const xfem::Problem p = problem_with(xfem::Json::parse(
      R"({"rotation": {"axis": [1, 1, 1], "angle_deg": 120, "translation": [0.1, -0.2, 0.3]}})"));
  const Eigen::Vector3d t(0.1, -0.2, 0.3);
  const Eigen::VectorXd u = prescribed(em, p), half = prescribed(em, p, 0.5);
  const Eigen::Matrix3d R60 = Eigen::AngleAxisd(M_PI / 3, Eigen::Vector3d(1, 1, 1).normalized()).toRotationMatrix();
  for (long k = 0; k < em.np; ++k) {
    const Eigen::Vector3d X = node(em, k);  // centre: the origin by default
    CHECK((u.segment<3>(3 * k) - (Eigen::Vector3d(X.z(), X.x(), X.y()) + t - X)).norm() < 1e-14);
    // Half way along the circle: 60 degrees, half the translation; its distance from the axis
    // is the node's (not the chord's midpoint, which lies closer to the axis).
    CHECK((half.segment<3>(3 * k) - (R60 * X + 0.5 * t - X)).norm() < 1e-14);
  }
}

TEST_CASE("dirichlet_data: value_array gives each selected node its tuple, times the load", "[dirichlet_data]") {
  xfem::EnrichedMesh em = cube();
  xfem::DataArray measured;
  measured.components = 3;
  Eigen::Matrix3d A;
  A << 0.01, -0.02, 0.005, 0.003, 0.02, -0.01, -0.004, 0.007, 0.015;
  for (long k = 0; k < em.np; ++k) {
    const Eigen::Vector3d v = A * node(em, k) + Eigen::Vector3d(1, 2, 3);
    measured.values.insert(measured.values.end(), {v.x(), v.y(), v.z()});
  }
  em.mesh.point_data["measured"] = measured;
  // The face z = 0 only.
  const xfem::Problem p = problem_with(xfem::Json::parse(
      R"({"name": "registered", "selector": {"box": {"lo": [0, 0, 0], "hi": [2, 2, 0]}}, "value_array": "measured"})"));
  const Eigen::VectorXd u = prescribed(em, p), quarter = prescribed(em, p, 0.25);
  int selected = 0;
  for (long k = 0; k < em.np; ++k) {
    if (node(em, k).z() != 0.0) {
      CHECK(std::isnan(u[3 * k]));
      continue;
    }
    ++selected;
    const Eigen::Vector3d v = A * node(em, k) + Eigen::Vector3d(1, 2, 3);
    for (int i = 0; i < 3; ++i) {
      CHECK(u[3 * k + i] == measured(k, i));
      CHECK(quarter[3 * k + i] == 0.25 * measured(k, i));
    }
    CHECK((u.segment<3>(3 * k) - v).norm() < 1e-15);
  }
  CHECK(selected == 9);

  SECTION("a non-finite value at an unselected node does not matter") {
    em.mesh.point_data["measured"].values[3 * (em.np - 1)] = std::numeric_limits<double>::infinity();
    CHECK(prescribed(em, p).segment<3>(0) == u.segment<3>(0));
  }
  SECTION("a non-finite value at a selected node") {
    em.mesh.point_data["measured"].values[3 * 4 + 1] = std::numeric_limits<double>::quiet_NaN();
    CHECK(data_error(em, p) == "problem.json: dirichlet[0] ('registered'): point array 'measured' (value_array) holds "
                               "a non-finite value at node 4 component y");
  }
  SECTION("a missing array") {
    em.mesh.point_data.erase("measured");
    CHECK(data_error(em, p) == "problem.json: dirichlet[0] ('registered'): the mesh has no point array 'measured' (value_array)");
  }
  SECTION("an array of 1 component") {
    xfem::DataArray scalar;
    scalar.values.assign(static_cast<std::size_t>(em.np), 0.0);
    em.mesh.point_data["measured"] = scalar;
    CHECK(data_error(em, p) == "problem.json: dirichlet[0] ('registered'): point array 'measured' (value_array) must "
                               "have 3 components per point, it has 1");
  }
}

TEST_CASE("dirichlet_data: value and exact values scale with the load; load 1 is the plain data", "[dirichlet_data]") {
  const xfem::EnrichedMesh em = cube();
  const xfem::Problem value = problem_with(xfem::Json::parse(R"({"value": [0.3, null, -0.7]})"));
  const Eigen::VectorXd full = prescribed(em, value), third = prescribed(em, value, 1.0 / 3);
  for (long k = 0; k < em.np; ++k) {
    CHECK(full[3 * k] == 0.3);
    CHECK(std::isnan(full[3 * k + 1]));
    CHECK(full[3 * k + 2] == -0.7);
    CHECK(third[3 * k] == 0.3 / 3);
    CHECK(third[3 * k + 2] == -0.7 / 3);
  }
  const xfem::Problem exact = problem_with(xfem::Json::parse(
      R"({"exact": {"linear": {"gradient": [[0.1, 0, 0], [0, 0.2, 0], [0, 0, -0.3]], "translation": [1, 2, 3]}}})"));
  const Eigen::VectorXd e = prescribed(em, exact), half = prescribed(em, exact, 0.5);
  for (long k = 0; k < em.np; ++k) {
    const Eigen::Vector3d X = node(em, k);
    const Eigen::Vector3d v(1 + 0.1 * X.x(), 2 + 0.2 * X.y(), 3 - 0.3 * X.z());
    CHECK((e.segment<3>(3 * k) - v).norm() < 1e-15);
    CHECK((half.segment<3>(3 * k) - 0.5 * v).norm() < 1e-15);
  }
  for (double bad : {0.0, -0.5, 1.5, std::numeric_limits<double>::quiet_NaN()})
    CHECK_THAT(data_error(em, value, bad), Catch::StartsWith("problem.json: the load factor of the Dirichlet data must lie in (0, 1], got "));
}

TEST_CASE("dirichlet_data: a rotation conflicting with a value condition is named; reactions count its 3 components",
          "[dirichlet_data]") {
  const xfem::EnrichedMesh em = cube();
  xfem::Json j = xfem::Json::parse(R"({
    "material": {"E": 1e3, "nu": 0.3},
    "dirichlet": [
      {"name": "turned", "selector": {"box": {"lo": [0, 0, 2], "hi": [2, 2, 2]}},
       "rotation": {"axis": [0, 0, 1], "angle_deg": 10, "center": [1, 1, 0]}},
      {"name": "base", "selector": {"box": {"lo": [0, 0, 0], "hi": [2, 2, 0]}}, "value": [0, 0, 0]}
    ]
  })");
  const xfem::Problem p = xfem::parse_problem(j, "problem.json");
  const xfem::DirichletGroups groups = xfem::dirichlet_groups(em.mesh, p);
  CHECK(groups.dofs[0].size() == 27);  // 9 nodes, 3 components each
  j["dirichlet"][1]["selector"]["box"]["hi"] = {2, 2, 2};
  CHECK(data_error(em, xfem::parse_problem(j, "problem.json")) ==
        "problem.json: dirichlet[1] ('base') and dirichlet[0] ('turned') prescribe different values for node 18 component x");
}

TEST_CASE("dirichlet_data: bad rotation and value_array conditions in problem.json", "[dirichlet_data]") {
  using xfem::Json;
  const Json rotation = Json::parse(R"({"axis": [0, 0, 1], "angle_deg": 30})");
  CHECK(parse_error(Json{{"rotation", rotation}}) == "(no error)");
  CHECK(parse_error(Json{{"name", "lid"}, {"rotation", rotation}, {"value", {0, 0, 0}}}) ==
        "problem.json: dirichlet[0] must have exactly one of value, exact, rotation, value_array");
  CHECK(parse_error(Json{{"rotation", rotation}, {"value_array", "u"}}) ==
        "problem.json: dirichlet[0] must have exactly one of value, exact, rotation, value_array");
  CHECK(parse_error(Json{{"name", "nothing"}}) ==
        "problem.json: dirichlet[0] must have exactly one of value, exact, rotation, value_array");
  CHECK(parse_error(Json{{"rotation", Json::parse(R"({"axis": [0, 0, 0], "angle_deg": 30})")}}) ==
        "problem.json: dirichlet[0].rotation.axis must not be zero");
  CHECK(parse_error(Json{{"rotation", Json::parse(R"({"axis": [0, 0, 1]})")}}) ==
        "problem.json: missing field 'dirichlet[0].rotation.angle_deg'");
  CHECK(parse_error(Json{{"rotation", Json::parse(R"({"axis": [0, 0, 1], "angle_deg": "30"})")}}) ==
        "problem.json: dirichlet[0].rotation.angle_deg must be a number");
  // A JSON file cannot hold an infinity (read_json refuses 1e999), a document built in code can.
  CHECK(parse_error(Json{{"rotation", {{"axis", {0, 0, 1}}, {"angle_deg", std::numeric_limits<double>::infinity()}}}}) ==
        "problem.json: dirichlet[0].rotation.angle_deg must be finite");
  CHECK(parse_error(Json{{"rotation", Json::parse(R"({"axis": [0, 1], "angle_deg": 30})")}}) ==
        "problem.json: dirichlet[0].rotation.axis must be a list of 3 numbers");
  CHECK(parse_error(Json{{"rotation", Json::parse(R"({"axis": [0, 0, 1], "angle_deg": 30, "centre": [0, 0, 0]})")}}) ==
        "problem.json: unknown key 'dirichlet[0].rotation.centre' (allowed here: axis, angle_deg, center, translation)");
  CHECK(parse_error(Json{{"rotation", Json::parse(R"({"axis": [0, 0, 1], "angle_deg": 30, "translation": [0, null, 0]})")}}) ==
        "problem.json: dirichlet[0].rotation.translation[1] must be a number");
  CHECK(parse_error(Json{{"rotation", rotation}, {"enriched_dofs", "exact"}}) ==
        "problem.json: dirichlet[0].enriched_dofs applies to an exact condition only");
  CHECK(parse_error(Json{{"value_array", 3}}) == "problem.json: dirichlet[0].value_array must be a string");
  CHECK(parse_error(Json{{"value_array", ""}}) == "problem.json: dirichlet[0].value_array must name a point array of the mesh");
}

TEST_CASE("dirichlet_data: an exact linear field on the boundary selector fixes the boundary's original DOFs only",
          "[dirichlet_data]") {
  // Hydrostatic compression u = -e X of a body's whole surface (e2e.contact_closed_organ): the
  // "boundary" selector with the exact field "linear" (u = translation + G X).
  const double e = 1e-3;
  const xfem::Json compress = xfem::Json::parse(R"({"selector": {"boundary": true},
      "exact": {"linear": {"gradient": [[-1e-3, 0, 0], [0, -1e-3, 0], [0, 0, -1e-3]]}}})");
  const xfem::EnrichedMesh em = cube();
  const xfem::Problem b = problem_with(compress);
  const Eigen::VectorXd ub = prescribed(em, b), quarter = prescribed(em, b, 0.25);
  const long inside = 1 + 3 * (1 + 3 * 1);  // node (1, 1, 1), the one inside the 2 x 2 x 2 cubes: free
  for (long k = 0; k < em.np; ++k) {
    CHECK(std::isnan(ub[3 * k]) == (k == inside));
    if (k == inside) continue;
    CHECK((ub.segment<3>(3 * k) + e * node(em, k)).norm() < 1e-18);
    CHECK((quarter.segment<3>(3 * k) + 0.25 * e * node(em, k)).norm() < 1e-18);
  }
  // The reactions group counts its 3 components per boundary node.
  CHECK(xfem::dirichlet_groups(em.mesh, b).dofs[0].size() == 3 * 26);
  // Cut through (sign-enriched nodes on both sides): every node is on the boundary of the
  // 1 x 1 x 2 cubes and gets -e X whatever its side; its enriched DOFs stay free.
  const xfem::EnrichedMesh cut = xfem_test::cut_box(0.25);
  REQUIRE(cut.ns == 8);
  std::vector<long> fixed;
  std::vector<double> values;
  xfem::dirichlet_data(cut, b, fixed, values, 1.0);
  REQUIRE(fixed.size() == static_cast<std::size_t>(3 * cut.np));
  for (std::size_t i = 0; i < fixed.size(); ++i) {
    REQUIRE(fixed[i] < 3 * cut.np);
    CHECK(std::abs(values[i] + e * cut.mesh.points(fixed[i] / 3, fixed[i] % 3)) < 1e-18);
  }
}

TEST_CASE("dirichlet_data: a linear field is the exact field linear, not a Dirichlet value of its own",
          "[dirichlet_data]") {
  using xfem::Json;
  const Json I = Json::parse(R"([[1, 0, 0], [0, 1, 0], [0, 0, 1]])");
  CHECK(parse_error(Json{{"exact", {{"linear", {{"gradient", I}}}}}}) == "(no error)");
  CHECK(parse_error(Json{{"linear", {{"gradient", I}}}}) ==
        "problem.json: unknown key 'dirichlet[0].linear' (allowed here: name, selector, value, exact, enriched_dofs, "
        "rotation, value_array)");
  CHECK(parse_error(Json{{"exact", {{"linear", {{"gradient", I}, {"center", {0, 0, 0}}}}}}}) ==
        "problem.json: unknown key 'dirichlet[0].exact.linear.center' (allowed here: gradient, translation)");
}

TEST_CASE("dirichlet_data: a Neumann condition on the boundary selector loads every boundary face", "[dirichlet_data]") {
  // The box [0, 2]^3: a traction t on its whole surface (area 24 m^2) adds up to 24 t; the one
  // node inside gets nothing.
  const xfem::EnrichedMesh em = cube();
  const xfem::Problem p = xfem::parse_problem(xfem::Json::parse(R"({"material": {"E": 1e3, "nu": 0.3},
      "neumann": [{"selector": {"boundary": true}, "traction": [1, -2, 3]}]})"), "problem.json");
  const Eigen::VectorXd f = xfem::load_vector(em, p);
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (long k = 0; k < em.np; ++k) total += f.segment<3>(3 * k);
  CHECK((total - 24 * Eigen::Vector3d(1, -2, 3)).norm() < 1e-12);
  CHECK(f.segment<3>(3 * (1 + 3 * (1 + 3 * 1))).norm() == 0.0);  // the inside node (1, 1, 1)
}
