// SPDX-License-Identifier: MIT
#include "xfem/geometry/cut_surface.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "xfem/core/error.h"
#include "xfem/generate/cut_generation.h"

namespace {

/// The paper's beam cut (DESIGN.md): z = 0.1 for x <= 0.015, two triangles, normal +z.
xfem::TriangleMesh beam_cut() {
  xfem::TriangleMesh m;
  m.points.resize(4, 3);
  m.points << -0.01, -0.01, 0.1,  //
      -0.01, 0.07, 0.1,           //
      0.015, -0.01, 0.1,          //
      0.015, 0.07, 0.1;
  m.triangles.resize(2, 3);
  m.triangles << 0, 2, 1,  //
      1, 2, 3;
  return m;
}

/// A roof: two unit squares meeting at the ridge x = 0 (z = 0) and sloping down to z = -1 at
/// x = +-1 (a concave-down dihedral), normals pointing up.
xfem::TriangleMesh roof() {
  xfem::TriangleMesh m;
  m.points.resize(6, 3);
  m.points << -1, 0, -1,  //
      0, 0, 0,            //
      1, 0, -1,           //
      -1, 1, -1,          //
      0, 1, 0,            //
      1, 1, -1;
  m.triangles.resize(4, 3);
  m.triangles << 0, 1, 4,  //
      0, 4, 3,             //
      1, 2, 5,             //
      1, 5, 4;
  return m;
}

}  // namespace

TEST_CASE("cut_surface: unit normals follow the triangle orientation", "[cut_surface]") {
  const xfem::CutSurface cut(beam_cut());
  CHECK(cut.unit_normal(0).isApprox(Eigen::Vector3d(0, 0, 1)));
  CHECK(cut.unit_normal(1).isApprox(Eigen::Vector3d(0, 0, 1)));
  CHECK_THROWS_WITH(cut.unit_normal(2), Catch::Contains("triangle index 2 out of range"));
}

TEST_CASE("cut_surface: closest point, triangle and distance", "[cut_surface]") {
  const xfem::CutSurface cut(beam_cut());
  SECTION("above the interior: the foot of the perpendicular") {
    const auto c = cut.closest({0.0, 0.0, 0.13});
    CHECK(c.point.isApprox(Eigen::Vector3d(0, 0, 0.1)));
    CHECK_THAT(c.distance, Catch::WithinAbs(0.03, 1e-15));
    // (0, 0) lies below the diagonal from (0.015,-0.01) to (-0.01,0.07), i.e. in triangle 0.
    CHECK(c.triangle == 0);
  }
  SECTION("ahead of the front: the closest point is on the front edge x = 0.015") {
    const auto c = cut.closest({0.025, 0.03, 0.1});
    CHECK(c.point.isApprox(Eigen::Vector3d(0.015, 0.03, 0.1)));
    CHECK_THAT(c.distance, Catch::WithinAbs(0.01, 1e-15));
    CHECK(c.triangle == 1);
  }
}

TEST_CASE("cut_surface: side is +1 on the normal's side, -1 below, +1 on the cut", "[cut_surface]") {
  const xfem::CutSurface cut(beam_cut());
  CHECK(cut.side({0.005, 0.03, 0.1 + 1e-9}) == 1);
  CHECK(cut.side({0.005, 0.03, 0.1 - 1e-9}) == -1);
  CHECK(cut.side({0.005, 0.03, 0.1}) == 1);
  // Ahead of the front the closest point is on the boundary edge: judged by that edge's normal.
  CHECK(cut.side({0.03, 0.03, 0.11}) == 1);
  CHECK(cut.side({0.03, 0.03, 0.09}) == -1);
  // Beyond a boundary vertex: the vertex pseudo-normal (here +z).
  CHECK(cut.side({0.03, 0.08, 0.12}) == 1);
  CHECK(cut.side({0.03, 0.08, 0.08}) == -1);
  // Above the diagonal edge shared by the two triangles.
  CHECK(cut.side({0.0025, 0.03, 0.2}) == 1);
  CHECK(cut.side({0.0025, 0.03, 0.0}) == -1);
}

TEST_CASE("cut_surface: side at a ridge uses the pseudo-normal, not one triangle's normal",
          "[cut_surface]") {
  const xfem::CutSurface cut(roof());
  // Points just below the ridge: their closest point is on the ridge edge x = 0, and both face
  // normals taken alone would give contradictory answers for points off the symmetry plane.
  CHECK(cut.side({0.0, 0.5, -0.1}) == -1);
  CHECK(cut.side({0.05, 0.5, -0.2}) == -1);
  CHECK(cut.side({-0.05, 0.5, -0.2}) == -1);
  CHECK(cut.side({0.0, 0.5, 0.1}) == 1);
  // Beyond the ridge's end vertex (y > 1), still below: vertex pseudo-normal.
  CHECK(cut.side({0.0, 1.5, -0.1}) == -1);
  CHECK(cut.side({0.0, 1.5, 0.1}) == 1);
  // Under the left slope, far from the ridge: the face normal.
  CHECK(cut.side({-0.5, 0.5, -0.6}) == -1);
  CHECK(cut.side({-0.5, 0.5, -0.4}) == 1);
}

TEST_CASE("cut_surface: meets_segment with closed segments and closed triangles", "[cut_surface]") {
  const xfem::CutSurface cut(beam_cut());
  CHECK(cut.meets_segment({0, 0, 0}, {0, 0, 0.2}));
  CHECK_FALSE(cut.meets_segment({0, 0, 0}, {0, 0, 0.09}));
  // Ends exactly on the cut: closed segment, so it meets.
  CHECK(cut.meets_segment({0, 0, 0}, {0, 0, 0.1}));
  // Crossing just ahead of the front misses; exactly through the front edge meets (closed cut).
  CHECK_FALSE(cut.meets_segment({0.0150001, 0, 0}, {0.0150001, 0, 0.2}));
  CHECK(cut.meets_segment({0.015, 0.03, 0}, {0.015, 0.03, 0.2}));
  // Lying in the cut's plane, overlapping it: meets; in the plane but beyond the front: misses.
  CHECK(cut.meets_segment({0.0, 0.0, 0.1}, {0.03, 0.0, 0.1}));
  CHECK_FALSE(cut.meets_segment({0.02, 0.0, 0.1}, {0.03, 0.0, 0.1}));
  // A degenerate segment (a point).
  CHECK(cut.meets_segment({0.0, 0.0, 0.1}, {0.0, 0.0, 0.1}));
  CHECK_FALSE(cut.meets_segment({0.0, 0.0, 0.2}, {0.0, 0.0, 0.2}));
  // Through the shared diagonal edge and through a vertex.
  CHECK(cut.meets_segment({0.0025, 0.03, 0}, {0.0025, 0.03, 0.2}));
  CHECK(cut.meets_segment({0.015, 0.07, 0}, {0.015, 0.07, 0.2}));
}

TEST_CASE("cut_surface: boundary edges follow their triangle's direction", "[cut_surface]") {
  const xfem::CutSurface cut(beam_cut());
  const auto& b = cut.boundary_edges();
  REQUIRE(b.size() == 4);
  // Triangle 0 = (0, 2, 1): boundary edges 0->2 and 1->0 (2->1 is the shared diagonal).
  CHECK((b[0].p0 == 0 && b[0].p1 == 2 && b[0].triangle == 0));
  CHECK((b[1].p0 == 1 && b[1].p1 == 0 && b[1].triangle == 0));
  // Triangle 1 = (1, 2, 3): 2->3 (the front x = 0.015) and 3->1.
  CHECK((b[2].p0 == 2 && b[2].p1 == 3 && b[2].triangle == 1));
  CHECK((b[3].p0 == 3 && b[3].p1 == 1 && b[3].triangle == 1));
  const xfem::CutSurface r(roof());
  CHECK(r.boundary_edges().size() == 6);  // 9 edges, 3 of them shared (the ridge and 2 diagonals)
}

TEST_CASE("cut_surface: a surface without triangles is an error", "[cut_surface]") {
  xfem::TriangleMesh empty;
  CHECK_THROWS_AS(xfem::CutSurface(empty), xfem::Error);
}

TEST_CASE("cut_surface: sides of a few points close together, and side at a given closest point, equal side()", "[cut_surface]") {
  // A wavy cut of 800 triangles; clusters of 2 to 12 points (as the centroids of one tet's pieces)
  // around it and beyond its edges, where the side is judged at edge and vertex pseudo-normals.
  const xfem::CutSurface cut(xfem::cut_sine({0, 0}, {1, 1}, 0.5, 0.1, 0.4, {20, 20}));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  int above = 0, below = 0;
  for (int cluster = 0; cluster < 500; ++cluster) {
    const Eigen::Vector3d at(0.5 + 0.6 * u(rng), 0.5 + 0.6 * u(rng), 0.5 + 0.15 * u(rng));
    const double size = cluster % 2 ? 0.01 : 0.05;
    std::vector<Eigen::Vector3d> points(2 + cluster % 11);
    for (auto& x : points) x = at + size * Eigen::Vector3d(u(rng), u(rng), u(rng));
    std::vector<int> sides(points.size(), 0);
    cut.sides(points.data(), static_cast<int>(points.size()), sides.data());
    for (std::size_t i = 0; i < points.size(); ++i) {
      REQUIRE(sides[i] == cut.side(points[i]));
      REQUIRE(cut.side(points[i], cut.closest(points[i])) == sides[i]);  // judged at a closest point given
      (sides[i] > 0 ? above : below) += 1;
    }
  }
  CHECK(above > 500);
  CHECK(below > 500);
  cut.sides(nullptr, 0, nullptr);  // no points: nothing asked
  CHECK_THROWS_WITH(cut.side({0, 0, 0}, xfem::CutSurface::Closest{}), Catch::Contains("out of range"));
}
