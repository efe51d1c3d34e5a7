// SPDX-License-Identifier: MIT
// Readers against hostile files: each bad input is one xfem::Error naming the file and the
// problem, raised before any large allocation; never a crash, another exception or a hang.
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>

#include "xfem/core/error.h"
#include "xfem/core/json_io.h"
#include "xfem/system/linear_system.h"
#include "xfem/io/label_image.h"
#include "xfem/io/matrix_market.h"
#include "xfem/system/problem.h"
#include "xfem/io/vtk_io.h"

namespace {
namespace fs = std::filesystem;

std::string scratch(const std::string& name, const std::string& text) {
  const auto dir = fs::temp_directory_path() / "xfem_unit_hostile";
  fs::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}
// A system directory from one fuzz input (as fuzz/fuzz_reader.cpp builds it): its files separated
// by the line "=====", in the order system.json, K.mtx, f.mtx, dirichlet.mtx, coordinates.mtx.
std::string system_dir(const std::string& input) {
  std::ifstream in(input, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const fs::path dir = fs::temp_directory_path() / "xfem_unit_hostile" / "system";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::size_t start = 0;
  for (const char* name : {"system.json", "K.mtx", "f.mtx", "dirichlet.mtx", "coordinates.mtx"}) {
    const std::size_t stop = text.find("\n=====\n", start);
    std::ofstream((dir / name).string(), std::ios::binary) << text.substr(start, stop == std::string::npos ? stop : stop - start);
    if (stop == std::string::npos) break;
    start = stop + 7;
  }
  return dir.string();
}
}  // namespace

TEST_CASE("hostile: deeply nested JSON is refused before parsing (no stack overflow)", "[hostile]") {
  const std::string deep = scratch("deep.json", std::string(100000, '[') + std::string(100000, ']'));
  CHECK_THROWS_WITH(xfem::read_json(deep), Catch::Contains("deep.json: JSON nested deeper than 64 levels (byte 65)"));
  // Brackets inside strings do not count.
  CHECK_NOTHROW(xfem::read_json(scratch("strings.json", "{\"a\": \"" + std::string(1000, '[') + "\"}")));
}

TEST_CASE("hostile: a JSON number beyond the double range names the file", "[hostile]") {
  CHECK_THROWS_WITH(xfem::read_json(scratch("big.json", "{\"E\": 1e999}")),
                    Catch::EndsWith("big.json: a number in the JSON is too large for a double (beyond 1.8e308)"));
}

TEST_CASE("hostile: write_json refuses NaN and Inf, naming the key", "[hostile]") {
  xfem::Json j;
  j["a"]["b"] = std::vector<double>{1.0, std::numeric_limits<double>::infinity()};
  const std::string path = scratch("nan.json", "");
  fs::remove(path);
  CHECK_THROWS_WITH(xfem::write_json(j, path), Catch::Contains("non-finite value (NaN or Inf) in 'a.b[1]'"));
  CHECK_FALSE(fs::exists(path));
}

TEST_CASE("hostile: Matrix Market sizes are checked against the file before allocating", "[hostile]") {
  CHECK_THROWS_WITH(xfem::read_vector(scratch("rows.mtx", "%%MatrixMarket matrix array real general\n1000000000000 1\n1\n")),
                    Catch::Contains("rows.mtx: the size line claims 1000000000000 values but only"));
  CHECK_THROWS_WITH(
      xfem::read_matrix(scratch("nnz.mtx", "%%MatrixMarket matrix coordinate real general\n10 10 1000000000000000\n1 1 1\n")),
      Catch::Contains("nnz.mtx: the size line claims 1000000000000000 entries"));
  CHECK_THROWS_WITH(
      xfem::read_matrix(scratch("wide.mtx", "%%MatrixMarket matrix coordinate real general\n1000000000000 1 1\n1 1 1\n")),
      Catch::Contains("is larger than supported"));
}

TEST_CASE("hostile: Matrix Market content that would be silently misread is refused", "[hostile]") {
  CHECK_THROWS_WITH(xfem::read_vector(scratch("extra.mtx", "%%MatrixMarket matrix array real general\n2 1\n1\n2\n3\n")),
                    Catch::Contains("extra.mtx: line 5: more values than the 2 entries the size line announces"));
  CHECK_THROWS_WITH(
      xfem::read_vector(scratch("sparse.mtx", "%%MatrixMarket matrix coordinate real general\n3 1 1\n1 1 0.5\n")),
      Catch::Contains("sparse.mtx: a sparse (coordinate) Matrix Market file, expected a dense (array) vector"));
  CHECK_THROWS_WITH(
      xfem::read_matrix(scratch("dup.mtx", "%%MatrixMarket matrix coordinate real general\n2 2 3\n1 1 1\n2 2 1\n1 1 5\n")),
      Catch::Contains("dup.mtx: an entry appears twice"));
  CHECK_THROWS_WITH(
      xfem::read_matrix(scratch("upper.mtx", "%%MatrixMarket matrix coordinate real symmetric\n2 2 2\n1 1 1\n1 2 1\n")),
      Catch::Contains("upper.mtx: line 4: entry (1, 2) above the diagonal in a symmetric file"));
  // dirichlet.mtx's rows must be strictly increasing (FORMATS.md): out of order or repeated is refused.
  const std::string unsorted =
      scratch("unsorted.mtx", "%%MatrixMarket matrix coordinate real general\n6 1 3\n1 1 0\n4 1 0.5\n2 1 0\n");
  CHECK_THROWS_WITH(xfem::read_matrix(unsorted, true),
                    Catch::Contains("unsorted.mtx: line 5: row 2 after row 4 (the rows must be strictly increasing)"));
  CHECK(xfem::read_matrix(unsorted).nonZeros() == 3);  // K.mtx may come in any order
  CHECK_THROWS_WITH(
      xfem::read_matrix(scratch("repeated.mtx", "%%MatrixMarket matrix coordinate real general\n6 1 2\n3 1 0\n3 1 0\n"), true),
      Catch::Contains("repeated.mtx: line 4: row 3 after row 3"));
  // Trailing white space is fine.
  CHECK(xfem::read_vector(scratch("ok.mtx", "%%MatrixMarket matrix array real general\n2 1\n1\n2\n\n  \n")).size() == 2);
}

TEST_CASE("hostile: legacy VTK with fewer points than POINTS claims is refused", "[hostile]") {
  const std::string head = "# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  const std::string cells = "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n";
  CHECK_THROWS_WITH(xfem::read_tet_mesh(scratch("phantom.vtk", head + "POINTS 104 double\n0 0 0 1 0 0 0 1 0 0 0 1\n" + cells)),
                    Catch::Contains("phantom.vtk: POINTS claims 104 points but only 12 coordinates follow"));
  CHECK(xfem::read_tet_mesh(scratch("fine.vtk", head + "POINTS 4 double\n0 0 0 1 0 0 0 1 0 0 0 1\n" + cells)).tets.rows() == 1);
}

TEST_CASE("hostile: legacy VTK cells naming a point beyond POINTS are refused, ASCII and binary", "[hostile][fuzz-regressions]") {
  // VTK's legacy reader (not built with the sanitizers) wrote out of bounds for such ids (fuzzing).
  const std::string head = "# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n0 0 0 1 0 0 0 1 0 0 0 1\n";
  CHECK_THROWS_WITH(xfem::read_tet_mesh(scratch("id9.vtk", head + "CELLS 1 5\n4 0 1 2 9\nCELL_TYPES 1\n10\n")),
                    Catch::Contains("id9.vtk: cell 0 uses point 9, out of range [0, 4)"));
  CHECK_THROWS_WITH(xfem::read_tet_mesh(scratch("idneg.vtk", head + "CELLS 1 5\n4 0 1 -2 3\nCELL_TYPES 1\n10\n")),
                    Catch::Contains("cell 0 uses point -2, out of range [0, 4)"));
  // VTK matches keywords in any case and by their first letters only ("CELLS1" would be CELLS).
  CHECK_THROWS_WITH(xfem::read_tet_mesh(scratch("lower.vtk", head + "cells 1 5\n4 0 1 2 9\nCELL_TYPES 1\n10\n")),
                    Catch::Contains("lower.vtk: cell 0 uses point 9, out of range [0, 4)"));
  CHECK_THROWS_WITH(xfem::read_tet_mesh(scratch("glued.vtk", head + "CELLS1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n")),
                    Catch::Contains("glued.vtk: unknown keyword 'CELLS1' in the legacy VTK file (did you mean 'cells'?)"));
  CHECK_THROWS_WITH(xfem::read_tet_mesh(scratch("field.vtk", head + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\nfieldPOINT_DATA 4\n")),
                    Catch::Contains("field.vtk: unknown keyword 'fieldPOINT_DATA'"));
  CHECK_THROWS_WITH(xfem::read_tet_mesh(scratch("bytes.vtk", head + "CELLS 1 5\x87\n4 0 1 2 3\nCELL_TYPES 1\n10\n")),
                    Catch::Contains("bytes.vtk: byte 110 is not text, in an ASCII legacy VTK file"));
  CHECK_THROWS_WITH(xfem::read_tet_mesh(scratch("decimal.vtk", head + "CELLS 1 5\n4 0 1 2.0 3\nCELL_TYPES 1\n10\n")),
                    Catch::Contains("decimal.vtk: CELLS section: '2.0' is not a whole number"));
  CHECK_THROWS_WITH(xfem::read_tet_mesh(scratch("twokeys.vtk", head + "CELLS 1 5 CELL_TYPES\n4 0 1 2 3\nCELL_TYPES 1\n10\n")),
                    Catch::Contains("twokeys.vtk: a second keyword in the line of CELLS"));
  // The same in a binary file: big-endian int32 counts and ids, big-endian doubles.
  const auto be32 = [](std::int32_t v) {
    std::string b(4, '\0');
    for (int i = 0; i < 4; ++i) b[i] = static_cast<char>((static_cast<std::uint32_t>(v) >> (24 - 8 * i)) & 0xff);
    return b;
  };
  const auto be64 = [](double d) {
    std::uint64_t u;
    std::memcpy(&u, &d, 8);
    std::string b(8, '\0');
    for (int i = 0; i < 8; ++i) b[i] = static_cast<char>((u >> (56 - 8 * i)) & 0xff);
    return b;
  };
  const auto binary = [&](std::int32_t last) {
    std::string t = "# vtk DataFile Version 3.0\nx\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n";
    for (double c : {0., 0., 0., 1., 0., 0., 0., 1., 0., 0., 0., 1.}) t += be64(c);
    t += "\nCELLS 1 5\n";
    for (std::int32_t v : {4, 0, 1, 2, last}) t += be32(v);
    return t + "\nCELL_TYPES 1\n" + be32(10) + "\n";
  };
  CHECK(xfem::read_tet_mesh(scratch("fine_binary.vtk", binary(3))).tets.rows() == 1);
  CHECK_THROWS_WITH(xfem::read_tet_mesh(scratch("id7_binary.vtk", binary(7))),
                    Catch::Contains("id7_binary.vtk: cell 0 uses point 7, out of range [0, 4)"));
}

TEST_CASE("hostile: an OFF header claiming 2e9 faces is refused before allocating", "[hostile]") {
  CHECK_THROWS_WITH(xfem::read_triangle_mesh(scratch("huge.off", "OFF\n4 2000000000 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n")),
                    Catch::Contains("huge.off: the OFF header claims 4 vertices and 2000000000 faces"));
  CHECK(xfem::read_triangle_mesh(scratch("ok.off", "OFF\n# a comment\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")).triangles.rows() == 1);
}

TEST_CASE("hostile: mesh writers refuse non-finite values, naming the array", "[hostile]") {
  xfem::TetMesh m;
  m.points.resize(4, 3);
  m.points << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  m.tets.resize(1, 4);
  m.tets << 0, 1, 2, 3;
  m.cell_data["von_mises"] = xfem::make_array(xfem::DataArray::Type::Float64, 1, 1, std::numeric_limits<double>::infinity());
  const std::string path = scratch("inf.vtu", "");
  fs::remove(path);
  CHECK_THROWS_WITH(xfem::write_tet_mesh(m, path),
                    Catch::Contains("refusing to write a non-finite value (inf) in cell array 'von_mises' at tuple 0"));
  CHECK_FALSE(fs::exists(path));
  m.cell_data.clear();
  m.points(3, 2) = std::nan("");
  CHECK_THROWS_WITH(xfem::write_tet_mesh(m, path), Catch::Contains("refusing to write point 3"));
}

TEST_CASE("hostile: the fuzzing regressions are rejected cleanly", "[hostile][fuzz-regressions]") {
  using Reader = std::function<void(const std::string&)>;
  const std::map<std::string, Reader> readers = {
      {"vtu", [](const std::string& p) { xfem::read_tet_mesh(p); }},
      {"vtk_mesh", [](const std::string& p) { xfem::read_tet_mesh(p); }},
      {"vtk_surface", [](const std::string& p) { xfem::read_triangle_mesh(p); }},
      {"vtp", [](const std::string& p) { xfem::read_triangle_mesh(p); }},
      {"stl", [](const std::string& p) { xfem::read_triangle_mesh(p); }},
      {"obj", [](const std::string& p) { xfem::read_triangle_mesh(p); }},
      {"off", [](const std::string& p) { xfem::read_triangle_mesh(p); }},
      {"mtx_matrix", [](const std::string& p) { xfem::read_matrix(p); }},
      {"mtx_vector", [](const std::string& p) { xfem::read_vector(p); }},
      {"problem", [](const std::string& p) { xfem::read_problem(p); }},
      {"exact", [](const std::string& p) { xfem::read_exact_field(p); }},
      {"system", [](const std::string& p) { xfem::read_linear_system(system_dir(p)); }},
      {"nrrd", [](const std::string& p) { xfem::read_label_image(p); }},
      {"vti", [](const std::string& p) { xfem::read_label_image(p); }},
      {"msh", [](const std::string& p) {  // as fuzz_msh reads it: as a body, then as a cut
         try {
           xfem::read_tet_mesh(p);
         } catch (const xfem::Error& e) {
           CHECK(std::string(e.what()).find(p) == 0);
         }
         xfem::read_triangle_mesh(p);
       }},
  };
  int files = 0;
  for (const auto& dir : fs::directory_iterator(std::string(XFEM_TEST_DATA) + "/fuzz-regressions")) {
    if (!dir.is_directory()) continue;
    const std::string reader = dir.path().filename().string();
    REQUIRE(readers.count(reader) == 1);
    for (const auto& file : fs::directory_iterator(dir.path())) {
      INFO(file.path().string());
      ++files;
      try {
        readers.at(reader)(file.path().string());
      } catch (const xfem::Error& e) {
        // names the file (a system input: the directory built from it)
        CHECK(std::string(e.what()).find(reader == "system" ? std::string(fs::temp_directory_path() / "xfem_unit_hostile" / "system")
                                                            : file.path().string()) == 0);
      }
    }
  }
  CHECK(files >= 6);
}
