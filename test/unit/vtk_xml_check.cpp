// SPDX-License-Identifier: MIT
// The pre-check of VTK XML files (lib/xfem/vtk_xml_check) must accept every layout VTK's own
// writers produce (other programs write these files: ParaView, meshio, pyvista), and refuse the
// corrupt headers that crash VTK 9.1's reader.
#include "xfem/io/vtk_xml_check.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <vtkXMLWriter.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iterator>

#include "xfem/core/error.h"
#include "xfem/io/vtk_io.h"

namespace {
namespace fs = std::filesystem;

std::string scratch(const std::string& name) {
  const auto dir = fs::temp_directory_path() / "xfem_unit_vtk_xml_check";
  fs::create_directories(dir);
  return (dir / name).string();
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// Every layout of vtkXMLWriter: data mode, appended encoding, header type, compressor, byte order.
template <class Writer>
void each_layout(vtkDataObject* data, const std::string& stem, const std::string& ext,
                 const std::function<void(const std::string&)>& check) {
  const int compressors[] = {vtkXMLWriter::NONE, vtkXMLWriter::ZLIB, vtkXMLWriter::LZ4, vtkXMLWriter::LZMA};
  int k = 0;
  for (int mode = 0; mode < 4; ++mode)
    for (int header = 0; header < 2; ++header)
      for (int compressor : compressors)
        for (int big = 0; big < 2; ++big) {
          vtkNew<Writer> w;
          w->SetInputData(data);
          if (mode == 0) w->SetDataModeToAscii();
          if (mode == 1) w->SetDataModeToBinary();
          if (mode >= 2) w->SetDataModeToAppended();
          w->SetEncodeAppendedData(mode == 3);
          w->SetHeaderType(header ? vtkXMLWriter::UInt64 : vtkXMLWriter::UInt32);
          w->SetCompressorType(compressor);
          w->SetByteOrder(big ? vtkXMLWriter::BigEndian : vtkXMLWriter::LittleEndian);
          const std::string path = scratch(stem + std::to_string(k++) + ext);
          w->SetFileName(path.c_str());
          REQUIRE(w->Write() == 1);
          INFO(path << " mode " << mode << " header " << header << " compressor " << compressor << " big " << big);
          check(path);
        }
}
}  // namespace

TEST_CASE("vtk_xml_check: every layout VTK writes is accepted and read back", "[vtk_xml_check]") {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const double xyz[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  for (const auto& p : xyz) points->InsertNextPoint(p);

  vtkNew<vtkPolyData> surface;
  surface->SetPoints(points);
  vtkNew<vtkCellArray> triangles;
  const vtkIdType t0[3] = {0, 1, 2}, t1[3] = {1, 3, 2};
  triangles->InsertNextCell(3, t0);
  triangles->InsertNextCell(3, t1);
  surface->SetPolys(triangles);
  each_layout<vtkXMLPolyDataWriter>(surface, "s", ".vtp", [](const std::string& path) {
    CHECK_NOTHROW(xfem::check_vtk_xml_sizes(path));
    const xfem::TriangleMesh m = xfem::read_triangle_mesh(path);
    CHECK(m.triangles.rows() == 2);
    CHECK(m.points(3, 2) == 1.0);
  });

  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  const vtkIdType tet0[4] = {0, 1, 2, 3}, tet1[4] = {1, 4, 2, 3};
  grid->InsertNextCell(VTK_TETRA, 4, tet0);
  grid->InsertNextCell(VTK_TETRA, 4, tet1);
  each_layout<vtkXMLUnstructuredGridWriter>(grid, "g", ".vtu", [](const std::string& path) {
    CHECK_NOTHROW(xfem::check_vtk_xml_sizes(path));
    const xfem::TetMesh m = xfem::read_tet_mesh(path);
    CHECK(m.tets.rows() == 2);
    CHECK(m.points(4, 0) == 1.0);
  });
}

TEST_CASE("vtk_xml_check: corrupt headers are refused with one line naming the file", "[vtk_xml_check]") {
  // A valid appended, compressed file to corrupt.
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 3; ++i) points->InsertNextPoint(i, i * i, 0);
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(points);
  vtkNew<vtkCellArray> triangles;
  const vtkIdType t0[3] = {0, 1, 2};
  triangles->InsertNextCell(3, t0);
  surface->SetPolys(triangles);
  const std::string good = scratch("good.vtp");
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetInputData(surface);
  w->SetEncodeAppendedData(false);  // raw bytes (the default is base64)
  w->SetFileName(good.c_str());
  REQUIRE(w->Write() == 1);
  const std::string text = slurp(good);
  const auto corrupted = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const std::size_t at = t.find(from);
    REQUIRE(at != std::string::npos);
    t.replace(at, from.size(), to);
    const std::string path = scratch("bad.vtp");
    write(path, t);
    return path;
  };
  using Catch::Contains;
  // The attribute read as the XML parser reads it: "versioncompressor" is not "compressor".
  CHECK_THROWS_WITH(xfem::read_triangle_mesh(corrupted("compressor=\"vtkZLibDataCompressor\"", "compressor=\"vtkNoSuch\"")),
                    Contains("bad.vtp: unknown compressor 'vtkNoSuch' (corrupt file?)"));
  CHECK_THROWS_WITH(xfem::read_triangle_mesh(corrupted("NumberOfPoints=\"3\"", "NumberOfPoints = '99999999999'")),
                    Contains("bad.vtp: NumberOfPoints = 99999999999 is more than"));
  CHECK_THROWS_WITH(xfem::read_triangle_mesh(corrupted("NumberOfPoints=\"3\"", "NumberOfPoints=\"-3\"")),
                    Contains("bad.vtp: NumberOfPoints = '-3' is not a count"));
  CHECK_THROWS_WITH(xfem::read_triangle_mesh(corrupted("NumberOfComponents=\"3\"", "NumberOfComponents=\"1000000\"")),
                    Contains("components is more than"));
  // VTK takes the first non-space character after <AppendedData ...> for the data's start.
  CHECK_THROWS_WITH(xfem::read_triangle_mesh(corrupted("encoding=\"raw\">\n   _", "encoding=\"raw\">\n  C _")),
                    Contains("bad.vtp: the appended data does not start with '_'"));
  CHECK_THROWS_WITH(xfem::read_triangle_mesh(corrupted("offset=\"0\"", "offset=\"99999\"")),
                    Contains("beyond the end of the file"));
  // A block count of 2^32 - 1 in the first array's header.
  const std::size_t data = text.find('_', text.find("<AppendedData")) + 1;
  std::string t = text;
  for (int b = 0; b < 4; ++b) t[data + b] = '\xff';
  write(scratch("blocks.vtp"), t);
  CHECK_THROWS_WITH(xfem::read_triangle_mesh(scratch("blocks.vtp")),
                    Contains("blocks.vtp: a compressed array claims more blocks than the file holds (corrupt file?)"));
}
