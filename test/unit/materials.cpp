// SPDX-License-Identifier: MIT
// Several materials: problem.json `materials` (parsed and checked against the mesh's regions),
// the stiffness and nonlinear forces with each tet's own material.
#include <catch2/catch.hpp>
#include <functional>
#include <memory>

#include "enriched_test_meshes.h"
#include "xfem/core/error.h"
#include "xfem/core/regions.h"
#include "xfem/enrich/classification.h"
#include "xfem/generate/box_mesh.h"
#include "xfem/generate/cut_generation.h"
#include "xfem/progressive/progressive_cut.h"
#include "xfem/system/assembly.h"
#include "xfem/system/nonlinear_assembly.h"
#include "xfem/system/problem.h"

namespace {

xfem::Problem parse(const std::string& materials, const std::string& material = R"({"E": 2, "nu": 0.3})") {
  return xfem::parse_problem(xfem::Json::parse("{\"material\": " + material + ", \"materials\": " + materials + "}"),
                             "p.json");
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const xfem::Error& e) {
    return e.what();
  }
  return "(no error)";
}

// A 4 x 1 x 1 box of [0,4] x [0,1]^2: region 1 'soft' for x < 2, region 7 'hard' beyond (the
// interface is the grid plane x = 2), and the name 'capsule' for region 9, which no tet has.
xfem::TetMesh two_regions() {
  xfem::TetMesh m = xfem::box_mesh({4, 1, 1}, {0, 0, 0}, {4, 1, 1});
  xfem_test::split_regions(m, 0, 2.0, 1, 7);
  m.region_names = {{1, "soft"}, {7, "hard"}, {9, "capsule"}};
  return m;
}

}  // namespace

TEST_CASE("materials: entries by id or name, model defaulting to material.model", "[materials]") {
  const xfem::Problem p = parse(R"([{"region": 1, "E": 5, "nu": 0.1}, {"region": "hard", "E": 7, "nu": 0.2,
                                    "model": "corotational"}])",
                                R"({"E": 2, "nu": 0.3, "model": "neo-hookean"})");
  REQUIRE(p.materials.size() == 2);
  CHECK(p.materials[0].id == 1);
  CHECK(p.materials[0].name.empty());
  CHECK(p.materials[0].E == 5);
  CHECK(p.materials[0].model == xfem::MaterialModel::NeoHookean);
  CHECK(p.materials[1].id == -1);
  CHECK(p.materials[1].name == "hard");
  CHECK(p.materials[1].model == xfem::MaterialModel::Corotational);
  // require_linear_material names the entry whose model is not linear.
  const xfem::Problem q = parse(R"([{"region": 1, "E": 5, "nu": 0.1, "model": "neo-hookean"}])");
  CHECK(error_of([&] { xfem::require_linear_material(q, "linear only"); }) ==
        "p.json: linear only: materials[0].model \"neo-hookean\" is not supported (use \"linear\"; xfem-newton solves "
        "\"neo-hookean\")");
}

TEST_CASE("materials: bad entries are one-line errors naming the item", "[materials]") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"region": 1})", "p.json: materials must be a list"},
      {R"([{"region": 1, "E": 0, "nu": 0.3}])", "p.json: materials[0].E must be positive, got 0"},
      {R"([{"region": 1, "E": -4, "nu": 0.3}])", "p.json: materials[0].E must be positive, got -4"},
      {R"([{"region": 1, "E": 1, "nu": 0.5}])", "p.json: materials[0].nu must lie in (-1, 0.5), got 0.5"},
      {R"([{"region": 1, "E": "stiff", "nu": 0.3}])", "p.json: materials[0].E must be a number"},
      {R"([{"region": 1, "nu": 0.3}])", "p.json: missing field 'materials[0].E'"},
      {R"([{"E": 1, "nu": 0.3}])", "p.json: missing field 'materials[0].region'"},
      {R"([{"region": 1.5, "E": 1, "nu": 0.3}])",
       "p.json: materials[0].region must be a region id (an integer in 0..2147483647) or a name, got 1.5"},
      {R"([{"region": -1, "E": 1, "nu": 0.3}])",
       "p.json: materials[0].region must be a region id (an integer in 0..2147483647) or a name, got -1"},
      {R"([{"region": 4294967296, "E": 1, "nu": 0.3}])",
       "p.json: materials[0].region must be a region id (an integer in 0..2147483647) or a name, got 4294967296"},
      {R"([{"region": [1], "E": 1, "nu": 0.3}])",
       "p.json: materials[0].region must be a region id (an integer in 0..2147483647) or a name, got [1]"},
      {R"([{"region": "", "E": 1, "nu": 0.3}])", "p.json: materials[0].region must name a region (a non-empty string) or be its id"},
      {R"([{"region": 1, "E": 1, "nu": 0.3, "model": "rubber"}])",
       "p.json: materials[0].model must be \"linear\", \"corotational\" or \"neo-hookean\", got \"rubber\""},
      {R"([{"region": 1, "E": 1, "nu": 0.3, "G": 3}])",
       "p.json: unknown key 'materials[0].G' (allowed here: region, E, nu, model)"},
      {R"([{"region": 1, "E": 1, "nu": 0.3}, {"region": 1, "E": 2, "nu": 0.3}])",
       "p.json: materials[1].region lists region 1 again (materials[0] gives its material)"},
      {R"([{"region": "a", "E": 1, "nu": 0.3}, {"region": "a", "E": 2, "nu": 0.3}])",
       "p.json: materials[1].region lists region \"a\" again (materials[0] gives its material)"},
  };
  for (const auto& c : cases) {
    const std::string& materials = c.first;  // named: a lambda captures it (not a structured binding)
    INFO(materials);
    CHECK(error_of([&] { parse(materials); }) == c.second);
  }
}

TEST_CASE("materials: each tet gets its region's material; unknown regions list the mesh's", "[materials]") {
  const xfem::TetMesh m = two_regions();
  const xfem::Problem p = parse(R"([{"region": "soft", "E": 5, "nu": 0.1}])");
  const xfem::TetMaterials tm = xfem::tet_materials(p, m, "body.vtu");
  REQUIRE(tm.laws.size() == 2);
  CHECK(tm.E == std::vector<double>{2, 5});
  const std::vector<int> region = xfem::tet_regions(m);
  for (std::size_t t = 0; t < region.size(); ++t) {
    INFO("tet " << t);
    CHECK(tm.index(static_cast<long>(t)) == (region[t] == 1 ? 1 : 0));  // 'hard' keeps the default
    CHECK(tm.lame(static_cast<long>(t)).mu == xfem::lame(region[t] == 1 ? 5 : 2, region[t] == 1 ? 0.1 : 0.3).mu);
  }
  // A named region without tets is known (it is named), and changes no tet.
  CHECK(xfem::tet_materials(parse(R"([{"region": "capsule", "E": 5, "nu": 0.1}])"), m, "b").of_tet.empty());
  CHECK(error_of([&] { xfem::tet_materials(parse(R"([{"region": "tumor", "E": 5, "nu": 0.1}])"), m, "body.vtu"); }) ==
        "p.json: materials[0].region 'tumor' is not a region of body.vtu (its regions: 1 'soft', 7 'hard', 9 'capsule')");
  CHECK(error_of([&] { xfem::tet_materials(parse(R"([{"region": 3, "E": 5, "nu": 0.1}])"), m, "body.vtu"); }) ==
        "p.json: materials[0].region 3 is not a region of body.vtu (its regions: 1 'soft', 7 'hard', 9 'capsule')");
  CHECK(error_of([&] {
          xfem::tet_materials(parse(R"([{"region": 7, "E": 5, "nu": 0.1}, {"region": "hard", "E": 5, "nu": 0.1}])"),
                              m, "body.vtu");
        }) == "p.json: materials[1].region names region 7 again (materials lists each region once)");
  // A mesh without regions is region 0.
  const xfem::TetMesh plain = xfem::box_mesh({1, 1, 1}, {0, 0, 0}, {1, 1, 1});
  CHECK(error_of([&] { xfem::tet_materials(parse(R"([{"region": 1, "E": 5, "nu": 0.1}])"), plain, "box.vtu"); }) ==
        "p.json: materials[0].region 1 is not a region of box.vtu (its regions: 0)");
  CHECK(xfem::tet_materials(parse(R"([{"region": 0, "E": 5, "nu": 0.1}])"), plain, "box.vtu").law(0).lame.mu ==
        xfem::lame(5, 0.1).mu);
}

TEST_CASE("materials: every region given the default's material is the single-material path", "[materials]") {
  const xfem::TetMesh m = two_regions();
  const xfem::TetMaterials tm = xfem::tet_materials(
      parse(R"([{"region": 1, "E": 2, "nu": 0.3}, {"region": "hard", "E": 2, "nu": 0.3}])"), m, "b");
  CHECK(tm.of_tet.empty());
  CHECK(tm.laws.size() == 1);
  // Two regions of one other material share one law.
  const xfem::TetMaterials other = xfem::tet_materials(
      parse(R"([{"region": 1, "E": 3, "nu": 0.3}, {"region": "hard", "E": 3, "nu": 0.3}])"), m, "b");
  CHECK(other.laws.size() == 2);
  CHECK(!other.of_tet.empty());
  for (std::size_t t = 0; t < other.of_tet.size(); ++t) CHECK(other.of_tet[t] == 1);
}

TEST_CASE("materials: K of a cut body with two materials is the sum of each region's K; the nonlinear forces agree",
          "[materials]") {
  // A 3 x 3 x 6 box cut partially by z = 0.93 (sign and branch DOFs), regions by z < 1 (the cut
  // and its front in region 1, the interface the grid plane z = 1).
  xfem::TetMesh mesh = xfem::box_mesh({3, 3, 6}, {0, 0, 0}, {1, 1, 2});
  xfem_test::split_regions(mesh, 2, 1.0, 1, 2);
  const auto cut = std::make_shared<xfem::CutSurface>(
      xfem::cut_parallelogram({-0.2, -0.2, 0.93}, {0.55, -0.2, 0.93}, {-0.2, 1.2, 0.93}, {3, 3}));
  const xfem::EnrichedMesh em = xfem::enriched_mesh(mesh, xfem::classify(mesh, *cut), cut);
  REQUIRE(em.nb > 0);
  const xfem::Problem p = parse(R"([{"region": 2, "E": 11, "nu": 0.1}])");
  const xfem::TetMaterials tm = xfem::tet_materials(p, em.mesh, "m");
  REQUIRE(tm.laws.size() == 2);
  const xfem::SparseMatrix K = xfem::stiffness_matrix(em, tm, xfem::Quadrature(), nullptr, {}, 3);
  // Each region alone (the other region's tets given a zero material) sums to K.
  xfem::TetMaterials only1 = tm, only2 = tm;
  only1.laws[1].lame = xfem::Lame{};
  only2.laws[0].lame = xfem::Lame{};
  const xfem::SparseMatrix K1 = xfem::stiffness_matrix(em, only1, xfem::Quadrature(), nullptr, {}, 3);
  const xfem::SparseMatrix K2 = xfem::stiffness_matrix(em, only2, xfem::Quadrature(), nullptr, {}, 3);
  const xfem::SparseMatrix Ka = xfem::stiffness_matrix(em, xfem::lame(2, 0.3), xfem::Quadrature(), nullptr, {}, 3);
  const xfem::SparseMatrix Kb = xfem::stiffness_matrix(em, xfem::lame(11, 0.1), xfem::Quadrature(), nullptr, {}, 3);
  const double scale = Eigen::MatrixXd(Kb).cwiseAbs().maxCoeff();
  CHECK(Eigen::MatrixXd(K - K1 - K2).cwiseAbs().maxCoeff() <= 1e-13 * scale);
  CHECK(Eigen::MatrixXd(K1).cwiseAbs().maxCoeff() > 0.1 * scale);
  CHECK(Eigen::MatrixXd(K2).cwiseAbs().maxCoeff() > 0.1 * scale);
  // Each part lives on its region's nodes: K1 on the nodes z <= 1, K2 on z >= 1 (original DOFs).
  for (const auto* part : {&K1, &K2})
    for (int c = 0; c < 3 * em.np; ++c)
      for (xfem::SparseMatrix::InnerIterator it(*part, c); it; ++it)
        if (it.value() != 0) {
          const double z = em.mesh.points(c / 3, 2);
          INFO("column " << c << " z " << z);
          CHECK((part == &K1 ? z <= 1.0 : z >= 1.0));
        }
  CHECK(Eigen::MatrixXd(K - Ka).cwiseAbs().maxCoeff() > 0.1 * scale);

  // The nonlinear forces with the body's per-tet laws (linear model): r = K u, tangent K.
  xfem::BodyIntegration body = xfem::integrate_body(em, 3);
  body.materials = &tm;
  std::vector<int> outer;
  xfem::SparseMatrix T = xfem::pattern_matrix(em, body.pattern, outer);
  std::srand(5);
  const Eigen::VectorXd u = 1e-3 * Eigen::VectorXd::Random(3 * em.n);
  double energy = 0;
  Eigen::VectorXd r;
  REQUIRE(xfem::internal_forces(em, body, xfem::MaterialLaw{xfem::MaterialModel::Linear, xfem::lame(99, 0.2)}, u,
                                energy, r, &T));
  CHECK(Eigen::MatrixXd(T - K).cwiseAbs().maxCoeff() <= 1e-12 * scale);
  const Eigen::VectorXd Ku = xfem::SparseMatrix(K.selfadjointView<Eigen::Lower>()) * u;
  CHECK((r - Ku).lpNorm<Eigen::Infinity>() <= 1e-12 * Ku.lpNorm<Eigen::Infinity>());
}
