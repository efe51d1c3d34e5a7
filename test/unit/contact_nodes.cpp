// SPDX-License-Identifier: MIT
// Contact per node of the cut (issue 33): the weighted gap, the penalty of each tet's material,
// the pressure file and the pressure on the wound.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "enriched_test_meshes.h"
#include "xfem/core/error.h"
#include "xfem/geometry/element_split.h"
#include "xfem/post/split_enriched_mesh.h"
#include "xfem/post/wound_pressure.h"
#include "xfem/solve/contact_pressure_file.h"
#include "xfem/system/contact_operator.h"
#include "xfem/system/problem.h"

namespace {

xfem::Problem contact_problem() {
  return xfem::parse_problem(xfem::Json::parse(R"({"material": {"E": 1e3, "nu": 0.3}, "contact": true})"), "p.json");
}

std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "xfem_contact_nodes";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

}  // namespace

TEST_CASE("contact nodes: the weighted gaps of a rigid opening and the nodes' areas", "[contact]") {
  const xfem::EnrichedMesh em = xfem_test::cut_box(0.3);  // the unit box of 1 x 1 x 2 cubes cut by z = 0.3
  const xfem::ContactOperator c = xfem::contact_operator(em, contact_problem());
  REQUIRE(c.points() > 0);
  // The nodes' areas share the cut's (1 m^2) among them: every point's shares sum to 1.
  CHECK(std::abs(c.weight.sum() - 1.0) < 1e-12);
  CHECK((c.weight.array() > 0).all());
  // The piece above moved by (0, 0, d): every sign DOF takes d along z (as in cut_loads.cpp's
  // work_on_upper_piece), and every weighted gap is d, a length.
  const double d = 1e-3;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * em.n);
  for (long k = 0; k < em.np; ++k)
    if (em.side[k] > 0) u[3 * k + 2] = d;
  for (long k = em.np; k < em.n; ++k) u[3 * k + 2] = d;
  const Eigen::VectorXd g = c.G * u;
  CHECK((g.array() - d).abs().maxCoeff() < 1e-15);
  // Sliding along x leaves every gap closed (frictionless: no tangential condition).
  u.setZero();
  for (long k = em.np; k < em.n; ++k) u[3 * k] = d;
  CHECK((c.G * u).cwiseAbs().maxCoeff() < 1e-15);
}

TEST_CASE("contact nodes: the penalty is the material of the cut tets (two regions)", "[contact]") {
  const xfem::EnrichedMesh em = xfem_test::cut_box(0.3);
  const xfem::Problem p = contact_problem();
  const xfem::ContactOperator one = xfem::contact_operator(em, p);
  // Every tet in a second material 10 times stiffer: every penalty 10 times larger, G the same.
  xfem::TetMaterials stiff(xfem::MaterialModel::Linear, 1e3, 0.3);
  const int law = stiff.add(xfem::MaterialModel::Linear, 1e4, 0.3);
  stiff.of_tet.assign(static_cast<std::size_t>(em.tets()), law);
  const xfem::ContactOperator ten = xfem::contact_operator(em, p, stiff);
  REQUIRE(ten.points() == one.points());
  CHECK(((ten.penalty.array() / one.penalty.array()) - 10.0).abs().maxCoeff() < 1e-12);
  CHECK((xfem::SparseMatrix(ten.G - one.G)).norm() == 0.0);
  // Two regions: the tets whose centroid lies at x < 0.5 stiff, the others not. A node's penalty
  // is its points' average: 10 times the single material's for a node of stiff tets only, the
  // same for a node of soft tets only, in between for the others (some nodes here), never outside.
  xfem::TetMaterials two(xfem::MaterialModel::Linear, 1e3, 0.3);
  two.add(xfem::MaterialModel::Linear, 1e4, 0.3);
  two.of_tet.assign(static_cast<std::size_t>(em.tets()), 0);
  std::vector<int> stiff_tets(static_cast<std::size_t>(em.np), 0), soft_tets(static_cast<std::size_t>(em.np), 0);
  for (int t = 0; t < em.tets(); ++t) {
    double x = 0;
    for (int a = 0; a < 4; ++a) x += em.mesh.points(em.mesh.tets(t, a), 0) / 4;
    if (x < 0.5) two.of_tet[static_cast<std::size_t>(t)] = 1;
    for (int a = 0; a < 4; ++a) ++(x < 0.5 ? stiff_tets : soft_tets)[static_cast<std::size_t>(em.mesh.tets(t, a))];
  }
  const xfem::ContactOperator mixed = xfem::contact_operator(em, p, two);
  REQUIRE(mixed.points() == one.points());
  int between = 0;
  for (long i = 0; i < mixed.points(); ++i) {
    const double ratio = mixed.penalty[i] / one.penalty[i];
    const int node = mixed.node[static_cast<std::size_t>(i)];
    CHECK(ratio >= 1 - 1e-12);
    CHECK(ratio <= 10 + 1e-12);
    if (soft_tets[static_cast<std::size_t>(node)] == 0) CHECK(std::abs(ratio - 10) < 1e-12);
    if (stiff_tets[static_cast<std::size_t>(node)] == 0) CHECK(std::abs(ratio - 1) < 1e-12);
    if (ratio > 1 + 1e-9 && ratio < 10 - 1e-9) ++between;
  }
  CHECK(between > 0);
}

TEST_CASE("contact nodes: the pressure file and the pressure on the wound", "[contact]") {
  const xfem::EnrichedMesh em = xfem_test::cut_box(0.3);
  const xfem::ContactOperator c = xfem::contact_operator(em, contact_problem());
  const std::string path = scratch("p.mtx");
  // A uniform pressure: every wound triangle carries it (the shape functions of the nodes with a
  // condition, renormalised, sum to 1).
  xfem::write_contact_pressure(c, Eigen::VectorXd::Constant(c.points(), 250.0), em.np, path);
  const xfem::SparseMatrix P = xfem::read_contact_pressure(path, em.np, 1);
  CHECK(P.nonZeros() == c.points());
  const xfem::SplitMesh split = xfem::split_mesh(em);
  const std::vector<double> on_wound = xfem::wound_contact_pressure(split, em, P);
  REQUIRE(on_wound.size() == static_cast<std::size_t>(split.wound.rows()));
  REQUIRE(!on_wound.empty());
  for (double p : on_wound) CHECK(std::abs(p - 250.0) < 1e-9);
  // Bad files: another mesh's node count, more cuts than the mesh has, a negative pressure.
  CHECK_THROWS_WITH(xfem::read_contact_pressure(path, em.np + 1, 1),
                    path + ": " + std::to_string(em.np) + " rows, expected one per mesh node (" +
                        std::to_string(em.np + 1) + ")");
  xfem::SparseMatrix two(em.np, 2);
  two.insert(0, 1) = 1.0;
  xfem::write_general_matrix(two, path);
  CHECK_THROWS_WITH(xfem::read_contact_pressure(path, em.np, 1), path + ": 2 columns (cuts), but the mesh has 1");
  xfem::write_contact_pressure(c, Eigen::VectorXd::Constant(c.points(), -1.0), em.np, path);
  CHECK_THROWS_WITH(xfem::read_contact_pressure(path, em.np, 1),
                    Catch::Matchers::StartsWith(path + ": the pressure of node ") &&
                        Catch::Matchers::Contains("is not a non-negative number"));
  std::filesystem::remove(path);
}
