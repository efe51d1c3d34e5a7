// SPDX-License-Identifier: MIT
#include "xfem/generate/box_mesh.h"

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cstdio>
#include <map>

#include "xfem/core/error.h"
#include "xfem/io/vtk_io.h"
#include "mesh_checks.h"

namespace {

using xfem_test::total_volume;

}  // namespace

TEST_CASE("box_mesh: tets are positive, fill the box and are conforming", "[box_mesh]") {
  const Eigen::Vector3d lo(0, 0, 0), hi(0.03, 0.06, 0.2);
  const xfem::TetMesh m = xfem::box_mesh({2, 3, 4}, lo, hi);
  CHECK(m.points.rows() == 3 * 4 * 5);
  CHECK(m.tets.rows() == 6 * 2 * 3 * 4);
  CHECK_THAT(total_volume(m), Catch::WithinRel(0.03 * 0.06 * 0.2, 1e-12));
  // Conforming: every interior face is shared by exactly two tets, boundary faces by one, and the
  // boundary has 2 triangles per square of the box surface.
  int boundary = 0;
  for (const auto& [f, count] : xfem_test::face_counts(m.tets)) {
    CHECK(count <= 2);
    boundary += count == 1;
  }
  CHECK(boundary == 2 * 2 * (2 * 3 + 3 * 4 + 2 * 4));
  std::vector<std::string> warnings;
  xfem::TetMesh copy = m;
  CHECK(xfem::validate_tet_mesh(copy, "box", &warnings) == 0);
}

TEST_CASE("box_mesh: a cut by duplicated nodes on the 2x4x14 beam, counted by hand", "[box_mesh]") {
  // z = 0.1 is grid plane k = 7 (dz = 0.2/14), x = 0.015 is i = 1 (dx = 0.015): the nodes i = 0,
  // j = 0..4 of plane 7 are duplicated, 5 copies; the cube layer k = 7 (2 x 4 cubes, 48 tets)
  // uses them.
  const Eigen::Vector3d lo(0, 0, 0), hi(0.03, 0.06, 0.2);
  const xfem::TetMesh m = xfem::box_mesh({2, 4, 14}, lo, hi, {0.1, 0.015});
  const int grid = 3 * 5 * 15;
  REQUIRE(m.points.rows() == grid + 5);
  REQUIRE(m.tets.rows() == 6 * 2 * 4 * 14);
  CHECK_THAT(total_volume(m), Catch::WithinRel(0.03 * 0.06 * 0.2, 1e-12));
  const auto& side = m.point_data.at("cut_side");
  CHECK(side.type == xfem::DataArray::Type::Int32);
  int plus = 0, minus = 0;
  for (int p = 0; p < m.points.rows(); ++p) {
    plus += side(p) == 1;
    minus += side(p) == -1;
    if (side(p) != 0) {
      CHECK(m.points(p, 0) == 0.0);  // x < 0.015: only i = 0
      CHECK_THAT(m.points(p, 2), Catch::WithinAbs(0.1, 1e-15));
    }
  }
  CHECK(plus == 5);
  CHECK(minus == 5);
  for (int c = 0; c < 5; ++c) CHECK(m.points.row(grid + c) == m.points.row(c * 3 + 7 * 15));  // copy of (0, c, 7)
  // No tet uses both an original and its copy; copies only in tets above the plane, originals of
  // the cut only below it.
  int tets_with_copies = 0;
  for (int t = 0; t < m.tets.rows(); ++t) {
    bool has_copy = false, has_original = false;
    double zmean = 0;
    for (int c = 0; c < 4; ++c) {
      has_copy |= side(m.tets(t, c)) == 1;
      has_original |= side(m.tets(t, c)) == -1;
      zmean += m.points(m.tets(t, c), 2) / 4;
    }
    CHECK(!(has_copy && has_original));
    if (has_copy) CHECK(zmean > 0.1);
    if (has_original) CHECK(zmean < 0.1);
    tets_with_copies += has_copy;
  }
  // Layer k = 7, cubes i = 0 (4 of them): each Kuhn tet holds its cube's corner 000, a copy.
  CHECK(tets_with_copies == 4 * 6);
  // Conforming except across the cut: the cut's 2 x 4 squares of faces (i = 0 column: 4 squares,
  // 8 triangles) are boundary twice (once each side), so 16 extra boundary faces.
  int boundary = 0;
  for (const auto& [f, count] : xfem_test::face_counts(m.tets)) {
    CHECK(count <= 2);
    boundary += count == 1;
  }
  CHECK(boundary == 2 * 2 * (2 * 4 + 4 * 14 + 2 * 14) + 2 * 8);
}

TEST_CASE("box_mesh: the paper's reference grid 18x36x120 with the beam cut", "[box_mesh][.slow]") {
  const xfem::TetMesh m = xfem::box_mesh({18, 36, 120}, {0, 0, 0}, {0.03, 0.06, 0.2}, {0.1, 0.015});
  CHECK(m.tets.rows() == 466560);
  CHECK(m.points.rows() == 85396);
  CHECK(19 * 37 * 121 + 9 * 37 == 85396);
}

TEST_CASE("box_mesh: a cut plane off the grid is refused with the nearest planes", "[box_mesh]") {
  const Eigen::Vector3d lo(0, 0, 0), hi(0.03, 0.06, 0.2);
  CHECK_THROWS_WITH(xfem::box_mesh({2, 4, 14}, lo, hi, {0.11, 0.015}),
                    Catch::Contains("cut z = 0.11 is not an interior grid plane") && Catch::Contains("nearest planes"));
  CHECK_THROWS_WITH(xfem::box_mesh({2, 4, 14}, lo, hi, {0.1, 0.01}),
                    Catch::Contains("cut x_front = 0.01 is not an interior grid plane"));
  CHECK_THROWS_WITH(xfem::box_mesh({2, 4, 14}, lo, hi, {0.2, 0.015}), Catch::Contains("strictly inside"));
  CHECK_THROWS_WITH(xfem::box_mesh({2, 4, 14}, lo, hi, {0.1, 0.03}), Catch::Contains("strictly inside"));
  CHECK_THROWS_WITH(xfem::box_mesh({0, 4, 14}, lo, hi), Catch::Contains("cell counts must be positive"));
  CHECK_THROWS_WITH(xfem::box_mesh({2, 4, 14}, hi, lo), Catch::Contains("empty box"));
}

TEST_CASE("box_mesh: the cut mesh survives a .vtu round trip with its cut_side array", "[box_mesh]") {
  const xfem::TetMesh m = xfem::box_mesh({2, 4, 14}, {0, 0, 0}, {0.03, 0.06, 0.2}, {0.1, 0.015});
  const std::string path = "box_mesh_roundtrip.vtu";
  xfem::write_tet_mesh(m, path);
  const xfem::TetMesh r = xfem::read_tet_mesh(path);
  std::remove(path.c_str());
  CHECK(r.points == m.points);
  CHECK(r.tets == m.tets);
  CHECK(r.point_data.at("cut_side").values == m.point_data.at("cut_side").values);
  CHECK(r.point_data.at("cut_side").type == xfem::DataArray::Type::Int32);
}
