// SPDX-License-Identifier: MIT
// read_tet_mesh: a tetrahedral mesh from .vtu, legacy .vtk or standard input (gmsh .msh: gmsh_io.cpp).
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <array>
#include <cmath>

#include "xfem/core/atomic_file.h"
#include "xfem/core/boundary_groups.h"
#include "xfem/core/error.h"
#include "xfem/io/gmsh_io.h"
#include "xfem/io/vtk_io.h"
#include "xfem/io/vtk_io_detail.h"

namespace xfem {
using namespace vtk_io_detail;
namespace {

// Cells a mesher writes beside the tets of a volume mesh: its geometry points, edges and
// boundary triangles. Other cell types stay errors (copy_cell names them).
bool is_lower_dimensional(int type) {
  return type == VTK_VERTEX || type == VTK_POLY_VERTEX || type == VTK_LINE || type == VTK_POLY_LINE ||
         type == VTK_TRIANGLE;
}

// The cell array naming the boundary group of each triangle: "group", or meshio's
// "gmsh:physical" (a gmsh mesh converted by meshio). Null when there is none.
const DataArray* triangle_groups(const DataArrays& cell_data) {
  for (const char* name : {"group", "gmsh:physical"}) {
    const auto it = cell_data.find(name);
    if (it != cell_data.end() && it->second.components == 1) return &it->second;
  }
  return nullptr;
}

// A mixed-cell grid (gmsh's VTK export, meshio's conversion): tets are the body, triangles
// join the group their "group" cell value names, vertices and lines carry nothing.
TetMesh read_mixed_grid(vtkUnstructuredGrid* grid, const std::string& name, std::vector<std::string>* warnings) {
  MixedMesh mixed;
  mixed.points = to_points(grid->GetPoints());
  mixed.point_data = to_arrays(grid->GetPointData());
  mixed.cell_data = to_arrays(grid->GetCellData());
  mixed.field_data = to_arrays(grid->GetFieldData());
  auto region_names = take_region_names(grid->GetFieldData(), mixed.field_data, name);
  const DataArray* group = triangle_groups(mixed.cell_data);
  const vtkIdType nc = grid->GetNumberOfCells(), np = grid->GetNumberOfPoints();
  for (vtkIdType i = 0; i < nc; ++i) {
    vtkIdType npts;
    const vtkIdType* ids;
    grid->GetCells()->GetCellAtId(i, npts, ids);
    const int type = grid->GetCellType(i);
    if (type == VTK_TRIANGLE && group) {
      std::array<int, 3> triangle;
      copy_cell(type, npts, ids, i, VTK_TRIANGLE, "triangles", np, name, triangle);
      const double g = (*group)(static_cast<std::size_t>(i));
      if (!(g == std::floor(g) && std::abs(g) < 1e9))
        throw Error(name + ": cell " + std::to_string(i) + " has group " + std::to_string(g) + ", not an integer");
      auto& members = mixed.groups[std::to_string(static_cast<long>(g))];
      members.insert(members.end(), triangle.begin(), triangle.end());
    } else if (!is_lower_dimensional(type)) {
      std::array<int, 4> tet;
      copy_cell(type, npts, ids, i, VTK_TETRA, "tetrahedra, triangles, lines or vertices", np, name, tet);
      mixed.tets.push_back(tet);
      mixed.tet_cells.push_back(static_cast<long>(i));
    }
  }
  // The group's value is now a point set: its cell array would mean nothing on the tets.
  if (group) mixed.cell_data.erase(mixed.cell_data.count("group") ? "group" : "gmsh:physical");
  TetMesh mesh = body_of(mixed, name);
  mesh.region_names = std::move(region_names);
  validate_tet_mesh(mesh, name, warnings);
  return mesh;
}

bool has_lower_dimensional_cells(vtkUnstructuredGrid* grid) {
  for (vtkIdType i = 0; i < grid->GetNumberOfCells(); ++i)
    if (is_lower_dimensional(grid->GetCellType(i))) return true;
  return false;
}

}  // namespace

TetMesh read_tet_mesh(const std::string& path, std::vector<std::string>* warnings) {
  if (path != "-" && extension_of(path) == ".msh") return read_gmsh_tet_mesh(path, warnings);
  const std::string name = display_name(path);
  TetMesh mesh;
  {
    VtkMessages messages;
    auto grid = read_unstructured_grid(path, messages);
    if (has_lower_dimensional_cells(grid)) return read_mixed_grid(grid, name, warnings);
    mesh.points = to_points(grid->GetPoints());
    const vtkIdType nc = grid->GetNumberOfCells();
    const vtkIdType np = grid->GetNumberOfPoints();
    mesh.tets.resize(nc, 4);
    vtkCellArray* cells = grid->GetCells();
    for (vtkIdType i = 0; i < nc; ++i) {
      vtkIdType npts;
      const vtkIdType* ids;
      cells->GetCellAtId(i, npts, ids);
      copy_cell(grid->GetCellType(i), npts, ids, i, VTK_TETRA, "tetrahedra", np, name, mesh.tets.row(i));
    }
    mesh.point_data = to_arrays(grid->GetPointData());
    mesh.cell_data = to_arrays(grid->GetCellData());
    mesh.field_data = to_arrays(grid->GetFieldData());
    mesh.region_names = take_region_names(grid->GetFieldData(), mesh.field_data, name);
  }
  validate_tet_mesh(mesh, name, warnings);
  return mesh;
}

}  // namespace xfem
