// SPDX-License-Identifier: MIT
#include "xfem/generate/unstructured_mesh.h"

#include <catch2/catch.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "xfem/core/error.h"
#include "xfem/generate/mesh_ordering.h"
#include "xfem/generate/organ_shape.h"
#include "xfem/io/vtk_io.h"
#include "mesh_checks.h"

namespace {

// Points on faces used by one tet only: the boundary.
std::set<int> boundary_points(const xfem::TetMesh& m) {
  const auto faces = xfem_test::face_counts(m.tets);
  std::set<int> points;
  for (const auto& [f, count] : faces) {
    CHECK(count <= 2);  // conforming
    if (count == 1) points.insert(f.begin(), f.end());
  }
  return points;
}

using xfem_test::total_volume;

// Every point is used by a tet.
void check_all_points_used(const xfem::TetMesh& m) {
  std::vector<bool> used(m.points.rows(), false);
  for (int t = 0; t < m.tets.rows(); ++t)
    for (int c = 0; c < 4; ++c) used[m.tets(t, c)] = true;
  CHECK(std::count(used.begin(), used.end(), false) == 0);
}

}  // namespace

TEST_CASE("unstructured_mesh: the box is filled exactly, its corners and faces kept", "[unstructured_mesh]") {
  const Eigen::Vector3d lo(0, 0, 0), hi(0.03, 0.06, 0.2);
  const xfem::TetMesh m = xfem::unstructured_box_mesh(lo, hi, 0.012);
  CHECK(m.tets.rows() > 500);
  check_all_points_used(m);
  // The boundary is the box surface, so the volume is the box's up to rounding.
  CHECK_THAT(total_volume(m), Catch::WithinRel(0.03 * 0.06 * 0.2, 1e-9));
  for (int p : boundary_points(m)) {
    INFO("boundary point " << p << ": " << m.points.row(p));
    bool on_face = false;
    for (int a = 0; a < 3; ++a) on_face |= m.points(p, a) == lo[a] || m.points(p, a) == hi[a];
    CHECK(on_face);
  }
  for (int c = 0; c < 8; ++c) {  // sharp corners: mesh vertices
    const Eigen::RowVector3d corner(c & 1 ? hi.x() : lo.x(), c & 2 ? hi.y() : lo.y(), c & 4 ? hi.z() : lo.z());
    bool found = false;
    for (int p = 0; p < m.points.rows() && !found; ++p) found = m.points.row(p) == corner;
    INFO("corner " << corner);
    CHECK(found);
  }
  xfem::TetMesh copy = m;
  std::vector<std::string> warnings;
  CHECK(xfem::validate_tet_mesh(copy, "box", &warnings) == 0);
}

TEST_CASE("unstructured_mesh: the same arguments give the same mesh, and it reads back", "[unstructured_mesh]") {
  const xfem::TetMesh a = xfem::unstructured_box_mesh({0, 0, 0}, {0.03, 0.06, 0.2}, 0.015);
  const xfem::TetMesh b = xfem::unstructured_box_mesh({0, 0, 0}, {0.03, 0.06, 0.2}, 0.015);
  CHECK(a.points == b.points);
  CHECK(a.tets == b.tets);
  const std::string path = "unstructured_mesh_roundtrip.vtu";
  xfem::write_tet_mesh(a, path);
  const xfem::TetMesh r = xfem::read_tet_mesh(path);
  std::remove(path.c_str());
  CHECK(r.points == a.points);
  CHECK(r.tets == a.tets);
}

TEST_CASE("unstructured_mesh: points and tets come numbered along the space-filling curve", "[unstructured_mesh]") {
  const xfem::TetMesh m = xfem::unstructured_box_mesh({0, 0, 0}, {0.03, 0.06, 0.2}, 0.01);
  const xfem::MeshOrdering o = xfem::spatial_ordering(m);  // identity when already in order
  std::vector<int> identity_p(m.points.rows()), identity_t(m.tets.rows());
  for (std::size_t i = 0; i < identity_p.size(); ++i) identity_p[i] = static_cast<int>(i);
  for (std::size_t i = 0; i < identity_t.size(); ++i) identity_t[i] = static_cast<int>(i);
  CHECK(o.point_order == identity_p);
  CHECK(o.tet_order == identity_t);
  const xfem::TetMesh organ = xfem::implicit_mesh(xfem::organ_function, xfem::organ_bounding_radius, 0.015);
  const xfem::TetMesh again = xfem::spatially_ordered(organ);
  CHECK(again.points == organ.points);
  CHECK(again.tets == organ.tets);
}

TEST_CASE("unstructured_mesh: a finer size gives more tets", "[unstructured_mesh]") {
  const long coarse = xfem::unstructured_box_mesh({0, 0, 0}, {0.03, 0.06, 0.2}, 0.02).tets.rows();
  const long fine = xfem::unstructured_box_mesh({0, 0, 0}, {0.03, 0.06, 0.2}, 0.01).tets.rows();
  CAPTURE(coarse, fine);
  CHECK(fine > 4 * coarse);  // ~8x for half the size
}

TEST_CASE("unstructured_mesh: the organ's volume and surface match its implicit function", "[unstructured_mesh]") {
  const xfem::TetMesh m = xfem::implicit_mesh(xfem::organ_function, xfem::organ_bounding_radius, 0.012);
  check_all_points_used(m);
  CHECK(m.tets.rows() > 1000);
  // Boundary points lie on the zero set: located by bisection to 1e-7 m, |grad f| < 200 / m.
  for (int p : boundary_points(m)) CHECK(std::abs(xfem::organ_function(m.points.row(p).transpose())) < 1e-4);
  // Polyhedral approximation inscribed in a convex-ish body: a little less volume, within 3%.
  const double v = total_volume(m);
  CHECK(v < xfem::organ_volume());
  CHECK_THAT(v, Catch::WithinRel(xfem::organ_volume(), 0.03));
  const Eigen::Vector3d extent = m.points.colwise().maxCoeff() - m.points.colwise().minCoeff();
  CHECK_THAT(extent.x(), Catch::WithinAbs(0.15, 0.005));  // 0.15 m long
}

TEST_CASE("unstructured_mesh: a closed surface is meshed, its volume kept", "[unstructured_mesh]") {
  // A unit-ish tetrahedron: 4 triangles, outward.
  xfem::TriangleMesh s;
  s.points.resize(4, 3);
  s.points << 0, 0, 0, 0.1, 0, 0, 0, 0.1, 0, 0, 0, 0.1;
  s.triangles.resize(4, 3);
  s.triangles << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
  const xfem::TetMesh m = xfem::surface_mesh(s, 0.02, "tet.off");
  CHECK(m.tets.rows() > 20);
  CHECK_THAT(total_volume(m), Catch::WithinRel(0.1 * 0.1 * 0.1 / 6, 1e-9));
  // Open: drop a triangle.
  xfem::TriangleMesh open = s;
  open.triangles.conservativeResize(3, 3);
  CHECK_THROWS_WITH(xfem::surface_mesh(open, 0.02, "open.off"),
                    Catch::Contains("open.off: surface is not closed: 3 boundary edges"));
}

TEST_CASE("unstructured_mesh: bad sizes and boxes are refused", "[unstructured_mesh]") {
  CHECK_THROWS_WITH(xfem::unstructured_box_mesh({0, 0, 0}, {1, 1, 1}, -0.1), Catch::Contains("size must be positive"));
  CHECK_THROWS_WITH(xfem::unstructured_box_mesh({0, 0, 0}, {1, 1, 1}, 0.0), Catch::Contains("size must be positive"));
  CHECK_THROWS_WITH(xfem::unstructured_box_mesh({0, 0, 0}, {1, 0, 1}, 0.1), Catch::Contains("empty box"));
  CHECK_THROWS_WITH(xfem::implicit_mesh(xfem::organ_function, 0.1, NAN), Catch::Contains("size must be positive"));
  const auto outside = [](const Eigen::Vector3d& p) { return 1.0 - p.norm(); };  // origin outside
  CHECK_THROWS_WITH(xfem::implicit_mesh(outside, 2.0, 0.1), Catch::Contains("origin must lie inside"));
}
