// SPDX-License-Identifier: MIT
#include "xfem/system/problem.h"

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <map>
#include <set>

#include "xfem/generate/box_mesh.h"
#include "xfem/core/error.h"

namespace {

xfem::Json beam() {
  return xfem::Json::parse(R"({
    "material": {"E": 300e3, "nu": 0.35},
    "integration": {"points": 30},
    "dirichlet": [
      {"name": "fixed end", "selector": {"half_spaces": [{"point": [0, 0, 0.001], "normal": [0, 0, -1]}]},
       "value": [0, 0, 0]},
      {"name": "pulled edge", "selector": {"half_spaces": [{"point": [0, 0, 0.199], "normal": [0, 0, 1]},
                                                          {"point": [0.001, 0, 0], "normal": [-1, 0, 0]}]},
       "value": [null, null, 0.02]}
    ],
    "neumann": [{"selector": {"box": {"lo": [0, 0, 0.2], "hi": [0.03, 0.06, 0.2]}}, "traction": [0, 0, 1e3]}],
    "body_force": [0, 0, -9810]
  })");
}

// The one-line message parse_problem throws for `j`.
std::string error_of(const xfem::Json& j) {
  try {
    xfem::parse_problem(j, "problem.json");
  } catch (const xfem::Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("problem: the paper's beam problem parses", "[problem]") {
  const xfem::Problem p = xfem::parse_problem(beam(), "problem.json");
  CHECK(p.E == 300e3);
  CHECK(p.nu == 0.35);
  CHECK(p.points == 30);
  REQUIRE(p.dirichlet.size() == 2);
  CHECK(p.dirichlet[1].name == "pulled edge");
  CHECK(p.dirichlet[1].selector.planes.size() == 2);
  CHECK(!p.dirichlet[1].value[0]);
  CHECK(*p.dirichlet[1].value[2] == 0.02);
  REQUIRE(p.neumann.size() == 1);
  CHECK(p.neumann[0].selector.kind == xfem::Selector::Kind::Box);
  CHECK(p.body_force.z() == -9810);
}

TEST_CASE("problem: selectors pick nodes by half-spaces (strict), boxes (closed) and point arrays", "[problem]") {
  xfem::TetMesh m = xfem::box_mesh({3, 3, 4}, {0, 0, 0}, {0.03, 0.06, 0.2});
  const xfem::Problem p = xfem::parse_problem(beam(), "problem.json");
  // z < 0.001: the 16 nodes of the face z = 0; z > 0.199 and x < 0.001: the 4 of the edge.
  CHECK(xfem::select_nodes(p.dirichlet[0].selector, m, "fixed").size() == 16);
  const auto edge = xfem::select_nodes(p.dirichlet[1].selector, m, "pulled");
  REQUIRE(edge.size() == 4);
  for (int k : edge) CHECK((m.points(k, 0) == 0.0 && m.points(k, 2) == 0.2));
  CHECK(xfem::select_nodes(p.neumann[0].selector, m, "top").size() == 16);
  // Strictness: a plane through a node row does not select it.
  xfem::Selector on_plane;
  on_plane.planes = {{Eigen::Vector3d(0, 0, 0.2), Eigen::Vector3d(0, 0, 1)}};
  CHECK_THROWS_WITH(xfem::select_nodes(on_plane, m, "problem.json: dirichlet[0] ('top')"),
                    "problem.json: dirichlet[0] ('top') selects no node");
  xfem::Selector named;
  named.kind = xfem::Selector::Kind::PointArray;
  named.array = "clamp";
  CHECK_THROWS_WITH(xfem::select_nodes(named, m, "problem.json: dirichlet[2]"),
                    "problem.json: dirichlet[2]: the mesh has no point array 'clamp'");
  m.point_data["clamp"] = xfem::make_array(xfem::DataArray::Type::Int32, 1, m.points.rows());
  m.point_data["clamp"].values[5] = 1;
  CHECK(xfem::select_nodes(named, m, "x") == std::vector<int>{5});
}

TEST_CASE("problem: the boundary selector picks the nodes of faces of one tet, on a box and on a curved body",
          "[problem]") {
  // A 3 x 3 x 4 grid of cubes: 4 x 4 x 5 = 80 nodes, of which the 2 x 2 x 3 = 12 inside are left out.
  const xfem::TetMesh m = xfem::box_mesh({3, 3, 4}, {0, 0, 0}, {0.03, 0.06, 0.2});
  xfem::Json j = beam();
  j["dirichlet"][0]["selector"] = xfem::Json::parse(R"({"boundary": true})");
  const xfem::Problem p = xfem::parse_problem(j, "problem.json");
  REQUIRE(p.dirichlet[0].selector.kind == xfem::Selector::Kind::Boundary);
  const std::vector<int> nodes = xfem::select_nodes(p.dirichlet[0].selector, m, "boundary");
  CHECK(nodes.size() == 68);
  std::vector<int> on_faces;  // by coordinates: a node on a face of the box
  for (int k = 0; k < m.points.rows(); ++k) {
    const Eigen::Vector3d x = m.points.row(k);
    if ((x.array() <= 1e-12).any() || (x.array() >= Eigen::Array3d(0.03, 0.06, 0.2) - 1e-12).any()) on_faces.push_back(k);
  }
  CHECK(nodes == on_faces);
  // A curved body: the tets of the grid whose centroid lies in a ball (a staircase surface that no
  // box or half-space selects). Every kept node on a face of exactly one kept tet is a boundary
  // node; the node at the ball's centre, with all its tets kept, is not.
  const xfem::TetMesh g = xfem::box_mesh({6, 6, 6}, {-1, -1, -1}, {1, 1, 1});
  xfem::TetMesh ball;
  ball.points = g.points;
  std::vector<int> kept;
  for (int t = 0; t < g.tets.rows(); ++t) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int i = 0; i < 4; ++i) c += g.points.row(g.tets(t, i)).transpose() / 4;
    if (c.norm() < 0.8) kept.push_back(t);
  }
  ball.tets.resize(static_cast<Eigen::Index>(kept.size()), 4);
  for (std::size_t t = 0; t < kept.size(); ++t) ball.tets.row(static_cast<Eigen::Index>(t)) = g.tets.row(kept[t]);
  const std::vector<int> surface = xfem::boundary_nodes(ball);
  std::map<std::array<int, 3>, int> count;
  for (int t = 0; t < ball.tets.rows(); ++t)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f{};
      for (int c = 0, i = 0; c < 4; ++c)
        if (c != skip) f[i++] = ball.tets(t, c);
      std::sort(f.begin(), f.end());
      ++count[f];
    }
  std::set<int> expected;
  for (const auto& [f, n] : count)
    if (n == 1) expected.insert(f.begin(), f.end());
  CHECK(surface == std::vector<int>(expected.begin(), expected.end()));
  int centre = -1;
  for (int k = 0; k < g.points.rows(); ++k)
    if (g.points.row(k).norm() < 1e-12) centre = k;
  REQUIRE(centre >= 0);
  CHECK(!std::binary_search(surface.begin(), surface.end(), centre));
  CHECK(surface.size() > 20);
  // Nodes in no kept tet are on no face: not selected.
  for (int k : surface) CHECK(g.points.row(k).norm() < 1.5);
  // No tet: nothing to select, named.
  xfem::TetMesh empty;
  empty.points = g.points;
  CHECK_THROWS_WITH(xfem::select_nodes(p.dirichlet[0].selector, empty, "problem.json: dirichlet[0]"),
                    "problem.json: dirichlet[0] selects no node (the mesh has no tet)");
}

TEST_CASE("problem: a bad boundary selector gives one error line", "[problem]") {
  xfem::Json j = beam();
  j["dirichlet"][0]["selector"] = xfem::Json::parse(R"({"boundary": false})");
  CHECK(error_of(j) ==
        "problem.json: dirichlet[0].selector.boundary must be true (the nodes of the mesh's boundary faces), got false");
  j["dirichlet"][0]["selector"] = xfem::Json::parse(R"({"boundary": 1})");
  CHECK(error_of(j) ==
        "problem.json: dirichlet[0].selector.boundary must be true (the nodes of the mesh's boundary faces), got 1");
  j["dirichlet"][0]["selector"] = xfem::Json::parse(R"({"boundary": "yes"})");
  CHECK_THAT(error_of(j), Catch::Contains("selector.boundary must be true"));
  j["dirichlet"][0]["selector"] = xfem::Json::parse(R"({"boundary": true, "box": {"lo": [0, 0, 0], "hi": [1, 1, 1]}})");
  CHECK(error_of(j) ==
        "problem.json: dirichlet[0].selector must have exactly one of half_spaces, box, point_array, group, boundary");
  j["neumann"][0]["selector"] = xfem::Json::parse(R"({"boundary": false})");
  j["dirichlet"][0]["selector"] = xfem::Json::parse(R"({"boundary": true})");
  CHECK_THAT(error_of(j), Catch::StartsWith("problem.json: neumann[0].selector.boundary must be true"));
}

TEST_CASE("problem: each bad problem file gives one error line naming the item", "[problem]") {
  xfem::Json j = beam();
  SECTION("missing field") {
    j["material"].erase("E");
    CHECK(error_of(j) == "problem.json: missing field 'material.E'");
  }
  SECTION("missing material") {
    j.erase("material");
    CHECK(error_of(j) == "problem.json: missing field 'material'");
  }
  SECTION("negative E") {
    j["material"]["E"] = -3;
    CHECK(error_of(j) == "problem.json: material.E must be positive, got -3");
  }
  SECTION("nu outside (-1, 0.5)") {
    j["material"]["nu"] = 0.5;
    CHECK(error_of(j) == "problem.json: material.nu must lie in (-1, 0.5), got 0.5");
    j["material"]["nu"] = -1.0;
    CHECK(error_of(j) == "problem.json: material.nu must lie in (-1, 0.5), got -1.0");
  }
  SECTION("unknown key") {
    j["dirichlet"][1]["valeu"] = 1;
    CHECK(error_of(j) == "problem.json: unknown key 'dirichlet[1].valeu' (allowed here: name, selector, value, exact, enriched_dofs, rotation, value_array)");
  }
  SECTION("unknown top-level key") {
    j["materails"] = 1;  // "materials" is a key (several materials); a misspelling of it is not
    CHECK(error_of(j) ==
          "problem.json: unknown key 'materails' (allowed here: description, material, materials, integration, "
          "dirichlet, neumann, body_force, load_steps, cut_loads, contact)");
  }
  SECTION("wrong type") {
    j["dirichlet"][0]["value"] = {0, "zero", 0};
    CHECK(error_of(j) == "problem.json: dirichlet[0].value[1] must be a number");
  }
  SECTION("two selector kinds") {
    j["dirichlet"][0]["selector"]["box"] = {{"lo", {0, 0, 0}}, {"hi", {1, 1, 1}}};
    CHECK(error_of(j) == "problem.json: dirichlet[0].selector must have exactly one of half_spaces, box, point_array, group, boundary");
  }
  SECTION("zero normal") {
    j["dirichlet"][0]["selector"]["half_spaces"][0]["normal"] = {0, 0, 0};
    CHECK(error_of(j) == "problem.json: dirichlet[0].selector.half_spaces[0].normal must not be zero");
  }
  SECTION("all components free") {
    j["dirichlet"][0]["value"] = {nullptr, nullptr, nullptr};
    CHECK(error_of(j) == "problem.json: dirichlet[0].value leaves every component free (null): the condition does nothing");
  }
  SECTION("bad point count") {
    j["integration"]["points"] = 0;
    CHECK(error_of(j) == "problem.json: integration.points must be an integer in 1..100000, got 0");
  }
  SECTION("bad refinement") {
    j["integration"]["refine"] = 9;
    CHECK(error_of(j) == "problem.json: integration.refine must be an integer in 0..8, got 9");
  }
  SECTION("traction of two numbers") {
    j["neumann"][0]["traction"] = {1, 2};
    CHECK(error_of(j) == "problem.json: neumann[0].traction must be a list of 3 numbers");
  }
}

TEST_CASE("problem: a missing problem file is named", "[problem]") {
  CHECK_THROWS_WITH(xfem::read_problem("no/such/problem.json"),
                    "no/such/problem.json: cannot open the problem file (does it exist?)");
}

TEST_CASE("problem: describe names the condition for messages", "[problem]") {
  const xfem::Problem p = xfem::parse_problem(beam(), "in/problem.json");
  CHECK(xfem::describe(p, "dirichlet", 1) == "in/problem.json: dirichlet[1] ('pulled edge')");
  CHECK(xfem::describe(p, "neumann", 0) == "in/problem.json: neumann[0]");
}

TEST_CASE("problem: exact Dirichlet fields parse, taking E and nu from the material", "[problem]") {
  xfem::Json j = beam();
  j["dirichlet"][0] = xfem::Json::parse(R"({"selector": {"box": {"lo": [0, 0, 0], "hi": [1, 1, 1]}},
      "exact": {"williams": {"origin": [0, 0, 0.1], "ahead": [2, 0, 0], "normal": [0, 0, 1], "K1": 3}},
      "enriched_dofs": "exact"})");
  const xfem::Problem p = xfem::parse_problem(j, "problem.json");
  REQUIRE(p.dirichlet[0].exact);
  CHECK(p.dirichlet[0].exact_enriched);
  CHECK(p.dirichlet[0].exact->williams.a.isApprox(Eigen::Vector3d::UnitX()));
  CHECK(p.dirichlet[0].exact->williams.E == p.E);
  CHECK(p.dirichlet[0].exact->williams.K1 == 3);
  j["dirichlet"][0]["exact"] = xfem::Json::parse(R"({"williams": {"origin": [0, 0, 0], "ahead": [1, 0, 0], "normal": [1, 1, 0]}})");
  CHECK_THAT(error_of(j), Catch::Contains("dirichlet[0].exact.williams ahead and normal must be perpendicular"));
  j["dirichlet"][0]["exact"] = xfem::Json::parse(R"({"rigid": {"above": {"translation": [1, 0, 0]}}})");
  CHECK_THAT(error_of(j), Catch::Contains("needs a williams field"));
  j["dirichlet"][0]["enriched_dofs"] = "maybe";
  CHECK_THAT(error_of(j), Catch::Contains("must be \"free\" or \"exact\""));
  j["dirichlet"][0].erase("enriched_dofs");
  j["dirichlet"][0]["value"] = {0, 0, 0};
  CHECK_THAT(error_of(j), Catch::Contains("dirichlet[0] must have exactly one of value, exact, rotation, value_array"));
}

TEST_CASE("problem: a linear exact field parses and gives t + G x on both sides", "[problem]") {
  xfem::Json j = beam();
  j["dirichlet"][0] = xfem::Json::parse(R"({"selector": {"box": {"lo": [0, 0, 0], "hi": [1, 1, 1]}},
      "exact": {"linear": {"gradient": [[1e-3, 0, 0], [0, -3e-4, 2e-4], [0, 0, -3e-4]], "translation": [1, 2, 3]}}})");
  const xfem::Problem p = xfem::parse_problem(j, "problem.json");
  REQUIRE(p.dirichlet[0].exact);
  const xfem::ExactField& f = *p.dirichlet[0].exact;
  CHECK(f.kind == xfem::ExactField::Kind::Linear);
  const Eigen::Vector3d x(0.5, -1, 2);
  // 1 + 5e-4, 2 + 3e-4 + 4e-4, 3 - 6e-4: exact up to rounding of the decimal inputs.
  CHECK((f.displacement(x, +1) - Eigen::Vector3d(1.0005, 2.0007, 2.9994)).norm() < 1e-15);
  CHECK(f.displacement(x, -1) == f.displacement(x, +1));
  CHECK(f.gradient(x, -1)(1, 2) == 2e-4);
  j["dirichlet"][0]["exact"] = xfem::Json::parse(R"({"linear": {"gradient": [[1, 0, 0], [0, 1, 0]]}})");
  CHECK_THAT(error_of(j), Catch::Contains("dirichlet[0].exact.linear.gradient must be a list of 3 rows"));
  j["dirichlet"][0]["exact"] = xfem::Json::parse(R"({"linear": {"gradient": [[1, 0, 0], [0, 1, 0], [0, 0]]}})");
  CHECK_THAT(error_of(j), Catch::Contains("must be a list of 3 numbers"));
}

TEST_CASE("problem: material.model and load_steps default to linear and 1, and parse", "[problem]") {
  xfem::Json j = beam();
  xfem::Problem p = xfem::parse_problem(j, "problem.json");
  CHECK(p.model == xfem::MaterialModel::Linear);
  CHECK(p.load_steps == 1);
  j["material"]["model"] = "neo-hookean";
  j["load_steps"] = 20;
  p = xfem::parse_problem(j, "problem.json");
  CHECK(p.model == xfem::MaterialModel::NeoHookean);
  CHECK(p.load_steps == 20);
  CHECK(p.E == 300e3);  // the rest of the file keeps its meaning
  CHECK(p.dirichlet.size() == 2);
  j["material"]["model"] = "corotational";
  CHECK(xfem::parse_problem(j, "problem.json").model == xfem::MaterialModel::Corotational);
  j["material"]["model"] = "linear";
  CHECK(xfem::parse_problem(j, "problem.json").model == xfem::MaterialModel::Linear);
}

TEST_CASE("problem: a bad material.model or load_steps gives one error line naming the file", "[problem]") {
  xfem::Json j = beam();
  SECTION("unknown model") {
    j["material"]["model"] = "neohookean";
    CHECK(error_of(j) ==
          "problem.json: material.model must be \"linear\", \"corotational\" or \"neo-hookean\", got \"neohookean\"");
  }
  SECTION("model not a string") {
    j["material"]["model"] = 1;
    CHECK(error_of(j) == "problem.json: material.model must be a string");
  }
  SECTION("unknown key in material lists model") {
    j["material"]["modle"] = "linear";
    CHECK(error_of(j) == "problem.json: unknown key 'material.modle' (allowed here: E, nu, model)");
  }
  SECTION("zero load steps") {
    j["load_steps"] = 0;
    CHECK(error_of(j) == "problem.json: load_steps must be an integer in 1..1000000, got 0");
  }
  SECTION("fractional load steps") {
    j["load_steps"] = 2.5;
    CHECK(error_of(j) == "problem.json: load_steps must be an integer in 1..1000000, got 2.5");
  }
  SECTION("load steps as a string") {
    j["load_steps"] = "10";
    CHECK(error_of(j) == "problem.json: load_steps must be an integer in 1..1000000, got \"10\"");
  }
  SECTION("too many load steps") {
    j["load_steps"] = 10000000000LL;
    CHECK(error_of(j) == "problem.json: load_steps must be an integer in 1..1000000, got 10000000000");
  }
}

TEST_CASE("problem: require_linear_material passes linear and refuses the other models by name", "[problem]") {
  xfem::Json j = beam();
  const std::string reason = "xfem-front's interaction integral is small-strain";
  CHECK_NOTHROW(xfem::require_linear_material(xfem::parse_problem(j, "problem.json"), reason));  // default: linear
  j["material"]["model"] = "linear";
  CHECK_NOTHROW(xfem::require_linear_material(xfem::parse_problem(j, "problem.json"), reason));
  for (const std::string model : {"corotational", "neo-hookean"}) {
    j["material"]["model"] = model;
    const xfem::Problem p = xfem::parse_problem(j, "in/problem.json");
    std::string message;
    try {
      xfem::require_linear_material(p, reason);
    } catch (const xfem::Error& e) {
      message = e.what();
    }
    CHECK(message == "in/problem.json: xfem-front's interaction integral is small-strain: material.model \"" + model +
                         "\" is not supported (use \"linear\"; xfem-newton solves \"" + model + "\")");
  }
}
