// SPDX-License-Identifier: MIT
#include "xfem/io/vtk_io.h"

#include <unistd.h>

#include <catch2/catch.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <sstream>

#include "xfem/generate/box_mesh.h"
#include "xfem/core/error.h"
#include "xfem/io/vtk_io_detail.h"

namespace fs = std::filesystem;
using xfem::DataArray;

namespace {

// A fresh scratch directory per test case, so tests can check that nothing else was left there.
std::string scratch_dir(const std::string& test) {
  const fs::path dir = fs::temp_directory_path() / ("xfem_unit_vtk_io_" + std::to_string(::getpid())) / test;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Captures everything written to file descriptor 2 (std::cerr, stdio and anything VTK or CGAL
// print), to show that a failed read reports only through the exception.
class StderrCapture {
 public:
  StderrCapture() : file_(std::tmpfile()) {
    std::cerr.flush();
    std::fflush(stderr);
    saved_ = ::dup(2);
    ::dup2(::fileno(file_), 2);
  }
  ~StderrCapture() {
    restore();
    std::fclose(file_);
  }
  std::string text() {
    restore();
    std::string out;
    std::rewind(file_);
    for (int c; (c = std::fgetc(file_)) != EOF;) out.push_back(static_cast<char>(c));
    return out;
  }

 private:
  void restore() {
    if (saved_ < 0) return;
    std::cerr.flush();
    std::fflush(stderr);
    ::dup2(saved_, 2);
    ::close(saved_);
    saved_ = -1;
  }
  std::FILE* file_;
  int saved_ = -1;
};

// The message of the xfem::Error thrown by `f`, with a check that nothing reached stderr.
template <class F>
std::string error_of(F&& f) {
  StderrCapture capture;
  std::string message = "(no exception)";
  try {
    f();
  } catch (const xfem::Error& e) {
    message = e.what();
  }
  const std::string printed = capture.text();
  CHECK(printed == "");
  return message;
}

xfem::TetMesh one_tet() {
  xfem::TetMesh m;
  m.points.resize(4, 3);
  m.points << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  m.tets.resize(1, 4);
  m.tets << 0, 1, 2, 3;
  return m;
}

// Two positively oriented tets on 5 points (the second: det[(-1,1,0), (-1,0,1), (0,1,1)] = 2).
const char* const two_tets_points = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n";

// A unit square in z = 0 as two triangles, both with normal +z.
xfem::TriangleMesh square() {
  xfem::TriangleMesh m;
  m.points.resize(4, 3);
  m.points << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 2, 0, 2, 3;
  return m;
}

void check_square(const xfem::TriangleMesh& m) {
  REQUIRE(m.points.rows() == 4);
  REQUIRE(m.triangles.rows() == 2);
  double area = 0;
  for (int f = 0; f < 2; ++f) {
    const Eigen::Vector3d a = m.points.row(m.triangles(f, 0)), b = m.points.row(m.triangles(f, 1)),
                          c = m.points.row(m.triangles(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    CHECK(n.z() > 0);  // orientation preserved from the file
    area += n.norm() / 2;
  }
  CHECK(area == 1.0);  // exact: coordinates are 0 and 1
  CHECK(m.points.colwise().minCoeff() == Eigen::RowVector3d(0, 0, 0));
  CHECK(m.points.colwise().maxCoeff() == Eigen::RowVector3d(1, 1, 0));
}

// Legacy VTK binary is big-endian.
template <class T>
void put_big_endian(std::string& out, T value) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  for (int i = sizeof(T) - 1; i >= 0; --i) out.push_back(static_cast<char>(bytes[i]));
}

template <class T>
void put_little_endian(std::string& out, T value) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  for (std::size_t i = 0; i < sizeof(T); ++i) out.push_back(static_cast<char>(bytes[i]));
}


// A legacy binary VTK file (big-endian) with the given points and cells of `cell_size` points:
// the writers refuse non-finite coordinates, so files holding them are made here.
std::string legacy_binary(const char* dataset, const char* cells_keyword, const std::vector<double>& xyz,
                          const std::vector<int>& ids, int cell_size, int vtk_type) {
  auto be = [](const void* p, std::size_t n) {
    std::string s(static_cast<const char*>(p), n);
    return std::string(s.rbegin(), s.rend());
  };
  const int points = static_cast<int>(xyz.size() / 3), cells = static_cast<int>(ids.size()) / cell_size;
  std::string out = std::string("# vtk DataFile Version 3.0\nx\nBINARY\nDATASET ") + dataset + "\nPOINTS " +
                    std::to_string(points) + " double\n";
  for (double v : xyz) out += be(&v, sizeof v);
  out += std::string("\n") + cells_keyword + " " + std::to_string(cells) + " " + std::to_string(cells * (cell_size + 1)) + "\n";
  for (int c = 0; c < cells; ++c) {
    out += be(&cell_size, sizeof cell_size);
    for (int k = 0; k < cell_size; ++k) out += be(&ids[c * cell_size + k], sizeof(int));
  }
  if (vtk_type > 0) {
    out += "\nCELL_TYPES " + std::to_string(cells) + "\n";
    for (int c = 0; c < cells; ++c) out += be(&vtk_type, sizeof vtk_type);
  }
  return out + "\n";
}
}  // namespace

// ---------------------------------------------------------------------------------------------
// Tetrahedral meshes: good files

TEST_CASE("vtk_io: a tet mesh with arrays round-trips exactly through .vtu", "[vtk_io]") {
  xfem::TetMesh m = xfem::box_mesh({2, 1, 1}, {0, 0, 0}, {0.3, 0.1, 0.1});
  m.points(3, 2) += 1.0 / 3.0 * 1e-3;  // a value with no short decimal form
  m.points(0, 0) = -std::numeric_limits<double>::denorm_min();
  const std::size_t np = m.points.rows(), nt = m.tets.rows();
  m.point_data["side"] = xfem::make_array(DataArray::Type::Int32, 1, np, -1);
  m.point_data["side"].values[1] = std::numeric_limits<std::int32_t>::max();
  m.point_data["side"].values[2] = std::numeric_limits<std::int32_t>::min();
  m.point_data["displacement"] = xfem::make_array(DataArray::Type::Float64, 3, np, 0.1);
  m.point_data["displacement"].values[4] = 1e-300;
  m.cell_data["stress"] = xfem::make_array(DataArray::Type::Float64, 6, nt, 2.0 / 3.0);
  m.cell_data["global_id"] = xfem::make_array(DataArray::Type::Int64, 1, nt, 0);
  m.cell_data["global_id"].values[5] = 9007199254740992.0;  // 2^53: exact in a double
  m.field_data["dof_counts"] = xfem::make_array(DataArray::Type::Int64, 1, 3, 7);
  m.field_data["connectivity"] = xfem::make_array(DataArray::Type::Int32, 4, 5, -3);
  m.field_data["scale"] = xfem::make_array(DataArray::Type::Float64, 1, 1, M_PI);
  const auto path = scratch_dir("roundtrip_vtu") + "/mesh.vtu";
  xfem::write_tet_mesh(m, path);
  std::vector<std::string> warnings;
  const xfem::TetMesh back = xfem::read_tet_mesh(path, &warnings);
  CHECK(warnings.empty());
  CHECK(back.points == m.points);
  CHECK(back.tets == m.tets);
  for (auto group : {&xfem::TetMesh::point_data, &xfem::TetMesh::cell_data, &xfem::TetMesh::field_data}) {
    const auto& written = m.*group;
    const auto& read = back.*group;
    REQUIRE(read.size() == written.size());
    for (const auto& [name, a] : written) {
      INFO(name);
      REQUIRE(read.count(name) == 1);
      CHECK(read.at(name).type == a.type);
      CHECK(read.at(name).components == a.components);
      CHECK(read.at(name).values == a.values);  // bitwise equal doubles
    }
  }
}

TEST_CASE("vtk_io: .vtu files are appended raw binary, zlib-compressed and deterministic", "[vtk_io]") {
  const xfem::TetMesh m = xfem::box_mesh({6, 6, 6}, {0, 0, 0}, {1, 1, 1});
  const auto dir = scratch_dir("deterministic_vtu");
  xfem::write_tet_mesh(m, dir + "/a.vtu");
  xfem::write_tet_mesh(m, dir + "/b.vtu");
  const std::string a = read_bytes(dir + "/a.vtu");
  CHECK(a == read_bytes(dir + "/b.vtu"));
  CHECK_THAT(a, Catch::Contains("format=\"appended\""));
  CHECK_THAT(a, Catch::Contains("compressor=\"vtkZLibDataCompressor\""));
  CHECK_THAT(a, Catch::Contains("<AppendedData encoding=\"raw\">"));
  CHECK_THAT(a, !Catch::Contains("format=\"ascii\"") && !Catch::Contains("format=\"binary\""));
  // Compressed: smaller than the raw doubles and 64-bit ids alone.
  const std::size_t raw = 8 * 3 * m.points.rows() + 8 * 4 * m.tets.rows();
  CHECK(a.size() < raw);
}

TEST_CASE("vtk_io: LZ4-compressed and uncompressed .vtu and .vtp read back bitwise as written", "[vtk_io]") {
  // xfem-sweep writes its frames with LZ4 (--compression): the project's reader must read them.
  xfem::TetMesh m = xfem::box_mesh({5, 4, 3}, {0, 0, 0}, {1, 0.7, 0.4});
  m.points(5, 1) += 1.0 / 3.0 * 1e-3;
  const std::size_t np = m.points.rows(), nt = m.tets.rows();
  m.point_data["displacement"] = xfem::make_array(DataArray::Type::Float64, 3, np, 0.0);
  for (std::size_t i = 0; i < 3 * np; ++i) m.point_data["displacement"].values[i] = std::sin(0.37 * i) * 1e-3;
  m.point_data["side"] = xfem::make_array(DataArray::Type::Int32, 1, np, -1);
  m.cell_data["von_mises"] = xfem::make_array(DataArray::Type::Float64, 1, nt, 0.0);
  for (std::size_t t = 0; t < nt; ++t) m.cell_data["von_mises"].values[t] = 1.0 / (t + 3.0);
  xfem::TriangleMesh s;
  s.points.resize(4, 3);
  s.points << 0, 0, 0.2, 1, 0, 0.2, 1, 1.0 / 3.0, 0.2, 0, 1, 0.3;
  s.triangles.resize(2, 3);
  s.triangles << 0, 1, 2, 0, 2, 3;
  s.cell_data["side"] = xfem::make_array(DataArray::Type::Int32, 1, 2, 1);
  s.point_data["displacement"] = xfem::make_array(DataArray::Type::Float64, 3, 4, 2.0 / 3.0);
  const auto dir = scratch_dir("compression");
  for (const auto& [compression, compressor] :
       {std::pair<xfem::Compression, std::string>{xfem::Compression::LZ4, "compressor=\"vtkLZ4DataCompressor\""},
        {xfem::Compression::None, ""}}) {
    INFO(compressor);
    xfem::write_tet_mesh(m, dir + "/m.vtu", compression);
    xfem::write_triangle_mesh(s, dir + "/s.vtp", compression);
    const std::string bytes = read_bytes(dir + "/m.vtu");
    CHECK_THAT(bytes, Catch::Contains("<AppendedData encoding=\"raw\">"));
    if (compressor.empty()) CHECK_THAT(bytes, !Catch::Contains("compressor="));
    else CHECK_THAT(bytes, Catch::Contains(compressor) && !Catch::Contains("vtkZLibDataCompressor"));
    std::vector<std::string> warnings;
    const xfem::TetMesh back = xfem::read_tet_mesh(dir + "/m.vtu", &warnings);
    const xfem::TriangleMesh sback = xfem::read_triangle_mesh(dir + "/s.vtp", &warnings);
    CHECK(warnings.empty());
    CHECK(back.points == m.points);
    CHECK(back.tets == m.tets);
    CHECK(sback.points == s.points);
    CHECK(sback.triangles == s.triangles);
    for (const auto& [name, a] : m.point_data) CHECK(back.point_data.at(name).values == a.values);
    for (const auto& [name, a] : m.cell_data) CHECK(back.cell_data.at(name).values == a.values);
    for (const auto& [name, a] : s.point_data) CHECK(sback.point_data.at(name).values == a.values);
    for (const auto& [name, a] : s.cell_data) CHECK(sback.cell_data.at(name).values == a.values);
  }
}

TEST_CASE("vtk_io: reads an ASCII .vtu written by another program (Float32 points, Int32 ids)", "[vtk_io]") {
  const auto path = scratch_dir("ascii_vtu") + "/mesh.vtu";
  write_text(path, R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">
  <UnstructuredGrid>
    <Piece NumberOfPoints="5" NumberOfCells="2">
      <PointData>
        <DataArray type="UInt8" Name="flag" format="ascii">1 0 1 0 1</DataArray>
      </PointData>
      <Points>
        <DataArray type="Float32" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0 0 0 1 1 1 1</DataArray>
      </Points>
      <Cells>
        <DataArray type="Int32" Name="connectivity" format="ascii">0 1 2 3 1 2 3 4</DataArray>
        <DataArray type="Int32" Name="offsets" format="ascii">4 8</DataArray>
        <DataArray type="UInt8" Name="types" format="ascii">10 10</DataArray>
      </Cells>
    </Piece>
  </UnstructuredGrid>
</VTKFile>
)");
  const xfem::TetMesh m = xfem::read_tet_mesh(path);
  REQUIRE(m.tets.rows() == 2);
  CHECK(m.tets.row(1) == Eigen::RowVector4i(1, 2, 3, 4));
  CHECK(m.points.row(4) == Eigen::RowVector3d(1, 1, 1));
  CHECK(m.point_data.at("flag").type == DataArray::Type::Int32);
  CHECK(m.point_data.at("flag").values == std::vector<double>{1, 0, 1, 0, 1});
}

TEST_CASE("vtk_io: reads a legacy ASCII .vtk tet mesh with point, cell and field data", "[vtk_io]") {
  const auto path = scratch_dir("legacy_ascii") + "/mesh.vtk";
  write_text(path, std::string("# vtk DataFile Version 3.0\ntwo tets\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                               "FIELD FieldData 1\ndof_counts 1 2 int\n5 6\n"
                               "POINTS 5 double\n") +
                       two_tets_points +
                       "CELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\nCELL_TYPES 2\n10\n10\n"
                       "POINT_DATA 5\nSCALARS side int 1\nLOOKUP_TABLE default\n1 -1 1 -1 1\n"
                       "CELL_DATA 2\nVECTORS force double\n0.5 0 0\n0 0 0.25\n");
  std::vector<std::string> warnings;
  const xfem::TetMesh m = xfem::read_tet_mesh(path, &warnings);
  CHECK(warnings.empty());
  REQUIRE(m.points.rows() == 5);
  REQUIRE(m.tets.rows() == 2);
  CHECK(m.tets.row(0) == Eigen::RowVector4i(0, 1, 2, 3));
  CHECK(m.tets.row(1) == Eigen::RowVector4i(1, 2, 3, 4));
  CHECK(m.point_data.at("side").values == std::vector<double>{1, -1, 1, -1, 1});
  CHECK(m.cell_data.at("force").components == 3);
  CHECK(m.cell_data.at("force").values == std::vector<double>{0.5, 0, 0, 0, 0, 0.25});
  CHECK(m.field_data.at("dof_counts").values == std::vector<double>{5, 6});
}

TEST_CASE("vtk_io: reads a legacy binary .vtk tet mesh", "[vtk_io]") {
  const auto path = scratch_dir("legacy_binary") + "/mesh.vtk";
  std::string file = "# vtk DataFile Version 3.0\ntwo tets\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n";
  const double points[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1.0 / 3.0};
  for (double x : points) put_big_endian(file, x);
  file += "\nCELLS 2 10\n";
  for (std::int32_t i : {4, 0, 1, 2, 3, 4, 1, 2, 3, 4}) put_big_endian(file, i);
  file += "\nCELL_TYPES 2\n";
  for (std::int32_t t : {10, 10}) put_big_endian(file, t);
  file += "\nCELL_DATA 2\nSCALARS label int 1\nLOOKUP_TABLE default\n";
  for (std::int32_t v : {7, -8}) put_big_endian(file, v);
  file += "\n";
  write_text(path, file);
  const xfem::TetMesh m = xfem::read_tet_mesh(path);
  REQUIRE(m.tets.rows() == 2);
  CHECK(m.tets.row(1) == Eigen::RowVector4i(1, 2, 3, 4));
  CHECK(m.points(4, 2) == 1.0 / 3.0);  // binary: exact
  CHECK(m.cell_data.at("label").values == std::vector<double>{7, -8});
}

TEST_CASE("vtk_io: '-' writes a .vtu to stdout and reads one from stdin", "[vtk_io]") {
  const xfem::TetMesh m = xfem::box_mesh({1, 1, 2}, {0, 0, 0}, {1, 1, 1});
  std::ostringstream out;
  auto* old_out = std::cout.rdbuf(out.rdbuf());
  xfem::write_tet_mesh(m, "-");
  std::cout.rdbuf(old_out);
  CHECK_THAT(out.str(), Catch::StartsWith("<VTKFile type=\"UnstructuredGrid\"") &&
                            Catch::Contains("<AppendedData encoding=\"raw\">"));
  std::istringstream in(out.str());
  auto* old_in = std::cin.rdbuf(in.rdbuf());
  const xfem::TetMesh back = xfem::read_tet_mesh("-");
  std::cin.rdbuf(old_in);
  CHECK(back.points == m.points);
  CHECK(back.tets == m.tets);
}

// ---------------------------------------------------------------------------------------------
// Tetrahedral meshes: each class of bad input

TEST_CASE("vtk_io: a non-tet cell is an error naming the first one and its VTK type", "[vtk_io]") {
  const auto dir = scratch_dir("non_tet");
  SECTION("legacy .vtk") {
    write_text(dir + "/m.vtk", std::string("# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                                           "POINTS 5 double\n") +
                                   two_tets_points +
                                   "CELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\nCELL_TYPES 2\n10\n9\n");  // triangles: gmsh_io.cpp
    CHECK(error_of([&] { xfem::read_tet_mesh(dir + "/m.vtk"); }) ==
          dir + "/m.vtk: cell 1 is a vtkQuad (VTK type 9), expected tetrahedra only (VTK type 10)");
  }
  SECTION(".vtu") {
    write_text(dir + "/m.vtu", R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">
  <UnstructuredGrid><Piece NumberOfPoints="8" NumberOfCells="1">
    <Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">
      0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1</DataArray></Points>
    <Cells>
      <DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 3 4 5 6 7</DataArray>
      <DataArray type="Int64" Name="offsets" format="ascii">8</DataArray>
      <DataArray type="UInt8" Name="types" format="ascii">12</DataArray>
    </Cells>
  </Piece></UnstructuredGrid>
</VTKFile>
)");
    CHECK(error_of([&] { xfem::read_tet_mesh(dir + "/m.vtu"); }) ==
          dir + "/m.vtu: cell 0 is a vtkHexahedron (VTK type 12), expected tetrahedra only (VTK type 10)");
  }
}

TEST_CASE("vtk_io: a tet with other than 4 points is an error", "[vtk_io]") {
  const auto path = scratch_dir("tet_3_points") + "/m.vtk";
  write_text(path, std::string("# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n") +
                       two_tets_points + "CELLS 2 9\n4 0 1 2 3\n3 1 2 3\nCELL_TYPES 2\n10\n10\n");
  CHECK_THAT(error_of([&] { xfem::read_tet_mesh(path); }), Catch::EndsWith(": cell 1 has 3 points, a vtkTetra (VTK type 10) has 4"));
}

TEST_CASE("vtk_io: a point index out of range is an error naming cell and index", "[vtk_io]") {
  const auto dir = scratch_dir("index_range");
  SECTION("legacy .vtk") {
    write_text(dir + "/m.vtk", std::string("# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                                           "POINTS 5 double\n") +
                                   two_tets_points + "CELLS 2 10\n4 0 1 2 3\n4 1 2 3 7\nCELL_TYPES 2\n10\n10\n");
    CHECK(error_of([&] { xfem::read_tet_mesh(dir + "/m.vtk"); }) ==
          dir + "/m.vtk: cell 1 uses point 7, out of range [0, 5)");
  }
  SECTION(".vtu") {
    xfem::TetMesh m = one_tet();
    m.tets(0, 2) = 4;
    xfem::write_tet_mesh(m, dir + "/m.vtu");
    CHECK(error_of([&] { xfem::read_tet_mesh(dir + "/m.vtu"); }) ==
          dir + "/m.vtu: cell 0 uses point 4, out of range [0, 4)");
  }
  SECTION("in memory") {
    xfem::TetMesh m = one_tet();
    m.tets(0, 3) = -1;
    CHECK_THROWS_WITH(xfem::validate_tet_mesh(m, "m", nullptr),
                      "m: tetrahedron 0 uses point -1, out of range [0, 4)");
  }
}

TEST_CASE("vtk_io: a non-finite coordinate is an error naming the point", "[vtk_io]") {
  const auto path = scratch_dir("non_finite") + "/m.vtk";
  const double bad = GENERATE(std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                              -std::numeric_limits<double>::infinity());
  write_text(path, legacy_binary("UNSTRUCTURED_GRID", "CELLS", {0, 0, 0, 1, 0, 0, 0, bad, 0, 0, 0, 1}, {0, 1, 2, 3}, 4, 10));
  CHECK(error_of([&] { xfem::read_tet_mesh(path); }) == path + ": point 2 has a non-finite coordinate");
}

TEST_CASE("vtk_io: zero-volume tets are an error with their count and the first", "[vtk_io]") {
  xfem::TetMesh m = xfem::box_mesh({1, 1, 1}, {0, 0, 0}, {1, 1, 1});  // 6 tets
  // Two tets flattened: the first has all four nodes in the plane z = 0, the other repeats a node.
  m.points.conservativeResize(m.points.rows() + 1, 3);
  m.points.row(m.points.rows() - 1) << 0.5, 0.5, 0;
  m.tets.row(2) << 0, 1, 3, static_cast<int>(m.points.rows() - 1);
  m.tets(4, 3) = m.tets(4, 0);
  const auto path = scratch_dir("zero_volume") + "/m.vtu";
  xfem::write_tet_mesh(m, path);
  CHECK(error_of([&] { xfem::read_tet_mesh(path); }) ==
        path + ": 2 tetrahedra have zero volume (first: tetrahedron 2)");
  // Scale-free: a mesh a million times smaller is not degenerate.
  xfem::TetMesh tiny = xfem::box_mesh({1, 1, 1}, {0, 0, 0}, {1e-6, 1e-6, 1e-6});
  CHECK(xfem::validate_tet_mesh(tiny, "tiny", nullptr) == 0);
}

TEST_CASE("vtk_io: inverted tets are reoriented with one warning giving the count", "[vtk_io]") {
  xfem::TetMesh m = xfem::box_mesh({1, 1, 1}, {0, 0, 0}, {1, 1, 1});
  std::vector<double> volumes;
  for (int t = 0; t < 6; ++t) volumes.push_back(xfem::signed_volume(m, t));
  for (int t : {1, 4}) std::swap(m.tets(t, 0), m.tets(t, 3));
  const auto path = scratch_dir("inverted") + "/m.vtu";
  xfem::write_tet_mesh(m, path);
  std::vector<std::string> warnings;
  const xfem::TetMesh back = xfem::read_tet_mesh(path, &warnings);
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0] == path + ": 2 inverted tetrahedra reoriented (first: tetrahedron 1)");
  for (int t = 0; t < 6; ++t) CHECK(xfem::signed_volume(back, t) == volumes[t]);
  // The fix swaps nodes 1 and 2 and keeps the node set.
  CHECK(back.tets.row(1) == Eigen::RowVector4i(m.tets(1, 0), m.tets(1, 2), m.tets(1, 1), m.tets(1, 3)));
}

TEST_CASE("vtk_io: an empty mesh is an error", "[vtk_io]") {
  const auto dir = scratch_dir("empty_mesh");
  xfem::TetMesh none;
  xfem::write_tet_mesh(none, dir + "/none.vtu");
  CHECK(error_of([&] { xfem::read_tet_mesh(dir + "/none.vtu"); }) ==
        dir + "/none.vtu: empty mesh (0 points, 0 tetrahedra)");
  write_text(dir + "/points_only.vtk", std::string("# vtk DataFile Version 3.0\nx\nASCII\n"
                                                   "DATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n") +
                                           two_tets_points + "CELLS 0 0\nCELL_TYPES 0\n");
  CHECK(error_of([&] { xfem::read_tet_mesh(dir + "/points_only.vtk"); }) ==
        dir + "/points_only.vtk: empty mesh (5 points, 0 tetrahedra)");
}

TEST_CASE("vtk_io: a missing or unreadable mesh file is an error", "[vtk_io]") {
  const auto dir = scratch_dir("missing");
  CHECK(error_of([&] { xfem::read_tet_mesh(dir + "/nothing.vtu"); }) ==
        dir + "/nothing.vtu: cannot open for reading (does it exist?)");
  fs::create_directories(dir + "/folder.vtu");
  CHECK(error_of([&] { xfem::read_tet_mesh(dir + "/folder.vtu"); }) ==
        dir + "/folder.vtu: is a directory, expected a file");
  CHECK(error_of([&] { xfem::read_triangle_mesh(dir + "/nothing.stl"); }) ==
        dir + "/nothing.stl: cannot open for reading (does it exist?)");
}

TEST_CASE("vtk_io: a wrong extension is an error naming the expected ones", "[vtk_io]") {
  const auto dir = scratch_dir("extension");
  write_text(dir + "/mesh.txt", "hello\n");
  CHECK(error_of([&] { xfem::read_tet_mesh(dir + "/mesh.txt"); }) ==
        dir + "/mesh.txt: unknown extension '.txt' for a tetrahedral mesh (expected .vtu or .vtk)");
  CHECK(error_of([&] { xfem::read_triangle_mesh(dir + "/mesh.txt"); }) ==
        dir + "/mesh.txt: unknown extension '.txt' for a triangle surface (expected .vtp, .vtu, .vtk, .stl, .obj, .off or .msh)");
  CHECK(error_of([&] { xfem::write_tet_mesh(one_tet(), dir + "/out.vtk"); }) ==
        dir + "/out.vtk: volume meshes are written as .vtu, not '.vtk'");
  CHECK(error_of([&] { xfem::write_triangle_mesh(square(), dir + "/out.stl"); }) ==
        dir + "/out.stl: surfaces are written as .vtp or .vtu, not '.stl'");
  CHECK(!fs::exists(dir + "/out.vtk"));
}

TEST_CASE("vtk_io: a file that is not the format its extension says is one error, VTK stays silent", "[vtk_io]") {
  const auto dir = scratch_dir("wrong_format");
  std::string garbage;
  for (int i = 0; i < 4096; ++i) garbage.push_back(static_cast<char>((i * 7919 + 13) % 256));
  for (const char* ext : {".vtu", ".vtk", ".vtp", ".stl", ".obj", ".off"}) write_text(dir + "/garbage" + ext, garbage);
  CHECK(error_of([&] { xfem::read_tet_mesh(dir + "/garbage.vtu"); }) ==
        dir + "/garbage.vtu: not a VTK XML unstructured grid (.vtu) file");
  CHECK(error_of([&] { xfem::read_triangle_mesh(dir + "/garbage.vtp"); }) ==
        dir + "/garbage.vtp: not a VTK XML polydata (.vtp) file");
  CHECK_THAT(error_of([&] { xfem::read_tet_mesh(dir + "/garbage.vtk"); }),
             Catch::StartsWith(dir + "/garbage.vtk: cannot read tetrahedral mesh: "));
  CHECK_THAT(error_of([&] { xfem::read_triangle_mesh(dir + "/garbage.vtk"); }),
             Catch::StartsWith(dir + "/garbage.vtk: cannot read triangle surface: "));
  CHECK(error_of([&] { xfem::read_triangle_mesh(dir + "/garbage.off"); }) ==
        dir + "/garbage.off: not a readable OFF file");
  CHECK(error_of([&] { xfem::read_triangle_mesh(dir + "/garbage.stl"); }) ==
        dir + "/garbage.stl: not an STL file (neither ASCII 'solid ...' nor binary with a matching triangle count)");
  const std::string obj = error_of([&] { xfem::read_triangle_mesh(dir + "/garbage.obj"); });
  CHECK(obj == dir + "/garbage.obj: not a readable OBJ file");
  CHECK(std::all_of(obj.begin(), obj.end(), [](char c) { return c >= 0x20 && c < 0x7f; }));  // printable
  CHECK(obj.size() < dir.size() + 300);

  // Well-formed files of the wrong kind.
  xfem::write_triangle_mesh(square(), dir + "/surface.vtp");
  fs::copy_file(dir + "/surface.vtp", dir + "/surface_named.vtu");
  CHECK(error_of([&] { xfem::read_tet_mesh(dir + "/surface_named.vtu"); }) ==
        dir + "/surface_named.vtu: not a VTK XML unstructured grid (.vtu) file");
  write_text(dir + "/poly.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n"
                                "0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 2\n");
  CHECK(error_of([&] { xfem::read_tet_mesh(dir + "/poly.vtk"); }) ==
        dir + "/poly.vtk: not a legacy VTK UNSTRUCTURED_GRID file");
  write_text(dir + "/image.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET STRUCTURED_POINTS\n"
                                 "DIMENSIONS 2 2 2\nSPACING 1 1 1\nORIGIN 0 0 0\n");
  CHECK(error_of([&] { xfem::read_triangle_mesh(dir + "/image.vtk"); }) ==
        dir + "/image.vtk: not a legacy VTK POLYDATA or UNSTRUCTURED_GRID file");
}

TEST_CASE("vtk_io: a truncated .vtu is one error carrying VTK's reason", "[vtk_io]") {
  const auto dir = scratch_dir("truncated");
  xfem::write_tet_mesh(xfem::box_mesh({3, 3, 3}, {0, 0, 0}, {1, 1, 1}), dir + "/full.vtu");
  const std::string full = read_bytes(dir + "/full.vtu");
  write_text(dir + "/cut.vtu", full.substr(0, full.size() * 2 / 3));
  const std::string message = error_of([&] { xfem::read_tet_mesh(dir + "/cut.vtu"); });
  CHECK_THAT(message, Catch::StartsWith(dir + "/cut.vtu: "));
  CHECK(message.find('\n') == std::string::npos);
  CHECK(message.find("0x") == std::string::npos);  // no object addresses: messages are deterministic
}

// ---------------------------------------------------------------------------------------------
// Triangle surfaces: good files

TEST_CASE("vtk_io: a surface with arrays round-trips exactly through .vtp, deterministically", "[vtk_io]") {
  xfem::TriangleMesh m = square();
  m.points(2, 2) = 1.0 / 7.0;
  m.point_data["id"] = xfem::make_array(DataArray::Type::Int64, 1, 4, 0);
  m.point_data["id"].values = {0, -1, 4e15, 3};
  m.point_data["normal"] = xfem::make_array(DataArray::Type::Float64, 3, 4, 0.1);
  m.cell_data["piece"] = xfem::make_array(DataArray::Type::Int32, 1, 2, 5);
  const auto dir = scratch_dir("roundtrip_vtp");
  xfem::write_triangle_mesh(m, dir + "/a.vtp");
  xfem::write_triangle_mesh(m, dir + "/b.vtp");
  const std::string bytes = read_bytes(dir + "/a.vtp");
  CHECK(bytes == read_bytes(dir + "/b.vtp"));
  CHECK_THAT(bytes, Catch::Contains("<AppendedData encoding=\"raw\">") &&
                        Catch::Contains("compressor=\"vtkZLibDataCompressor\""));
  std::vector<std::string> warnings;
  const xfem::TriangleMesh back = xfem::read_triangle_mesh(dir + "/a.vtp", &warnings);
  CHECK(warnings.empty());
  CHECK(back.points == m.points);
  CHECK(back.triangles == m.triangles);
  for (auto group : {&xfem::TriangleMesh::point_data, &xfem::TriangleMesh::cell_data}) {
    REQUIRE((back.*group).size() == (m.*group).size());
    for (const auto& [name, a] : m.*group) {
      INFO(name);
      CHECK((back.*group).at(name).type == a.type);
      CHECK((back.*group).at(name).components == a.components);
      CHECK((back.*group).at(name).values == a.values);
    }
  }
}

TEST_CASE("vtk_io: reads cut surfaces from every supported format", "[vtk_io]") {
  const auto dir = scratch_dir("surface_formats");
  const std::string legacy = "# vtk DataFile Version 3.0\nsquare\nASCII\n";
  SECTION("legacy .vtk POLYDATA") {
    write_text(dir + "/s.vtk", legacy + "DATASET POLYDATA\nPOINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\n"
                                        "POLYGONS 2 8\n3 0 1 2\n3 0 2 3\n");
    check_square(xfem::read_triangle_mesh(dir + "/s.vtk"));
  }
  SECTION("legacy .vtk UNSTRUCTURED_GRID of triangles") {
    write_text(dir + "/s.vtk", legacy + "DATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n0 0 0 1 0 0 1 1 0 0 1 0\n"
                                        "CELLS 2 8\n3 0 1 2\n3 0 2 3\nCELL_TYPES 2\n5\n5\n");
    check_square(xfem::read_triangle_mesh(dir + "/s.vtk"));
  }
  SECTION("ASCII .stl, coincident points merged") {
    write_text(dir + "/s.stl",
               "solid square\n"
               "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 1 1 0\n endloop\nendfacet\n"
               "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 1 0\n  vertex 0 1 0\n endloop\nendfacet\n"
               "endsolid square\n");
    check_square(xfem::read_triangle_mesh(dir + "/s.stl"));
  }
  SECTION("binary .stl, coincident points merged") {
    std::string file(80, ' ');
    file.replace(0, 10, "binary stl");
    put_little_endian<std::uint32_t>(file, 2);
    const float facets[2][12] = {{0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1, 0}, {0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 0}};
    for (const auto& facet : facets) {
      for (float x : facet) put_little_endian(file, x);
      put_little_endian<std::uint16_t>(file, 0);
    }
    write_text(dir + "/s.stl", file);
    check_square(xfem::read_triangle_mesh(dir + "/s.stl"));
  }
  SECTION(".obj") {
    write_text(dir + "/s.obj", "# square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n");
    check_square(xfem::read_triangle_mesh(dir + "/s.obj"));
  }
  SECTION(".off") {
    write_text(dir + "/s.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
    check_square(xfem::read_triangle_mesh(dir + "/s.off"));
  }
  SECTION(".vtp from stdin") {
    std::ostringstream out;
    auto* old_out = std::cout.rdbuf(out.rdbuf());
    xfem::write_triangle_mesh(square(), "-");
    std::cout.rdbuf(old_out);
    std::istringstream in(out.str());
    auto* old_in = std::cin.rdbuf(in.rdbuf());
    const xfem::TriangleMesh m = xfem::read_triangle_mesh("-");
    std::cin.rdbuf(old_in);
    check_square(m);
  }
}

// ---------------------------------------------------------------------------------------------
// Triangle surfaces: each class of bad input

TEST_CASE("vtk_io: an empty surface is an error", "[vtk_io]") {
  const auto dir = scratch_dir("empty_surface");
  write_text(dir + "/e.off", "OFF\n0 0 0\n");
  CHECK(error_of([&] { xfem::read_triangle_mesh(dir + "/e.off"); }) ==
        dir + "/e.off: empty surface (0 points, 0 triangles)");
  xfem::TriangleMesh points_only = square();
  points_only.triangles.resize(0, 3);
  xfem::write_triangle_mesh(points_only, dir + "/p.vtp");
  CHECK(error_of([&] { xfem::read_triangle_mesh(dir + "/p.vtp"); }) ==
        dir + "/p.vtp: empty surface (4 points, 0 triangles)");
}

TEST_CASE("vtk_io: a non-triangle surface cell is an error naming the first one", "[vtk_io]") {
  const auto dir = scratch_dir("non_triangle");
  write_text(dir + "/q.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 2 5 3\nf 1 2 3 4\n");
  CHECK(error_of([&] { xfem::read_triangle_mesh(dir + "/q.obj"); }) ==
        dir + "/q.obj: face 1 has 4 vertices, expected triangles only");
  write_text(dir + "/q.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  CHECK(error_of([&] { xfem::read_triangle_mesh(dir + "/q.off"); }) ==
        dir + "/q.off: face 0 has 4 vertices, expected triangles only");
  write_text(dir + "/l.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n"
                             "0 0 0 1 0 0 0 1 0\nLINES 1 3\n2 0 1\n");
  CHECK(error_of([&] { xfem::read_triangle_mesh(dir + "/l.vtk"); }) ==
        dir + "/l.vtk: cell 0 is a vtkLine (VTK type 3), expected triangles only (VTK type 5)");
}

TEST_CASE("vtk_io: a surface index out of range or a non-finite point is an error", "[vtk_io]") {
  const auto dir = scratch_dir("surface_range");
  write_text(dir + "/r.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n");
  CHECK(error_of([&] { xfem::read_triangle_mesh(dir + "/r.off"); }) ==
        dir + "/r.off: not a readable OFF file");  // CGAL's reader checks the indices
  write_text(dir + "/r.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n"
                             "0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 3\n");
  CHECK(error_of([&] { xfem::read_triangle_mesh(dir + "/r.vtk"); }) ==
        dir + "/r.vtk: cell 0 uses point 3, out of range [0, 3)");
  const double inf = std::numeric_limits<double>::infinity();
  write_text(dir + "/inf.vtk", legacy_binary("POLYDATA", "POLYGONS", {0, 0, 0, inf, 0, 0, 0, 1, 0}, {0, 1, 2}, 3, 0));
  CHECK(error_of([&] { xfem::read_triangle_mesh(dir + "/inf.vtk"); }) ==
        dir + "/inf.vtk: point 1 has a non-finite coordinate");
}

TEST_CASE("vtk_io: an edge shared by three triangles is an error", "[vtk_io]") {
  const auto path = scratch_dir("three_sheets") + "/t.off";
  // Three fins on the edge (0, 1).
  write_text(path, "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  CHECK(error_of([&] { xfem::read_triangle_mesh(path); }) ==
        path + ": edge (0, 1) is shared by 3 triangles; a cut must be a manifold surface");
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
  // The same strip without the twist is orientable.
  xfem::TriangleMesh band = m;
  band.triangles.row(2 * n - 2) << 2 * n - 2, 0, 2 * n - 1;
  band.triangles.row(2 * n - 1) << 2 * n - 1, 0, 1;
  CHECK_NOTHROW(xfem::validate_triangle_mesh(band, "band", nullptr));
  // Through a file, the error names the file.
  const auto path = scratch_dir("moebius") + "/strip.vtp";
  xfem::write_triangle_mesh(m, path);
  CHECK_THAT(error_of([&] { xfem::read_triangle_mesh(path); }),
             Catch::StartsWith(path + ": the surface cannot be oriented consistently (a Moebius strip?) at edge ("));
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
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0] == "cut: 1 triangles flipped to agree with their neighbours' orientation");
}

TEST_CASE("vtk_io: zero-area triangles are dropped with a warning, with their cell data", "[vtk_io]") {
  xfem::TriangleMesh m = square();
  m.triangles.conservativeResize(3, 3);
  m.triangles.row(2) << 0, 1, 1;  // repeated node
  m.cell_data["piece"] = xfem::make_array(DataArray::Type::Int32, 1, 3, 0);
  m.cell_data["piece"].values = {4, 5, 6};
  std::vector<std::string> warnings;
  xfem::validate_triangle_mesh(m, "cut", &warnings);
  CHECK(m.triangles.rows() == 2);
  CHECK(m.cell_data.at("piece").values == std::vector<double>{4, 5});
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0] == "cut: 1 zero-area triangles dropped");
  xfem::TriangleMesh flat = square();
  flat.points.row(2) << 0.5, 0, 0;
  flat.points.row(3) << 0.25, 0, 0;
  CHECK_THROWS_WITH(xfem::validate_triangle_mesh(flat, "flat", nullptr), "flat: every triangle has zero area");
}

// ---------------------------------------------------------------------------------------------
// Writers

TEST_CASE("vtk_io: writers refuse arrays of the wrong size or integer arrays holding non-integers", "[vtk_io]") {
  const auto dir = scratch_dir("bad_arrays");
  xfem::TetMesh m = one_tet();
  SECTION("wrong tuple count") {
    m.point_data["side"] = xfem::make_array(DataArray::Type::Int32, 1, 3, 1);
    CHECK(error_of([&] { xfem::write_tet_mesh(m, dir + "/m.vtu"); }) ==
          dir + "/m.vtu: cannot write point array 'side': 3 tuples for 4 items");
  }
  SECTION("values not a whole number of tuples") {
    m.field_data["pairs"] = xfem::make_array(DataArray::Type::Float64, 2, 2, 1);
    m.field_data["pairs"].values.push_back(3);
    CHECK(error_of([&] { xfem::write_tet_mesh(m, dir + "/m.vtu"); }) ==
          dir + "/m.vtu: cannot write field array 'pairs': 5 values do not make tuples of 2 components");
  }
  SECTION("non-integer in an Int32 array") {
    m.cell_data["flag"] = xfem::make_array(DataArray::Type::Int32, 1, 1, 1.5);
    CHECK_THAT(error_of([&] { xfem::write_tet_mesh(m, dir + "/m.vtu"); }),
               Catch::StartsWith(dir + "/m.vtu: cannot write cell array 'flag': value 1.5") &&
                   Catch::EndsWith("at index 0 is not an integer of its type"));
  }
  SECTION("Int32 overflow") {
    m.cell_data["flag"] = xfem::make_array(DataArray::Type::Int32, 1, 1, 3e9);
    CHECK_THROWS_WITH(xfem::write_tet_mesh(m, dir + "/m.vtu"), Catch::Contains("is not an integer of its type"));
  }
  CHECK(fs::is_empty(dir));  // nothing written, no temporary left
}

TEST_CASE("vtk_io: a failing write leaves no file and no temporary", "[vtk_io]") {
  const auto dir = scratch_dir("failing_write");
  CHECK(error_of([&] { xfem::write_tet_mesh(one_tet(), dir + "/missing_dir/m.vtu"); }) ==
        dir + "/missing_dir/m.vtu: directory " + dir + "/missing_dir does not exist");
  // A directory where the file should go: VTK writes the temporary, the rename fails.
  fs::create_directories(dir + "/taken.vtu/inside");
  CHECK_THAT(error_of([&] { xfem::write_tet_mesh(one_tet(), dir + "/taken.vtu"); }),
             Catch::StartsWith(dir + "/taken.vtu: cannot rename temporary file"));
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(dir)) left.push_back(entry.path().filename().string());
  CHECK(left == std::vector<std::string>{"taken.vtu"});
}

TEST_CASE("vtk_io: write and read a 500k-tet box mesh (timing for docs/PERFORMANCE.md)", "[vtk_io][.slow]") {
  const xfem::TetMesh m = xfem::box_mesh({18, 36, 120}, {0, 0, 0}, {0.03, 0.06, 0.2});
  const auto path = scratch_dir("big") + "/beam.vtu";
  const auto t0 = std::chrono::steady_clock::now();
  xfem::write_tet_mesh(m, path);
  const auto t1 = std::chrono::steady_clock::now();
  const xfem::TetMesh back = xfem::read_tet_mesh(path);
  const auto t2 = std::chrono::steady_clock::now();
  const double raw = 8.0 * 3 * m.points.rows() + 8.0 * 4 * m.tets.rows();
  const double size = static_cast<double>(fs::file_size(path));
  WARN("points " << m.points.rows() << " tets " << m.tets.rows() << " write "
                 << std::chrono::duration<double>(t1 - t0).count() << " s, read "
                 << std::chrono::duration<double>(t2 - t1).count() << " s, file " << size / 1e6 << " MB, raw "
                 << raw / 1e6 << " MB, ratio " << size / raw);
  CHECK(back.points == m.points);
  CHECK(back.tets == m.tets);
  fs::remove(path);
}

TEST_CASE("vtk_io: a surface written as .vtu (a grid of triangles) reads back with its arrays", "[vtk_io]") {
  const auto dir = scratch_dir("surface_vtu");
  xfem::TriangleMesh m = square();
  m.cell_data["side"] = xfem::make_array(DataArray::Type::Int32, 1, 2, -1.0);
  m.point_data["displacement"] = xfem::make_array(DataArray::Type::Float64, 3, 4, 0.25);
  xfem::write_triangle_mesh(m, dir + "/surface.vtu");
  std::ifstream in(dir + "/surface.vtu");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text.find("<UnstructuredGrid>") != std::string::npos);
  const xfem::TriangleMesh back = xfem::read_triangle_mesh(dir + "/surface.vtu");
  CHECK(back.points == m.points);
  CHECK(back.triangles == m.triangles);
  CHECK(back.cell_data.at("side").values == m.cell_data.at("side").values);
  CHECK(back.point_data.at("displacement").values == m.point_data.at("displacement").values);
  // A volume mesh is not a surface: its first tet is named.
  xfem::write_tet_mesh(xfem::box_mesh({1, 1, 1}, {0, 0, 0}, {1, 1, 1}), dir + "/box.vtu");
  CHECK(error_of([&] { xfem::read_triangle_mesh(dir + "/box.vtu"); }) ==
        dir + "/box.vtu: cell 0 is a vtkTetra (VTK type 10), expected triangles only (VTK type 5)");
}

TEST_CASE("vtk_io: VTK's messages reach the user without addresses, raw bytes or object dumps", "[vtk_io][messages]") {
  const auto clean = [](const std::string& m) { return xfem::vtk_io_detail::MessageCollector::clean(m.c_str()); };
  // The reader's own error: source location and "<Class> (0x...): " go.
  CHECK(clean("ERROR: In /build/vtk/IO/XML/vtkXMLReader.cxx, line 512\nvtkXMLUnstructuredGridReader (0x5585a1b2c3d0): "
              "Error parsing input file.  ReadXMLInformation aborting.\n\n") ==
        "Error parsing input file.  ReadXMLInformation aborting.");
  // The executive's: addresses inside the message, then an object dump on the following lines.
  CHECK(clean("ERROR: In /build/vtk/Common/ExecutionModel/vtkExecutive.cxx, line 753\nvtkCompositeDataPipeline "
              "(0x5585a1b2c3d0): Algorithm vtkXMLUnstructuredGridReader(0x5585a1b2d4e0) returned failure for request: "
              "vtkInformation (0x5585a1b2e5f0)\n  Debug: Off\n  Modified Time: 123\n") ==
        "Algorithm vtkXMLUnstructuredGridReader returned failure for request: vtkInformation");
  // Bytes of a corrupt file VTK quotes: escaped; the line capped.
  CHECK(clean("vtkXMLDataParser (0x55aa00112233): bad token 'A\x01\xff'") == "bad token 'A\\x01\\xff'");
  const std::string long_message = clean(("vtkXMLParser (0x55aa00112233): " + std::string(1000, 'x')).c_str());
  CHECK(long_message == std::string(200, 'x') + "...");
  // What is not an address stays: a short hexadecimal value, a warning without a class.
  CHECK(clean("Warning: In file.cxx, line 1\nvtkDataReader (0x1234567): value 0x1f is odd\n") == "value 0x1f is odd");
  for (const char* m : {"ERROR: In a.cxx, line 2\nvtkFoo (0xdeadbeef1234): x (0xdeadbeef5678) y 0x55aa00112233 z\n"})
    CHECK(clean(m).find("0x") == std::string::npos);
}
