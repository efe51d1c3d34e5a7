// SPDX-License-Identifier: MIT
// write_triangle_mesh: a cut surface as VTK XML .vtp, or .vtu (a grid of triangles).
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "xfem/core/atomic_file.h"
#include "xfem/core/error.h"
#include "xfem/io/surface_write.h"
#include "xfem/io/vtk_io.h"
#include "xfem/io/vtk_io_detail.h"

namespace xfem {
using namespace vtk_io_detail;
namespace {

// A surface as a VTK XML unstructured grid of triangles: for readers that take no .vtp (meshio).
void write_triangle_grid(const TriangleMesh& mesh, const DataArrays* field_data, const std::string& path,
                         Compression compression) {
  auto grid = Ptr<vtkUnstructuredGrid>::New();
  grid->SetPoints(to_vtk(mesh.points, path));
  grid->SetCells(VTK_TRIANGLE, cell_array(mesh.triangles));
  write_vtk_xml(Ptr<vtkXMLUnstructuredGridWriter>::New(), grid, mesh.point_data, mesh.cell_data, field_data, path, path,
                compression);
}

// The surface with `field_data` (null: none) as .vtp, or .vtu (a grid of triangles).
void write_surface(const TriangleMesh& mesh, const DataArrays* field_data, const std::string& path,
                   Compression compression) {
  if (path != "-" && extension_of(path) == ".vtu") return write_triangle_grid(mesh, field_data, path, compression);
  if (path != "-" && extension_of(path) != ".vtp")
    throw Error(path + ": surfaces are written as .vtp or .vtu, not '" + extension_of(path) + "'");
  const std::string name = path == "-" ? std::string("<stdout>") : path;
  auto poly = Ptr<vtkPolyData>::New();
  poly->SetPoints(to_vtk(mesh.points, name));
  poly->SetPolys(cell_array(mesh.triangles));
  write_vtk_xml(Ptr<vtkXMLPolyDataWriter>::New(), poly, mesh.point_data, mesh.cell_data, field_data, path, name,
                compression);
}

}  // namespace

void write_triangle_mesh(const TriangleMesh& mesh, const std::string& path, Compression compression) {
  write_surface(mesh, nullptr, path, compression);
}

void write_triangle_mesh(const TriangleMesh& mesh, const DataArrays& field_data, const std::string& path,
                         Compression compression) {
  write_surface(mesh, &field_data, path, compression);
}

}  // namespace xfem
