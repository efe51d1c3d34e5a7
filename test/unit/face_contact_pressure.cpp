// SPDX-License-Identifier: MIT
#include "xfem/fracture/face_contact_pressure.h"

#include <catch2/catch.hpp>
#include <vector>

#include "xfem/core/error.h"

namespace {

// One tet (0,0,0), (1,0,0), (0,1,0), (0,0,1).
xfem::TetMesh unit_tet() {
  xfem::TetMesh m;
  m.points.resize(4, 3);
  m.points << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  m.tets.resize(1, 4);
  m.tets << 0, 1, 2, 3;
  return m;
}

// The nodal pressure file's matrix: NP x C, entries (node, cut, value).
xfem::SparseMatrix nodal(long np, int cuts, const std::vector<Eigen::Triplet<double, int>>& entries) {
  xfem::SparseMatrix P(np, cuts);
  P.setFromTriplets(entries.begin(), entries.end());
  return P;
}

}  // namespace

TEST_CASE("face_contact_pressure: the gap's shares, a uniform pressure carried exactly", "[contact][front]") {
  const xfem::TetMesh m = unit_tet();
  const Eigen::Vector3d x(0.2, 0.3, 0.1);  // N = (0.4, 0.2, 0.3, 0.1)
  SECTION("every node a contact node: linear interpolation") {
    const auto p = xfem::face_contact_pressure(nodal(4, 1, {{0, 0, 1.0}, {1, 0, 2.0}, {2, 0, 3.0}, {3, 0, 4.0}}), 0, "p.mtx");
    CHECK(xfem::face_contact_pressure_at(p, m, 0, x) == Approx(0.4 * 1 + 0.2 * 2 + 0.3 * 3 + 0.1 * 4).epsilon(1e-14));
  }
  SECTION("a sliver node (no entry) gives its share to the others: a uniform pressure stays uniform") {
    // Node 3 is no contact node; a zero stored for node 2 keeps it one (zeros are contact nodes too).
    const auto p = xfem::face_contact_pressure(nodal(4, 2, {{0, 1, 5.0}, {1, 1, 5.0}, {2, 1, 5.0}}), 1, "p.mtx");
    CHECK(xfem::face_contact_pressure_at(p, m, 0, x) == Approx(5.0).epsilon(1e-14));
    const auto q = xfem::face_contact_pressure(nodal(4, 1, {{0, 0, 9.0}, {1, 0, 0.0}}), 0, "p.mtx");
    CHECK(xfem::face_contact_pressure_at(q, m, 0, x) == Approx(9.0 * 0.4 / 0.6).epsilon(1e-14));
    CHECK(q.contact_node[1] == 1);
  }
  SECTION("refused: no column for the cut, no contact node on it") {
    CHECK_THROWS_WITH(xfem::face_contact_pressure(nodal(4, 1, {{0, 0, 1.0}}), 1, "p.mtx"),
                      Catch::StartsWith("p.mtx: no contact pressure for cut 1"));
    CHECK_THROWS_WITH(xfem::face_contact_pressure(nodal(4, 2, {{0, 1, 1.0}}), 0, "p.mtx"),
                      Catch::StartsWith("p.mtx: no contact node on cut 0"));
  }
}
