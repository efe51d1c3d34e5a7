// SPDX-License-Identifier: MIT
#include "xfem/box_mesh.h"

#include <catch2/catch.hpp>
#include <map>

#include "xfem/vtk_io.h"

TEST_CASE("box_mesh: tets are positive, fill the box and are conforming", "[box_mesh]") {
  const Eigen::Vector3d lo(0, 0, 0), hi(0.03, 0.06, 0.2);
  const xfem::TetMesh m = xfem::box_mesh({2, 3, 4}, lo, hi);
  CHECK(m.points.rows() == 3 * 4 * 5);
  CHECK(m.tets.rows() == 6 * 2 * 3 * 4);
  double volume = 0;
  for (int t = 0; t < m.tets.rows(); ++t) {
    const double v = xfem::signed_volume(m, t);
    CHECK(v > 0);
    volume += v;
  }
  CHECK_THAT(volume, Catch::WithinRel(0.03 * 0.06 * 0.2, 1e-12));
  // Conforming: every interior face is shared by exactly two tets, boundary faces by one, and the
  // boundary has 2 triangles per square of the box surface.
  std::map<std::array<int, 3>, int> faces;
  for (int t = 0; t < m.tets.rows(); ++t)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f;
      int n = 0;
      for (int k = 0; k < 4; ++k)
        if (k != skip) f[n++] = m.tets(t, k);
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  int boundary = 0;
  for (const auto& [f, count] : faces) {
    CHECK(count <= 2);
    boundary += count == 1;
  }
  CHECK(boundary == 2 * 2 * (2 * 3 + 3 * 4 + 2 * 4));
  std::vector<std::string> warnings;
  xfem::TetMesh copy = m;
  CHECK(xfem::validate_tet_mesh(copy, "box", &warnings) == 0);
}
