// SPDX-License-Identifier: MIT
#include "xfem/enrich/dof_numbering.h"

#include <catch2/catch.hpp>

#include "xfem/core/error.h"

namespace {

std::vector<long> C(const xfem::DofNumbering& d, int t) {
  return std::vector<long>(d.dofs.begin() + d.offsets[t], d.dofs.begin() + d.offsets[t + 1]);
}
std::vector<int> L(const xfem::DofNumbering& d, int t) {
  return std::vector<int>(d.local.begin() + d.offsets[t], d.local.begin() + d.offsets[t + 1]);
}

}  // namespace

TEST_CASE("dof_numbering: the paper's figure 2 lifted to tets, entry by entry", "[dof_numbering]") {
  // Figure 2's five triangles, each made a tet with a common unenriched apex 7. Nodes 0, 1, 2
  // sign, 3, 5, 6 branch, 4 none; elements 0, 1, 3 completely cut, 2 uncut, 4 partially cut.
  xfem::Tets tets(5, 4);
  tets << 1, 0, 2, 7,  //
      2, 3, 1, 7,      //
      4, 5, 2, 7,      //
      3, 2, 5, 7,      //
      3, 5, 6, 7;
  const auto d = xfem::dof_numbering(tets, 8, {1, 1, 1, 2, 0, 2, 2, 0}, {2, 2, 0, 2, 1});
  // NP = 8, NS = 3 (ids 8, 9, 10), NB = 3 (11-14, 15-18, 19-22), N = 8 + 3 + 12 = 23.
  CHECK((d.np == 8 && d.ns == 3 && d.nb == 3 && d.n == 23));
  CHECK(d.sign_dof == std::vector<long>{8, 9, 10, -1, -1, -1, -1, -1});
  CHECK(d.branch_dof == std::vector<long>{-1, -1, -1, 11, -1, 15, 19, -1});
  // The paper's lists with its ids shifted by one (the apex is point 7) and the apex in slot 3.
  // Element 0: sorted by DOF id (the paper lists 8, 7, 9 here, against its own elements 1-4).
  CHECK(C(d, 0) == std::vector<long>{1, 0, 2, 7, 8, 9, 10});
  CHECK(L(d, 0) == std::vector<int>{0, 1, 2, 3, 1, 0, 2});
  CHECK(C(d, 1) == std::vector<long>{2, 3, 1, 7, 9, 10, 11, 12, 13, 14});
  CHECK(L(d, 1) == std::vector<int>{0, 1, 2, 3, 2, 0, 1, 1, 1, 1});
  // Element 2 is an uncut blending element: node 2's sign DOF stays out, node 5's branch DOFs in.
  CHECK(C(d, 2) == std::vector<long>{4, 5, 2, 7, 15, 16, 17, 18});
  CHECK(L(d, 2) == std::vector<int>{0, 1, 2, 3, 1, 1, 1, 1});
  CHECK(C(d, 3) == std::vector<long>{3, 2, 5, 7, 10, 11, 12, 13, 14, 15, 16, 17, 18});
  CHECK(L(d, 3) == std::vector<int>{0, 1, 2, 3, 1, 0, 0, 0, 0, 2, 2, 2, 2});
  CHECK(C(d, 4) == std::vector<long>{3, 5, 6, 7, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22});
  CHECK(L(d, 4) == std::vector<int>{0, 1, 2, 3, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2});
  CHECK(d.offsets == std::vector<long>{0, 7, 17, 25, 38, 54});
}

TEST_CASE("dof_numbering: no enrichment gives the plain connectivity, N = NP", "[dof_numbering]") {
  xfem::Tets tets(1, 4);
  tets << 0, 1, 2, 3;
  const auto d = xfem::dof_numbering(tets, 4, {0, 0, 0, 0}, {0});
  CHECK((d.n == 4 && d.ns == 0 && d.nb == 0));
  CHECK(C(d, 0) == std::vector<long>{0, 1, 2, 3});
}

TEST_CASE("dof_numbering: bad values are named", "[dof_numbering]") {
  xfem::Tets tets(1, 4);
  tets << 0, 1, 2, 3;
  CHECK_THROWS_WITH(xfem::dof_numbering(tets, 4, {0, 3, 0, 0}, {0}), Catch::Contains("point 1: enrichment 3"));
  CHECK_THROWS_WITH(xfem::dof_numbering(tets, 4, {0, 0, 0, 0}, {5}), Catch::Contains("tet 0: cut_class 5"));
  CHECK_THROWS_WITH(xfem::dof_numbering(tets, 4, {0, 0, 0}, {0}), Catch::Contains("3 enrichment values for 4 points"));
}
