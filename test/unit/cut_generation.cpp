// SPDX-License-Identifier: MIT
#include "xfem/generate/cut_generation.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <map>

#include "xfem/core/error.h"
#include "xfem/io/vtk_io.h"

namespace {

constexpr double pi = 3.14159265358979323846;

Eigen::Vector3d normal(const xfem::TriangleMesh& m, int f) {
  const Eigen::Vector3d a = m.points.row(m.triangles(f, 0)), b = m.points.row(m.triangles(f, 1)),
                        c = m.points.row(m.triangles(f, 2));
  return (b - a).cross(c - a);
}

// Every triangle's normal has a positive component along `up`, and the mesh passes the reader's
// checks unchanged (no triangle flipped or dropped, each edge in at most two triangles).
void check_oriented(const xfem::TriangleMesh& m, const Eigen::Vector3d& up) {
  for (int f = 0; f < m.triangles.rows(); ++f) {
    INFO("triangle " << f);
    CHECK(normal(m, f).dot(up) > 0);
  }
  xfem::TriangleMesh copy = m;
  std::vector<std::string> warnings;
  xfem::validate_triangle_mesh(copy, "cut", &warnings);
  CHECK(warnings.empty());
  CHECK(copy.triangles == m.triangles);
}

}  // namespace

TEST_CASE("cut_generation: the beam cut is the two triangles of DESIGN.md, normal +z", "[cut_generation]") {
  const xfem::TriangleMesh m = xfem::beam_cut();
  REQUIRE(m.points.rows() == 4);
  REQUIRE(m.triangles.rows() == 2);
  // The corners of DESIGN.md exactly, the front x = 0.015 included.
  CHECK(m.points.row(0) == Eigen::RowVector3d(-0.01, -0.01, 0.1));
  CHECK(m.points.row(1) == Eigen::RowVector3d(0.015, -0.01, 0.1));
  CHECK(m.points.row(2) == Eigen::RowVector3d(-0.01, 0.07, 0.1));
  CHECK(m.points(3, 0) == 0.015);
  CHECK_THAT(m.points(3, 1), Catch::WithinAbs(0.07, 1e-17));
  CHECK(m.points(3, 2) == 0.1);
  CHECK_THAT(xfem::surface_area(m), Catch::WithinRel(0.025 * 0.08, 1e-12));
  check_oriented(m, Eigen::Vector3d::UnitZ());
}

TEST_CASE("cut_generation: a subdivided parallelogram keeps its area, edges and orientation", "[cut_generation]") {
  const Eigen::Vector3d p00(0, 0, 0.1), e1(0.03, 0.01, 0), e2(0, 0.06, 0.02);
  const xfem::TriangleMesh m = xfem::cut_parallelogram(p00, p00 + e1, p00 + e2, {3, 5});
  CHECK(m.points.rows() == 4 * 6);
  CHECK(m.triangles.rows() == 2 * 3 * 5);
  CHECK_THAT(xfem::surface_area(m), Catch::WithinRel(e1.cross(e2).norm(), 1e-12));
  check_oriented(m, e1.cross(e2));
  // The beam cut subdivided: every point of the front column has x = 0.015 exactly.
  const xfem::TriangleMesh b = xfem::beam_cut({4, 6});
  for (int j = 0; j <= 6; ++j) CHECK(b.points(4 + 5 * j, 0) == 0.015);
  CHECK_THROWS_WITH(xfem::cut_parallelogram(p00, p00 + e1, p00 + 2 * e1, {1, 1}), Catch::Contains("parallel"));
  CHECK_THROWS_WITH(xfem::cut_parallelogram(p00, p00 + e1, p00 + e2, {0, 1}), Catch::Contains("at least 1"));
}

TEST_CASE("cut_generation: the sinusoidal sheet follows z0 + A sin(2 pi x / L) with area converging", "[cut_generation]") {
  const double z0 = 0.005, A = 0.01, L = 0.1;
  const Eigen::Vector2d lo(-0.1, -0.07), hi(0.1, 0.01);
  const xfem::TriangleMesh m = xfem::cut_sine(lo, hi, z0, A, L, {200, 4});
  CHECK(m.points.rows() == 201 * 5);
  CHECK(m.triangles.rows() == 2 * 200 * 4);
  for (int p = 0; p < m.points.rows(); ++p)
    CHECK_THAT(m.points(p, 2), Catch::WithinAbs(z0 + A * std::sin(2 * pi * m.points(p, 0) / L), 1e-15));
  check_oriented(m, Eigen::Vector3d::UnitZ());
  // Exact area: (hi_y - lo_y) * integral of sqrt(1 + (2 pi A / L cos(2 pi x / L))^2) dx over two
  // periods, by Simpson's rule on 20000 intervals (error far below 1e-9). The triangulated sheet
  // is a chordal approximation: its area is slightly smaller, by O(h^2) ~ 1e-4 relative here.
  const int n = 20000;
  double s = 0;
  for (int i = 0; i <= n; ++i) {
    const double x = lo(0) + (hi(0) - lo(0)) * i / n, d = 2 * pi * A / L * std::cos(2 * pi * x / L);
    s += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * std::sqrt(1 + d * d);
  }
  const double exact = (hi(1) - lo(1)) * s * (hi(0) - lo(0)) / n / 3;
  const double area = xfem::surface_area(m);
  CHECK(area < exact);
  CHECK_THAT(area, Catch::WithinRel(exact, 1e-4));
  CHECK_THROWS_WITH(xfem::cut_sine(lo, hi, z0, A, 0.0, {2, 2}), Catch::Contains("wavelength must be positive"));
  CHECK_THROWS_WITH(xfem::cut_sine(hi, lo, z0, A, L, {2, 2}), Catch::Contains("empty rectangle"));
}

TEST_CASE("cut_generation: the disc is a regular 6n-gon of the right area, oriented along its normal", "[cut_generation]") {
  const Eigen::Vector3d c(0.01, -0.02, 0.03), n(1, 2, 2);
  const int rings = 5;
  const double r = 0.03;
  const xfem::TriangleMesh m = xfem::cut_disc(c, n, r, rings);
  CHECK(m.points.rows() == 1 + 3 * rings * (rings + 1));
  CHECK(m.triangles.rows() == 6 * rings * rings);
  // Area of the inscribed regular 6n-gon, (6n / 2) r^2 sin(2 pi / 6n).
  CHECK_THAT(xfem::surface_area(m), Catch::WithinRel(3.0 * rings * r * r * std::sin(2 * pi / (6 * rings)), 1e-12));
  check_oriented(m, n);
  for (int p = 0; p < m.points.rows(); ++p) {
    const Eigen::Vector3d x = m.points.row(p).transpose() - c;
    CHECK(std::abs(x.dot(n.normalized())) < 1e-15);  // in the plane
    CHECK(x.norm() <= r * (1 + 1e-15));
  }
  // The boundary is the outer ring only: 6n edges in one triangle each.
  std::map<std::pair<int, int>, int> edges;
  for (int f = 0; f < m.triangles.rows(); ++f)
    for (int e = 0; e < 3; ++e) {
      int a = m.triangles(f, e), b = m.triangles(f, (e + 1) % 3);
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  int boundary = 0;
  for (const auto& [e, k] : edges) boundary += k == 1;
  CHECK(boundary == 6 * rings);
  CHECK_THROWS_WITH(xfem::cut_disc(c, Eigen::Vector3d::Zero(), r, 2), Catch::Contains("normal is zero"));
  CHECK_THROWS_WITH(xfem::cut_disc(c, n, -1, 2), Catch::Contains("radius must be positive"));
  CHECK_THROWS_WITH(xfem::cut_disc(c, n, r, 0), Catch::Contains("rings must be at least 1"));
}

TEST_CASE("cut_generation: cuts are the same bit for bit each time and survive a .vtp round trip", "[cut_generation]") {
  const xfem::TriangleMesh a = xfem::cut_sine({-0.1, -0.07}, {0.1, 0.01}, 0.005, 0.01, 0.1, {8, 4});
  const xfem::TriangleMesh b = xfem::cut_sine({-0.1, -0.07}, {0.1, 0.01}, 0.005, 0.01, 0.1, {8, 4});
  CHECK(a.points == b.points);
  CHECK(a.triangles == b.triangles);
  const std::string path = "cut_generation_roundtrip.vtp";
  xfem::write_triangle_mesh(a, path);
  const xfem::TriangleMesh r = xfem::read_triangle_mesh(path);
  std::remove(path.c_str());
  CHECK(r.points == a.points);
  CHECK(r.triangles == a.triangles);
}

TEST_CASE("cut_generation: the zig-zag sheet has flat strips, straight folds along y and the right area",
          "[cut_generation]") {
  const Eigen::Vector2d lo(-0.13, -0.1), hi(1.07, 1.1);
  const double z0 = 0.47, A = 0.13;
  const int folds = 3, divisions = 2;
  const xfem::TriangleMesh m = xfem::cut_zigzag(lo, hi, z0, A, folds, divisions);
  const int n0 = folds + 1;
  CHECK(m.points.rows() == (n0 + 1) * (divisions + 1));
  CHECK(m.triangles.rows() == 2 * n0 * divisions);
  check_oriented(m, Eigen::Vector3d::UnitZ());
  // Each strip: width w in x, rises or falls by 2A: area (hi_y - lo_y) sqrt(w^2 + 4 A^2).
  const double w = (hi(0) - lo(0)) / n0;
  CHECK_THAT(xfem::surface_area(m), Catch::WithinRel((hi(1) - lo(1)) * n0 * std::sqrt(w * w + 4 * A * A), 1e-12));
  // Fold line i (column i of the point grid): one x and one z bit for bit, z alternating
  // z0 - A (i even) and z0 + A (i odd), all y from lo to hi.
  for (int i = 0; i <= n0; ++i) {
    INFO("fold column " << i);
    CHECK_THAT(m.points(i, 0), Catch::WithinAbs(lo(0) + i * w, 1e-15));
    for (int j = 0; j <= divisions; ++j) {
      CHECK(m.points(i + (n0 + 1) * j, 0) == m.points(i, 0));
      CHECK(m.points(i + (n0 + 1) * j, 2) == (i % 2 == 0 ? z0 - A : z0 + A));
    }
    CHECK(m.points(i, 1) == lo(1));
    CHECK(m.points(i + (n0 + 1) * divisions, 1) == hi(1));
  }
  // Every triangle lies in its strip's plane: unit normal (-s, 0, 1) / |.|, s = +-2A/w, the sign
  // alternating from strip to strip (so the folds are real folds, not flat).
  for (int f = 0; f < m.triangles.rows(); ++f) {
    const int strip = (f / 2) % n0;
    const double s = (strip % 2 == 0 ? 2 : -2) * A / w;
    INFO("triangle " << f << ", strip " << strip);
    CHECK((normal(m, f).normalized() - Eigen::Vector3d(-s, 0, 1).normalized()).norm() < 1e-14);
  }
  // The boundary runs round the rectangle: 2 n0 + 2 divisions edges in one triangle each.
  std::map<std::pair<int, int>, int> edges;
  for (int f = 0; f < m.triangles.rows(); ++f)
    for (int e = 0; e < 3; ++e) {
      int a = m.triangles(f, e), b = m.triangles(f, (e + 1) % 3);
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  int boundary = 0;
  for (const auto& [e, k] : edges) boundary += k == 1;
  CHECK(boundary == 2 * n0 + 2 * divisions);
  // No folds: one flat strip sloping from z0 - A to z0 + A.
  CHECK(xfem::cut_zigzag(lo, hi, z0, A, 0, 1).triangles.rows() == 2);
  CHECK_THROWS_WITH(xfem::cut_zigzag(lo, hi, z0, A, -1, 1), Catch::Contains("folds must be 0 or more"));
  CHECK_THROWS_WITH(xfem::cut_zigzag(lo, hi, z0, A, 2, 0), Catch::Contains("at least 1"));
  CHECK_THROWS_WITH(xfem::cut_zigzag(hi, lo, z0, A, 2, 1), Catch::Contains("empty rectangle"));
}

TEST_CASE("cut_generation: merged surfaces keep every piece's points, triangles and orientation", "[cut_generation]") {
  const xfem::TriangleMesh a = xfem::cut_parallelogram({-0.1, -0.1, 0.3}, {1.1, -0.1, 0.3}, {-0.1, 1.1, 0.3}, {2, 1});
  // Normal -z: edges swapped.
  const xfem::TriangleMesh b = xfem::cut_parallelogram({-0.1, -0.1, 0.7}, {-0.1, 1.1, 0.7}, {1.1, -0.1, 0.7}, {1, 1});
  const xfem::TriangleMesh m = xfem::merge_surfaces({a, b});
  REQUIRE(m.points.rows() == a.points.rows() + b.points.rows());
  REQUIRE(m.triangles.rows() == a.triangles.rows() + b.triangles.rows());
  CHECK_THAT(xfem::surface_area(m), Catch::WithinRel(xfem::surface_area(a) + xfem::surface_area(b), 1e-15));
  for (int f = 0; f < m.triangles.rows(); ++f) {
    INFO("triangle " << f);
    CHECK(normal(m, f).z() * (f < a.triangles.rows() ? 1 : -1) > 0);
  }
  CHECK(m.points.topRows(a.points.rows()) == a.points);
  CHECK(m.points.bottomRows(b.points.rows()) == b.points);
  // Two pieces with opposite normals pass the reader's checks unchanged (orientation is per piece).
  xfem::TriangleMesh copy = m;
  std::vector<std::string> warnings;
  xfem::validate_triangle_mesh(copy, "cut", &warnings);
  CHECK(warnings.empty());
  CHECK(copy.triangles == m.triangles);
}
