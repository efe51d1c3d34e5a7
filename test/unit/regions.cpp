// SPDX-License-Identifier: MIT
// Regions of a tet mesh (core/regions.h): the cell array "region" and the field arrays
// region_ids / region_names, through .vtu and legacy .vtk, and the refusal of hostile values.
#include "xfem/core/regions.h"

#include <unistd.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkLongLongArray.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkTetra.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <catch2/catch.hpp>
#include <array>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>

#include "xfem/core/error.h"
#include "xfem/generate/box_mesh.h"
#include "xfem/io/vtk_io.h"

namespace fs = std::filesystem;

namespace {

std::string scratch(const std::string& test) {
  const fs::path dir = fs::temp_directory_path() / ("xfem_unit_regions_" + std::to_string(::getpid())) / test;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Two positively oriented tets written by VTK itself, decorated by `add` (arrays our writer
// would never write), as ASCII .vtu.
std::string vtk_written(const std::string& dir, const std::function<void(vtkUnstructuredGrid*)>& add) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  for (const auto& p : {std::array<double, 3>{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}})
    points->InsertNextPoint(p.data());
  grid->SetPoints(points);
  const vtkIdType a[4] = {0, 1, 2, 3}, b[4] = {1, 2, 3, 4};
  grid->InsertNextCell(VTK_TETRA, 4, a);
  grid->InsertNextCell(VTK_TETRA, 4, b);
  add(grid);
  const std::string path = dir + "/mesh.vtu";
  auto writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
  writer->SetInputData(grid);
  writer->SetDataModeToAscii();
  writer->SetFileName(path.c_str());
  REQUIRE(writer->Write() == 1);
  return path;
}

template <class Array>
vtkSmartPointer<Array> array(const char* name, std::initializer_list<typename Array::ValueType> values,
                             int components = 1) {
  auto out = vtkSmartPointer<Array>::New();
  out->SetName(name);
  out->SetNumberOfComponents(components);
  for (auto v : values) out->InsertNextValue(v);
  return out;
}

vtkSmartPointer<vtkStringArray> strings(const char* name, std::initializer_list<std::string> values) {
  auto out = vtkSmartPointer<vtkStringArray>::New();
  out->SetName(name);
  for (const auto& v : values) out->InsertNextValue(v);
  return out;
}

std::string error_reading(const std::string& path) {
  try {
    xfem::read_tet_mesh(path);
  } catch (const xfem::Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("regions: a mesh without the array is one region 0", "[regions]") {
  const xfem::TetMesh m = xfem::box_mesh({2, 1, 1}, {0, 0, 0}, {2, 1, 1});
  CHECK(xfem::tet_regions(m) == std::vector<int>(m.tets.rows(), 0));
  CHECK(xfem::region_ids(m) == std::vector<int>{0});
  CHECK(xfem::region_list(m) == "0");
}

TEST_CASE("regions: ids and names round-trip through .vtu; a mesh without regions writes none", "[regions]") {
  const std::string dir = scratch("roundtrip");
  xfem::TetMesh m = xfem::box_mesh({2, 1, 1}, {0, 0, 0}, {2, 1, 1});
  xfem::write_tet_mesh(m, dir + "/plain.vtu");
  const std::string plain = bytes_of(dir + "/plain.vtu");
  CHECK(plain.find("region") == std::string::npos);
  const xfem::TetMesh plain_back = xfem::read_tet_mesh(dir + "/plain.vtu");
  CHECK(plain_back.region_names.empty());
  CHECK(plain_back.cell_data.count("region") == 0);

  std::vector<int> regions(m.tets.rows());
  for (std::size_t t = 0; t < regions.size(); ++t) regions[t] = t < regions.size() / 2 ? 3 : 7;
  xfem::set_tet_regions(m, regions);
  m.region_names = {{3, "liver"}, {7, "tumour (stiff)"}, {9, "vessel"}};
  xfem::write_tet_mesh(m, dir + "/regions.vtu");
  const xfem::TetMesh back = xfem::read_tet_mesh(dir + "/regions.vtu");
  CHECK(xfem::tet_regions(back) == regions);
  CHECK(back.cell_data.at("region").type == xfem::DataArray::Type::Int32);
  CHECK(back.region_names == m.region_names);
  CHECK(back.field_data.count("region_ids") == 0);  // read into region_names, not kept twice
  CHECK(xfem::region_ids(back) == std::vector<int>{3, 7});
  CHECK(xfem::region_list(back) == "3 'liver', 7 'tumour (stiff)', 9 'vessel'");
  // Written again, the file is the same bytes (a stage that copies the mesh keeps its regions).
  xfem::write_tet_mesh(back, dir + "/again.vtu");
  CHECK(bytes_of(dir + "/again.vtu") == bytes_of(dir + "/regions.vtu"));
}

TEST_CASE("regions: a region array and names written by VTK itself are read", "[regions]") {
  const std::string path = vtk_written(scratch("vtk"), [](vtkUnstructuredGrid* g) {
    g->GetCellData()->AddArray(array<vtkIntArray>("region", {4, 2}));
    g->GetFieldData()->AddArray(array<vtkIntArray>("region_ids", {2, 4}));
    g->GetFieldData()->AddArray(strings("region_names", {"capsule", "parenchyma"}));
  });
  const xfem::TetMesh m = xfem::read_tet_mesh(path);
  CHECK(xfem::tet_regions(m) == std::vector<int>{4, 2});
  CHECK(m.region_names == std::map<int, std::string>{{2, "capsule"}, {4, "parenchyma"}});
}

TEST_CASE("regions: hostile region arrays are one-line errors naming the file", "[regions]") {
  const std::string dir = scratch("hostile");
  using Decorate = std::function<void(vtkUnstructuredGrid*)>;
  const std::vector<std::pair<Decorate, std::string>> cases = {
      {[](vtkUnstructuredGrid* g) { g->GetCellData()->AddArray(array<vtkDoubleArray>("region", {1.0, 2.5})); },
       "cell array 'region' must be an integer array (Int32), not floating point"},
      {[](vtkUnstructuredGrid* g) { g->GetCellData()->AddArray(array<vtkIntArray>("region", {1, 2, 3, 4}, 2)); },
       "cell array 'region' has 2 components, expected 1"},
      {[](vtkUnstructuredGrid* g) { g->GetCellData()->AddArray(array<vtkIntArray>("region", {1, -5})); },
       "cell array 'region': tetrahedron 1 has region -5, not an integer in [0, 2147483647]"},
      {[](vtkUnstructuredGrid* g) {
         g->GetCellData()->AddArray(array<vtkLongLongArray>("region", {1, 1LL << 40}));
       },
       "cell array 'region': tetrahedron 1 has region 1.09951e+12, not an integer in [0, 2147483647]"},
      {[](vtkUnstructuredGrid* g) { g->GetFieldData()->AddArray(strings("region_names", {"a"})); },
       "field array 'region_ids' missing: region names need both 'region_ids' and 'region_names'"},
      {[](vtkUnstructuredGrid* g) { g->GetFieldData()->AddArray(array<vtkIntArray>("region_ids", {1})); },
       "field array 'region_names' missing: region names need both 'region_ids' and 'region_names'"},
      {[](vtkUnstructuredGrid* g) {
         g->GetFieldData()->AddArray(array<vtkIntArray>("region_ids", {1, 2}));
         g->GetFieldData()->AddArray(strings("region_names", {"a"}));
       },
       "field arrays 'region_ids' (2 values) and 'region_names' (1) differ in length"},
      {[](vtkUnstructuredGrid* g) {
         g->GetFieldData()->AddArray(array<vtkDoubleArray>("region_ids", {1.5}));
         g->GetFieldData()->AddArray(strings("region_names", {"a"}));
       },
       "field array 'region_ids' must be a one-component integer array"},
      {[](vtkUnstructuredGrid* g) {
         g->GetFieldData()->AddArray(array<vtkIntArray>("region_ids", {1}));
         g->GetFieldData()->AddArray(array<vtkIntArray>("region_names", {1}));
       },
       "field array 'region_names' must be a string array"},
      {[](vtkUnstructuredGrid* g) {
         g->GetFieldData()->AddArray(array<vtkIntArray>("region_ids", {1, -1}));
         g->GetFieldData()->AddArray(strings("region_names", {"a", "b"}));
       },
       "field array 'region_ids' holds -1, not a region id in [0, 2147483647]"},
      {[](vtkUnstructuredGrid* g) {
         g->GetFieldData()->AddArray(array<vtkIntArray>("region_ids", {1, 1}));
         g->GetFieldData()->AddArray(strings("region_names", {"a", "b"}));
       },
       "field array 'region_ids' names region 1 twice"},
      {[](vtkUnstructuredGrid* g) {
         g->GetFieldData()->AddArray(array<vtkIntArray>("region_ids", {1, 2}));
         g->GetFieldData()->AddArray(strings("region_names", {"a", "a"}));
       },
       "region 2: the name 'a' names two regions"},
      {[](vtkUnstructuredGrid* g) {
         g->GetFieldData()->AddArray(array<vtkIntArray>("region_ids", {1}));
         g->GetFieldData()->AddArray(strings("region_names", {""}));
       },
       "region 1 has an empty name"},
      {[](vtkUnstructuredGrid* g) {
         g->GetFieldData()->AddArray(array<vtkIntArray>("region_ids", {1}));
         g->GetFieldData()->AddArray(strings("region_names", {"two\nlines"}));
       },
       "region 1 has a name with a control character"},
      {[](vtkUnstructuredGrid* g) {
         g->GetFieldData()->AddArray(array<vtkIntArray>("region_ids", {1}));
         g->GetFieldData()->AddArray(strings("region_names", {std::string(201, 'x')}));
       },
       "region 1 has a name of 201 characters (at most 200)"},
  };
  int i = 0;
  for (const auto& [decorate, message] : cases) {
    const std::string sub = dir + "/" + std::to_string(i++);
    fs::create_directories(sub);
    const std::string path = vtk_written(sub, decorate);
    INFO(message);
    CHECK(error_reading(path) == path + ": " + message);
  }
}

TEST_CASE("regions: a region array of the wrong length is refused in memory too", "[regions]") {
  xfem::TetMesh m = xfem::box_mesh({1, 1, 1}, {0, 0, 0}, {1, 1, 1});
  m.cell_data["region"] = xfem::make_array(xfem::DataArray::Type::Int32, 1, 2, 1);
  std::string message;
  try {
    xfem::validate_regions(m, "m");
  } catch (const xfem::Error& e) {
    message = e.what();
  }
  CHECK(message == "m: cell array 'region' has 2 values for 6 tetrahedra");
}
