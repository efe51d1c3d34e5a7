// SPDX-License-Identifier: MIT
// read_triangle_mesh: a cut surface from .vtp, .vtu, legacy .vtk, .stl, .obj, .off or standard input
// (gmsh .msh: gmsh_io.cpp).
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataSetReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <sstream>

#include "xfem/core/atomic_file.h"
#include "xfem/core/error.h"
#include "xfem/io/gmsh_io.h"
#include "xfem/io/vtk_io.h"
#include "xfem/io/vtk_io_detail.h"
#include "xfem/io/vtk_on_demand.h"
#include "xfem/io/vtk_xml_check.h"

namespace xfem {
using namespace vtk_io_detail;
namespace {

// OFF and OBJ through CGAL, in double precision (VTK's OBJ reader stores float: a cut through mesh
// nodes would move by 1e-8 and miss them).
TriangleMesh read_off(const std::string& path, bool obj = false) {
  std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::ifstream in(path);
  if (!obj) {  // OFF: the counts in the header, checked against the file size before CGAL allocates.
    std::vector<std::string> words;  // the first words, comments left out
    std::string line, word;
    while (words.size() < 3 && std::getline(in, line)) {
      std::istringstream split(line.substr(0, line.find('#')));
      while (words.size() < 3 && split >> word) words.push_back(word);
    }
    if (!words.empty() && words[0].find("OFF") != std::string::npos) words.erase(words.begin());
    long long nv = -1, nf = -1;
    if (words.size() >= 2) {
      std::istringstream(words[0]) >> nv;
      std::istringstream(words[1]) >> nf;
    }
    in.clear();
    in.seekg(0, std::ios::end);
    const long long size = static_cast<long long>(in.tellg());
    if (nv < 0 || nf < 0) throw Error(path + ": not a readable OFF file (no vertex and face counts)");
    if (nv > size / 6 + 1 || nf > size / 8 + 1)
      throw Error(path + ": the OFF header claims " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                  " faces, more than the " + std::to_string(size) + " bytes of the file can hold");
    in.seekg(0);
  }
  // verbose(false): CGAL would otherwise explain its failure on std::cerr.
  if (!(obj ? CGAL::IO::read_OBJ(in, points, polygons, CGAL::parameters::verbose(false))
            : CGAL::IO::read_OFF(in, points, polygons, CGAL::parameters::verbose(false))))
    throw Error(path + (obj ? ": not a readable OBJ file" : ": not a readable OFF file"));
  TriangleMesh mesh;
  mesh.points.resize(points.size(), 3);
  for (std::size_t i = 0; i < points.size(); ++i)
    mesh.points.row(i) << points[i].x(), points[i].y(), points[i].z();
  mesh.triangles.resize(polygons.size(), 3);
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    if (polygons[f].size() != 3)
      throw Error(path + ": face " + std::to_string(f) + " has " + std::to_string(polygons[f].size()) +
                  " vertices, expected triangles only");
    // CGAL has checked the indices: a face naming a missing vertex makes read_OFF fail.
    for (int k = 0; k < 3; ++k) mesh.triangles(f, k) = static_cast<int>(polygons[f][k]);
  }
  return mesh;
}

// Binary STL has no signature, and VTK reads any bytes as one: check that the file is exactly
// the 80-byte header, the triangle count and 50 bytes per triangle, unless it is ASCII ("solid").
void check_stl(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char header[84] = {};
  in.read(header, sizeof header);
  const std::streamsize got = in.gcount();
  in.seekg(0, std::ios::end);
  const auto size = static_cast<std::uint64_t>(in.tellg());
  if (got == 84) {
    const auto* b = reinterpret_cast<const unsigned char*>(header + 80);
    const std::uint64_t n = b[0] | b[1] << 8 | b[2] << 16 | static_cast<std::uint64_t>(b[3]) << 24;
    if (size == 84 + 50 * n) return;  // binary (even if its header happens to start with "solid")
  }
  std::size_t i = 0;
  while (i < static_cast<std::size_t>(got) && std::isspace(static_cast<unsigned char>(header[i]))) ++i;
  if (std::string(header + i, std::min<std::size_t>(5, got - i)) != "solid")
    throw Error(path + ": not an STL file (neither ASCII 'solid ...' nor binary with a matching triangle count)");
  // ASCII. VTK takes a file with a byte above 127 near its start for binary whatever its first
  // word, and then allocates the triangle count of bytes 80-83: refuse any byte ASCII lacks.
  in.clear();
  in.seekg(0);
  char chunk[65536];
  std::uint64_t at = 0;
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    for (std::streamsize k = 0; k < in.gcount(); ++k)
      if (static_cast<unsigned char>(chunk[k]) > 127)
        throw Error(path + ": byte " + std::to_string(at + static_cast<std::uint64_t>(k)) +
                    " is not ASCII in an ASCII STL file ('solid ...'), and the size does not fit a binary one");
    at += static_cast<std::uint64_t>(in.gcount());
  }
}

TriangleMesh from_polydata(vtkPolyData* poly, const std::string& name) {
  TriangleMesh mesh;
  mesh.points = to_points(poly->GetPoints());
  const vtkIdType np = poly->GetNumberOfPoints();
  // The polygons read straight from their cell array: vtkPolyData's cell map (GetCellType) is
  // built from all four arrays and was a null pointer on a damaged file (found by fuzzing).
  vtkCellArray* polys = poly->GetPolys();
  const vtkIdType nc = polys ? polys->GetNumberOfCells() : 0;
  mesh.triangles.resize(std::max<vtkIdType>(nc, 1), 3);  // row 0 for the error below
  // Cells are numbered vertices first, then lines, polygons, strips: the first that is no polygon.
  const vtkIdType verts = poly->GetNumberOfVerts(), lines = poly->GetNumberOfLines();
  if (verts > 0 || lines > 0 || poly->GetNumberOfStrips() > 0)
    copy_cell(verts > 0 ? VTK_VERTEX : lines > 0 ? VTK_LINE : VTK_TRIANGLE_STRIP, 0, nullptr, verts + lines > 0 ? 0 : nc,
              VTK_TRIANGLE, "triangles", np, name, mesh.triangles.row(0));
  for (vtkIdType i = 0; i < nc; ++i) {
    vtkIdType npts;
    const vtkIdType* ids;
    polys->GetCellAtId(i, npts, ids);
    copy_cell(npts == 3 ? VTK_TRIANGLE : VTK_POLYGON, npts, ids, i, VTK_TRIANGLE, "triangles", np, name,
              mesh.triangles.row(i));
  }
  mesh.triangles.conservativeResize(nc, 3);
  mesh.point_data = to_arrays(poly->GetPointData());
  mesh.cell_data = to_arrays(poly->GetCellData());
  return mesh;
}

TriangleMesh from_grid(vtkUnstructuredGrid* grid, const std::string& name) {
  TriangleMesh mesh;
  mesh.points = to_points(grid->GetPoints());
  const vtkIdType nc = grid->GetNumberOfCells();
  const vtkIdType np = grid->GetNumberOfPoints();
  mesh.triangles.resize(nc, 3);
  for (vtkIdType i = 0; i < nc; ++i) {
    vtkIdType npts;
    const vtkIdType* ids;
    grid->GetCells()->GetCellAtId(i, npts, ids);
    copy_cell(grid->GetCellType(i), npts, ids, i, VTK_TRIANGLE, "triangles", np, name, mesh.triangles.row(i));
  }
  mesh.point_data = to_arrays(grid->GetPointData());
  mesh.cell_data = to_arrays(grid->GetCellData());
  return mesh;
}

}  // namespace

TriangleMesh read_triangle_mesh(const std::string& path, std::vector<std::string>* warnings) {
  if (path != "-" && extension_of(path) == ".msh") return read_gmsh_triangle_mesh(path, warnings);
  const std::string name = display_name(path);
  const char* what = "triangle surface";
  TriangleMesh mesh;
  {
    VtkMessages messages;
    const std::string ext = path == "-" ? std::string(".vtp") : extension_of(path);  // stdin carries VTK XML
    if (path != "-") require_readable(path);
    if (ext == ".vtp") {
      auto reader = Ptr<vtkXMLPolyDataReader>::New();
      if (path == "-") {
        reader->ReadFromInputStringOn();
        const std::string text = read_stdin();
        check_vtk_xml_text(name, text);
        reader->SetInputString(text);
      } else {
        if (!reader->CanReadFile(path.c_str())) throw Error(path + ": not a VTK XML polydata (.vtp) file");
        check_vtk_xml_sizes(path);
        reader->SetFileName(path.c_str());
      }
      update_or_throw(reader.Get(), messages, name, what);
      mesh = from_polydata(reader->GetOutput(), name);
    } else if (ext == ".vtk") {
      check_legacy_sections(path);
      auto reader = Ptr<vtkDataSetReader>::New();
      reader->SetFileName(path.c_str());
      configure_legacy(reader.Get());
      update_or_throw(reader.Get(), messages, path, what);
      if (auto poly = vtkPolyData::SafeDownCast(reader->GetOutput()))
        mesh = from_polydata(poly, path);
      else if (auto grid = vtkUnstructuredGrid::SafeDownCast(reader->GetOutput()))
        mesh = from_grid(grid, path);
      else
        throw Error(path + ": not a legacy VTK POLYDATA or UNSTRUCTURED_GRID file");
    } else if (ext == ".vtu") {  // an unstructured grid of triangles (meshio reads and writes these)
      mesh = from_grid(read_unstructured_grid(path, messages), path);
    } else if (ext == ".stl") {
      check_stl(path);
      auto reader = Ptr<vtkSTLReader>::Take(vtk_new_on_demand<vtkSTLReader>(  // not linked: vtk_on_demand.h
          vtk_io_geometry_library, "_ZN12vtkSTLReader3NewEv", path, what));
      reader->SetFileName(path.c_str());
      reader->MergingOn();  // STL repeats each vertex in every facet; merge exact duplicates
      update_or_throw(reader.Get(), messages, path, what);
      mesh = from_polydata(reader->GetOutput(), path);
    } else if (ext == ".obj") {
      mesh = read_off(path, true);
    } else if (ext == ".off") {
      mesh = read_off(path);
    } else {
      throw Error(path + ": unknown extension '" + ext + "' for a " + what +
                  " (expected .vtp, .vtu, .vtk, .stl, .obj, .off or .msh)");
    }
  }
  validate_triangle_mesh(mesh, name, warnings);
  return mesh;
}

}  // namespace xfem
