// SPDX-License-Identifier: MIT
#include "xfem/post/point_probe.h"

#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <string>

#include "xfem/generate/box_mesh.h"
#include "xfem/core/error.h"

namespace {
using Field = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

// A file with `text`, removed when the object goes (at the end of the full expression).
struct TempFile {
  std::string path;
  TempFile(const std::string& name, const std::string& text) : path("point_probe_test_" + name) {
    std::ofstream(path) << text;
  }
  ~TempFile() { std::remove(path.c_str()); }
};

Eigen::Vector3d linear(const Eigen::Vector3d& x) {
  return Eigen::Vector3d(0.1 + 2 * x[0] - x[2], 3 * x[1], -0.5 * x[0] + x[1] + 4 * x[2]);
}

std::string message_of(const std::string& path) {
  try {
    xfem::read_probe_points(path);
  } catch (const xfem::Error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("point_probe: CSV points with and without sides, comments skipped", "[point_probe]") {
  const auto p =
      xfem::read_probe_points(TempFile("a.csv", "# a comment\nx,y,z,side\n0,0.03,0.1,1\n 1e-3 , 2, 3 ,-1\n").path);
  REQUIRE(p.size() == 2);
  CHECK(p[0].x == Eigen::Vector3d(0, 0.03, 0.1));
  CHECK(p[0].side == 1);
  CHECK(p[1].x == Eigen::Vector3d(1e-3, 2, 3));
  CHECK(p[1].side == -1);
  const auto q = xfem::read_probe_points(TempFile("b.csv", "x,y,z\n1,2,3\n").path);
  REQUIRE(q.size() == 1);
  CHECK(q[0].side == 0);
}

TEST_CASE("point_probe: bad CSV input is refused with the line", "[point_probe]") {
  CHECK(message_of(TempFile("h.csv", "a,b,c\n1,2,3\n").path).find("line 1: the header must be x,y,z") !=
        std::string::npos);
  CHECK(message_of(TempFile("n.csv", "x,y,z\n1,abc,3\n").path).find("line 2: 'abc' is not a finite number") !=
        std::string::npos);
  CHECK(message_of(TempFile("i.csv", "x,y,z\n1,inf,3\n").path).find("line 2: 'inf' is not a finite number") !=
        std::string::npos);
  CHECK(message_of(TempFile("s.csv", "x,y,z,side\n1,2,3,2\n").path).find("line 2: side must be -1, 0 or 1") !=
        std::string::npos);
  CHECK(message_of(TempFile("c.csv", "x,y,z,side\n1,2,3\n").path).find("line 2: 3 values, expected 4") !=
        std::string::npos);
  CHECK(message_of(TempFile("e.csv", "x,y,z\n").path).find("no point to probe") != std::string::npos);
  CHECK(message_of(TempFile("z.csv", "").path).find("no header line") != std::string::npos);
  CHECK(message_of("point_probe_test_missing.csv").find("point_probe_test_missing.csv") != std::string::npos);
}

TEST_CASE("point_probe: a linear field is sampled exactly; outside points are an error", "[point_probe]") {
  const auto m = xfem::box_mesh({2, 3, 4}, {0, 0, 0}, {0.03, 0.06, 0.2});
  Field u(m.points.rows(), 3);
  for (Eigen::Index i = 0; i < m.points.rows(); ++i) u.row(i) = linear(m.points.row(i).transpose()).transpose();
  const auto field = xfem::plain_field(m, u, 1e-9);
  const std::vector<xfem::ProbePoint> points = {{{0.011, 0.037, 0.123}, 0}, {{0.03, 0.06, 0.2}, 0}, {{0, 0, 0}, 0}};
  const auto v = xfem::probe(field, points, "points.csv");
  for (std::size_t k = 0; k < points.size(); ++k)
    CHECK((v[k] - linear(points[k].x)).norm() < 1e-14);
  const std::vector<xfem::ProbePoint> outside = {{{0.01, 0.01, 0.01}, 0}, {{0.04, 0.01, 0.01}, 0}};
  CHECK_THROWS_WITH(xfem::probe(field, outside, "points.csv"),
                    Catch::Contains("points.csv: point 2 (0.04, 0.01, 0.01) lies outside the mesh"));
}

TEST_CASE("point_probe: on a cut of doubled nodes, each side gives its own face's value", "[point_probe]") {
  // Cut z = 0.1 for x < 0.015: the copies (cut_side +1, above) move up by 1 mm, the rest stays.
  const auto m = xfem::box_mesh({2, 2, 4}, {0, 0, 0}, {0.03, 0.06, 0.2}, xfem::BoxCut{0.1, 0.015});
  Field u = Field::Zero(m.points.rows(), 3);
  const auto& side = m.point_data.at("cut_side");
  for (Eigen::Index i = 0; i < m.points.rows(); ++i)
    if (side(i) > 0) u(i, 2) = 1e-3;
  const auto field = xfem::plain_field(m, u, 1e-9);
  const std::vector<xfem::ProbePoint> points = {{{0, 0.03, 0.1}, 1}, {{0, 0.03, 0.1}, -1}};
  const auto v = xfem::probe(field, points, "points.csv");
  CHECK(v[0][2] == Approx(1e-3));
  CHECK(v[1][2] == 0.0);
}

TEST_CASE("point_probe: the CSV written holds every point and value", "[point_probe]") {
  const std::string path = "point_probe_test_out.csv";
  xfem::write_probe_csv({{{1, 2, 3}, -1}}, {Eigen::Vector3d(0.5, -0.25, 1e-3)}, path);
  std::ifstream in(path);
  std::string header, line;
  std::getline(in, header);
  std::getline(in, line);
  CHECK(header == "x,y,z,side,ux,uy,uz");
  CHECK(line == "1,2,3,-1,0.5,-0.25,0.001");
  std::remove(path.c_str());
}
