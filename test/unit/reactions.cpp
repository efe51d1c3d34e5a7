// SPDX-License-Identifier: MIT
#include "xfem/system/reactions.h"

#include <Eigen/SparseCholesky>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "xfem/system/assembly.h"
#include "xfem/generate/box_mesh.h"
#include "xfem/system/dirichlet.h"
#include "xfem/core/error.h"
#include "enriched_test_meshes.h"

namespace {

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

// Solves the system with its Dirichlet conditions eliminated, as xfem-solve does (K_ff, here by
// Eigen's sparse LDL^T).
Eigen::VectorXd solve(const xfem::LinearSystem& s) {
  const xfem::ReducedSystem r = xfem::eliminate_dirichlet(s.K, s.f, s.fixed, s.fixed_values);
  const Eigen::SimplicialLDLT<xfem::SparseMatrix> ldlt(r.K);
  REQUIRE(ldlt.info() == Eigen::Success);
  return xfem::expand_solution(r, ldlt.solve(r.f), s.fixed, s.fixed_values);
}

xfem::LinearSystem full(xfem::LinearSystem s) {  // assemble_system fills the lower triangle only
  const xfem::SparseMatrix both = s.K.selfadjointView<Eigen::Lower>();  // not in place: aliasing
  s.K = both;
  return s;
}

}  // namespace

TEST_CASE("reactions: a bar in uniaxial tension pulls with E A strain", "[reactions]") {
  // Bar [0, a] x [0, b] x [0, L], its ends held at u_z = 0 and u_z = strain L, laterally free but
  // for the two corner pins that remove the rigid motions. The exact solution is the homogeneous
  // stretch u = strain (-nu x, -nu y, z), which linear tets reproduce exactly, so the reaction at
  // each end is E A strain up to round-off.
  const double a = 0.01, b = 0.02, L = 0.1, E = 300e3, nu = 0.35, strain = 0.05;
  const xfem::EnrichedMesh em = xfem_test::plain(xfem::box_mesh({2, 3, 6}, {0, 0, 0}, {a, b, L}));
  xfem::Json j = xfem::Json::parse(R"({
    "material": {"E": 300e3, "nu": 0.35},
    "dirichlet": [
      {"name": "bottom", "selector": {"box": {"lo": [-1, -1, -1], "hi": [1, 1, 0]}}, "value": [null, null, 0]},
      {"name": "top", "selector": {"box": {"lo": [-1, -1, 0.1], "hi": [1, 1, 1]}}, "value": [null, null, 0.005]},
      {"name": "pin", "selector": {"box": {"lo": [0, 0, 0], "hi": [0, 0, 0]}}, "value": [0, 0, 0]},
      {"name": "roller", "selector": {"box": {"lo": [0.01, 0, 0], "hi": [0.01, 0, 0]}}, "value": [null, 0, null]}
    ]})");
  const xfem::Problem p = xfem::parse_problem(j, "p.json");
  const xfem::LinearSystem s = full(xfem::assemble_system(em, p, 30, 0));
  const Eigen::VectorXd u = solve(s);
  const xfem::DirichletGroups g = xfem::dirichlet_groups(em.mesh, p);
  REQUIRE(g.names == std::vector<std::string>{"bottom", "top", "pin", "roller"});
  CHECK(g.dofs[0].size() == 12);  // 3 x 4 nodes, z only
  CHECK(g.dofs[2] == std::vector<long>{0, 1});  // z of node 0 belongs to "bottom", the first condition
  const auto r = xfem::condition_reactions(g, xfem::nodal_reactions(s, u), s.coordinates);
  const double pull = E * a * b * strain;  // 0.15 N
  // The linear system is solved to ~1e-15 relative; the reactions inherit it.
  CHECK_THAT(r[1].force.z(), WithinRel(pull, 1e-10));
  CHECK_THAT(r[0].force.z(), WithinRel(-pull, 1e-10));
  CHECK(r[1].nodes == 12);
  for (int c = 0; c < 2; ++c) CHECK_THAT(r[1].force[c], WithinAbs(0, 1e-12 * pull));
  CHECK_THAT(r[2].force.norm(), WithinAbs(0, 1e-12 * pull));
  CHECK_THAT(r[3].force.norm(), WithinAbs(0, 1e-12 * pull));
  // Moment of the top's uniform pull about the origin: x_centroid x F = (b/2 F, -a/2 F, 0).
  CHECK_THAT(r[1].moment.x(), WithinRel(b / 2 * pull, 1e-10));
  CHECK_THAT(r[1].moment.y(), WithinRel(-a / 2 * pull, 1e-10));
  // And the displacement is the exact stretch.
  for (long k = 0; k < em.np; ++k)
    CHECK_THAT(u[3 * k], WithinAbs(-nu * strain * em.mesh.points(k, 0), 1e-12));
}

TEST_CASE("reactions: reactions and loads of a cut body are in equilibrium, forces and moments", "[reactions]") {
  // The cut box (sign-enriched lower cube) under a body force and a traction on a side face, held
  // at its bottom and top faces so that both pieces are fixed. K annihilates the rigid motions,
  // which the original DOFs reproduce exactly, so sum(r) + sum(f) = 0 and likewise the moments.
  const xfem::EnrichedMesh em = xfem_test::cut_box(0.3);
  const xfem::Problem p = xfem::parse_problem(xfem::Json::parse(R"({
    "material": {"E": 1e3, "nu": 0.3},
    "body_force": [3, -2, 5],
    "neumann": [{"selector": {"box": {"lo": [1, 0, 0], "hi": [1, 1, 1]}}, "traction": [10, 20, -7]}],
    "dirichlet": [
      {"name": "base", "selector": {"box": {"lo": [0, 0, 0], "hi": [1, 1, 0]}}, "value": [0, 0, 0]},
      {"name": "lid", "selector": {"box": {"lo": [0, 0, 1], "hi": [1, 1, 1]}}, "value": [0.01, 0, -0.02]}
    ]})"), "p.json");
  const xfem::LinearSystem s = full(xfem::assemble_system(em, p, 30, 0));
  REQUIRE(s.ns > 0);
  const Eigen::VectorXd u = solve(s);
  const auto r = xfem::condition_reactions(xfem::dirichlet_groups(em.mesh, p), xfem::nodal_reactions(s, u), s.coordinates);
  const xfem::Resultant f = xfem::applied_load(s.f, s.coordinates);
  // Loads: body force 1 m^3 x b, traction 1 m^2 x t (the face x = 1 of the unit box).
  CHECK_THAT((f.force - Eigen::Vector3d(13, 18, -2)).norm(), WithinAbs(0, 1e-12));
  const Eigen::Vector3d force = r[0].force + r[1].force + f.force, moment = r[0].moment + r[1].moment + f.moment;
  // Round-off of a system with entries ~1e3 and reactions ~10 N.
  CHECK_THAT(force.norm(), WithinAbs(0, 1e-9));
  CHECK_THAT(moment.norm(), WithinAbs(0, 1e-9));
  CHECK(r[0].force.norm() > 1);  // not trivially zero
  CHECK(r[1].moment.norm() > 1e-3);
  // Free DOFs carry no reaction.
  const Eigen::VectorXd nodal = xfem::nodal_reactions(s, u);
  for (long d = 0; d < nodal.size(); ++d)
    if (!std::binary_search(s.fixed.begin(), s.fixed.end(), d)) CHECK(nodal[d] == 0.0);
}

TEST_CASE("reactions: the groups go through system/dirichlet_conditions.json", "[reactions]") {
  const auto dir = std::filesystem::temp_directory_path() / "xfem_reactions_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  xfem::LinearSystem s;
  s.np = s.n = 4;
  s.fixed = {0, 1, 2, 5, 9};
  // Without the file (an older system): one group of every constrained original DOF.
  xfem::DirichletGroups g = xfem::read_dirichlet_groups(dir.string(), s);
  REQUIRE(g.names == std::vector<std::string>{"constrained DOFs"});
  CHECK(g.dofs[0] == s.fixed);
  g.names = {"a", "b"};
  g.dofs = {{0, 1, 2}, {5, 9}};
  xfem::write_dirichlet_groups(g, dir.string(), "test");
  const xfem::DirichletGroups back = xfem::read_dirichlet_groups(dir.string(), s);
  CHECK(back.names == g.names);
  CHECK(back.dofs == g.dofs);
  s.fixed = {0, 1, 2, 5};
  CHECK_THROWS_WITH(xfem::read_dirichlet_groups(dir.string(), s),
                    (dir / "dirichlet_conditions.json").string() +
                        ": condition 'b' lists DOF 9, which the system does not fix (is this file from another system?)");
  std::filesystem::remove_all(dir);
}
