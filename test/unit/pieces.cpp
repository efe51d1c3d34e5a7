// SPDX-License-Identifier: MIT
#include "xfem/system/pieces.h"

#include <catch2/catch.hpp>

#include "xfem/generate/box_mesh.h"

namespace {

// A column of 3 cubes (18 tets, 6 per cube layer, layer k = tets 6k..6k+5), cut through the
// middle layer by a plane between z = 1 and z = 2: nodes of z-levels 0, 1 below (-1), 2, 3 above.
xfem::EnrichedMesh column_cut_in_the_middle() {
  xfem::EnrichedMesh m;
  m.mesh = xfem::box_mesh({1, 1, 3}, Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1, 3));
  for (Eigen::Index v = 0; v < m.mesh.points.rows(); ++v) m.side.push_back(m.mesh.points(v, 2) > 1.5 ? 1 : -1);
  m.cut_class.assign(18, 0);
  for (int t = 6; t < 12; ++t) m.cut_class[t] = 2;
  return m;
}

std::vector<char> constrained_at_z(const xfem::EnrichedMesh& m, double z) {
  std::vector<char> c(m.mesh.points.rows(), 0);
  for (Eigen::Index v = 0; v < m.mesh.points.rows(); ++v) c[v] = m.mesh.points(v, 2) == z;
  return c;
}

}  // namespace

TEST_CASE("pieces: a body cut through falls apart into two pieces, the loose one named", "[pieces]") {
  const xfem::EnrichedMesh m = column_cut_in_the_middle();
  REQUIRE(m.tets() == 18);
  for (int t = 0; t < 6; ++t) REQUIRE(m.mesh.points(m.mesh.tets(t, 0), 2) <= 1.0);  // layer order as assumed
  const auto pieces = xfem::find_pieces(m, constrained_at_z(m, 0.0));
  REQUIRE(pieces.size() == 2);
  // Each piece: 6 uncut tets + 6 halves of the cut layer.
  CHECK(pieces[0].tets == 12);
  CHECK(pieces[1].tets == 12);
  CHECK(pieces[0].constrained);
  CHECK_FALSE(pieces[1].constrained);
}

TEST_CASE("pieces: a constrained node holds only its own side of a cut tet", "[pieces]") {
  const xfem::EnrichedMesh m = column_cut_in_the_middle();
  // z = 1 nodes (below the cut) touch the cut layer's lower halves: piece 1 only.
  auto pieces = xfem::find_pieces(m, constrained_at_z(m, 1.0));
  REQUIRE(pieces.size() == 2);
  CHECK(pieces[0].constrained);
  CHECK_FALSE(pieces[1].constrained);
  // z = 2 nodes (above) hold the upper piece.
  pieces = xfem::find_pieces(m, constrained_at_z(m, 2.0));
  CHECK_FALSE(pieces[0].constrained);
  CHECK(pieces[1].constrained);
}

TEST_CASE("pieces: with the mesh's shared faces found once, the same pieces for every cut", "[pieces]") {
  xfem::EnrichedMesh m = column_cut_in_the_middle();
  const xfem::SharedFaces faces = xfem::shared_faces(m.mesh);
  for (int partial : {-1, 8, 3}) {
    INFO("partially cut tet " << partial);
    if (partial >= 0) m.cut_class[partial] = 1;
    for (double z : {0.0, 1.0, 2.0}) {
      const auto a = xfem::find_pieces(m, constrained_at_z(m, z));
      const auto b = xfem::find_pieces(m, constrained_at_z(m, z), faces);
      REQUIRE(a.size() == b.size());
      for (std::size_t i = 0; i < a.size(); ++i) {
        CHECK(a[i].tets == b[i].tets);
        CHECK(a[i].constrained == b[i].constrained);
      }
    }
  }
  const xfem::SharedFaces other = xfem::shared_faces(xfem::box_mesh({1, 1, 1}, {0, 0, 0}, {1, 1, 1}));
  CHECK_THROWS_WITH(xfem::find_pieces(m, constrained_at_z(m, 0.0), other), Catch::Matchers::Contains("another mesh"));
}

TEST_CASE("pieces: a partially cut tet holds both sides together", "[pieces]") {
  xfem::EnrichedMesh m = column_cut_in_the_middle();
  m.cut_class[8] = 1;  // the crack front runs through tet 8
  const auto pieces = xfem::find_pieces(m, constrained_at_z(m, 0.0));
  REQUIRE(pieces.size() == 1);
  CHECK(pieces[0].tets == 6 + 5 * 2 + 1 + 6);
  CHECK(pieces[0].constrained);
}

TEST_CASE("pieces: an uncut body is one piece, and mismatched arrays are refused", "[pieces]") {
  xfem::EnrichedMesh m = column_cut_in_the_middle();
  m.cut_class.assign(18, 0);
  const auto pieces = xfem::find_pieces(m, constrained_at_z(m, 3.0));
  REQUIRE(pieces.size() == 1);
  CHECK(pieces[0].tets == 18);
  CHECK(pieces[0].constrained);
  m.cut_class.pop_back();
  CHECK_THROWS_WITH(xfem::find_pieces(m, constrained_at_z(m, 3.0)), Catch::Matchers::Contains("17 cut classes for 18 tets"));
}

TEST_CASE("pieces: a tet naming a node outside the points is refused with its id", "[pieces]") {
  xfem::EnrichedMesh m = column_cut_in_the_middle();
  m.mesh.tets(5, 2) = static_cast<int>(m.mesh.points.rows());
  REQUIRE_THROWS_WITH(xfem::find_pieces(m, constrained_at_z(m, 0.0)),
                      Catch::Contains("tet 5 has node") && Catch::Contains("outside the 16 points"));
}

TEST_CASE("pieces: a mesh of many cubes is one piece, the same with and without the cut layer", "[pieces]") {
  // Enough tets for every node to own several faces: the bucketed face sort must pair them all.
  xfem::EnrichedMesh m;
  m.mesh = xfem::box_mesh({6, 5, 4}, Eigen::Vector3d::Zero(), Eigen::Vector3d(6, 5, 4));
  m.side.assign(m.mesh.points.rows(), 1);
  m.cut_class.assign(m.tets(), 0);
  const auto pieces = xfem::find_pieces(m, std::vector<char>(m.mesh.points.rows(), 0));
  REQUIRE(pieces.size() == 1);
  CHECK(pieces[0].tets == 6 * 5 * 4 * 6);
  CHECK_FALSE(pieces[0].constrained);
}
