// SPDX-License-Identifier: MIT
#include "xfem/vtk_io.h"

#include <catch2/catch.hpp>
#include <filesystem>

#include "xfem/error.h"

namespace {
std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "xfem_unit";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

xfem::TetMesh one_tet() {
  xfem::TetMesh m;
  m.points.resize(4, 3);
  m.points << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  m.tets.resize(1, 4);
  m.tets << 0, 1, 2, 3;
  return m;
}
}  // namespace

TEST_CASE("vtk_io: a tet mesh with arrays round-trips exactly through .vtu", "[vtk_io]") {
  xfem::TetMesh m = one_tet();
  m.points(3, 2) = 1.0 / 3.0;
  m.point_data["side"] = xfem::make_array(xfem::DataArray::Type::Int32, 1, 4, -1);
  m.cell_data["stress"] = xfem::make_array(xfem::DataArray::Type::Float64, 6, 1, 0.1);
  m.field_data["dof_counts"] = xfem::make_array(xfem::DataArray::Type::Int64, 1, 4, 7);
  const auto path = scratch("one.vtu");
  xfem::write_tet_mesh(m, path);
  const xfem::TetMesh back = xfem::read_tet_mesh(path);
  CHECK(back.points == m.points);
  CHECK(back.tets == m.tets);
  CHECK(back.point_data.at("side").values == m.point_data.at("side").values);
  CHECK(back.point_data.at("side").type == xfem::DataArray::Type::Int32);
  CHECK(back.cell_data.at("stress").components == 6);
  CHECK(back.cell_data.at("stress").values == m.cell_data.at("stress").values);
  CHECK(back.field_data.at("dof_counts").values == m.field_data.at("dof_counts").values);
}

TEST_CASE("vtk_io: an inverted tet is reoriented with a warning", "[vtk_io]") {
  xfem::TetMesh m = one_tet();
  std::swap(m.tets(0, 1), m.tets(0, 2));
  std::vector<std::string> warnings;
  CHECK(xfem::validate_tet_mesh(m, "m", &warnings) == 1);
  CHECK(xfem::signed_volume(m, 0) > 0);
  REQUIRE(warnings.size() == 1);
  CHECK_THAT(warnings[0], Catch::Contains("1 inverted tetrahedra reoriented"));
}

TEST_CASE("vtk_io: a flat tet is an error", "[vtk_io]") {
  xfem::TetMesh m = one_tet();
  m.points(3, 2) = 0.0;
  CHECK_THROWS_WITH(xfem::validate_tet_mesh(m, "m", nullptr), Catch::Contains("1 tetrahedra have zero volume"));
}

TEST_CASE("vtk_io: a Moebius strip cannot be oriented", "[vtk_io]") {
  // A strip of 6 quads (12 triangles) closed with a half twist.
  const int n = 6;
  xfem::TriangleMesh m;
  m.points.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n, t = a / 2;
    for (int s = 0; s < 2; ++s) {
      const double w = s ? 0.3 : -0.3;
      m.points.row(2 * i + s) << (1 + w * std::cos(t)) * std::cos(a), (1 + w * std::cos(t)) * std::sin(a),
          w * std::sin(t);
    }
  }
  m.triangles.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    int a0 = 2 * i, a1 = 2 * i + 1, b0 = 2 * (i + 1), b1 = 2 * (i + 1) + 1;
    if (i == n - 1) std::swap(b0 = 0, b1 = 1);  // the half twist joins bottom to top
    m.triangles.row(2 * i) << a0, b0, a1;
    m.triangles.row(2 * i + 1) << a1, b0, b1;
  }
  CHECK_THROWS_WITH(xfem::validate_triangle_mesh(m, "strip", nullptr), Catch::Contains("Moebius"));
}

TEST_CASE("vtk_io: a badly oriented triangle is flipped to agree", "[vtk_io]") {
  xfem::TriangleMesh m;
  m.points.resize(4, 3);
  m.points << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 2, 0, 3, 2;  // the second runs 0->2 like the first: disagrees
  std::vector<std::string> warnings;
  xfem::validate_triangle_mesh(m, "cut", &warnings);
  CHECK(m.triangles.row(1) == Eigen::RowVector3i(0, 2, 3));
  CHECK(warnings.size() == 1);
}
