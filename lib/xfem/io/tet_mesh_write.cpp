// SPDX-License-Identifier: MIT
// write_tet_mesh: a tetrahedral mesh as VTK XML .vtu.
#include <vtkFieldData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "xfem/core/atomic_file.h"
#include "xfem/core/error.h"
#include "xfem/io/vtk_io.h"
#include "xfem/io/vtk_io_detail.h"

namespace xfem {
using namespace vtk_io_detail;

void write_tet_mesh(const TetMesh& mesh, const std::string& path, Compression compression) {
  if (path != "-" && extension_of(path) != ".vtu")
    throw Error(path + ": volume meshes are written as .vtu, not '" + extension_of(path) + "'");
  const std::string name = path == "-" ? std::string("<stdout>") : path;
  auto grid = Ptr<vtkUnstructuredGrid>::New();
  grid->SetPoints(to_vtk(mesh.points, name));
  grid->SetCells(VTK_TETRA, cell_array(mesh.tets));
  add_region_names(grid->GetFieldData(), mesh.region_names, mesh.field_data, name);
  write_vtk_xml(Ptr<vtkXMLUnstructuredGridWriter>::New(), grid, mesh.point_data, mesh.cell_data, &mesh.field_data,
                path, name, compression);
}

}  // namespace xfem
