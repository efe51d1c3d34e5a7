// SPDX-License-Identifier: MIT
#include "xfem/vtk_io.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellTypes.h>
#include <vtkCommand.h>
#include <vtkDataSetReader.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkLongLongArray.h>
#include <vtkOBJReader.h>
#include <vtkObject.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OFF.h>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <queue>

#include "xfem/atomic_file.h"
#include "xfem/error.h"

namespace xfem {
namespace {

template <class T>
using Ptr = vtkSmartPointer<T>;

// VTK reports problems through its output window and keeps going; this observer turns the first
// error an algorithm raises into an exception with the file's name.
class ErrorCatcher : public vtkCommand {
 public:
  static ErrorCatcher* New() { return new ErrorCatcher; }
  void Execute(vtkObject*, unsigned long, void* data) override {
    if (message.empty() && data) message = static_cast<const char*>(data);
  }
  std::string message;
};

template <class Algorithm>
void update_or_throw(Algorithm* algorithm, const std::string& path, const char* what) {
  vtkObject::GlobalWarningDisplayOff();
  auto catcher = Ptr<ErrorCatcher>::New();
  algorithm->AddObserver(vtkCommand::ErrorEvent, catcher);
  algorithm->AddObserver(vtkCommand::WarningEvent, catcher);
  algorithm->Update();
  if (!catcher->message.empty()) {
    std::string m = catcher->message;
    while (!m.empty() && (m.back() == '\n' || m.back() == ' ')) m.pop_back();
    const auto nl = m.rfind('\n');
    if (nl != std::string::npos) m = m.substr(nl + 1);
    throw Error(path + ": cannot read " + what + ": " + m);
  }
}

DataArray to_array(vtkDataArray* in) {
  DataArray out;
  const int type = in->GetDataType();
  const bool is_float = type == VTK_FLOAT || type == VTK_DOUBLE;
  const bool is_wide = type == VTK_LONG || type == VTK_LONG_LONG || type == VTK_ID_TYPE ||
                       type == VTK_UNSIGNED_LONG || type == VTK_UNSIGNED_LONG_LONG ||
                       type == VTK_UNSIGNED_INT;
  out.type = is_float ? DataArray::Type::Float64 : is_wide ? DataArray::Type::Int64 : DataArray::Type::Int32;
  out.components = in->GetNumberOfComponents();
  const vtkIdType n = in->GetNumberOfTuples();
  out.values.resize(static_cast<std::size_t>(n) * out.components);
  for (vtkIdType i = 0; i < n; ++i)
    for (int c = 0; c < out.components; ++c) out.values[i * out.components + c] = in->GetComponent(i, c);
  return out;
}

DataArrays to_arrays(vtkFieldData* in) {
  DataArrays out;
  if (!in) return out;
  for (int i = 0; i < in->GetNumberOfArrays(); ++i) {
    vtkDataArray* a = in->GetArray(i);  // null for string arrays, which carry nothing we use
    if (a && a->GetName()) out[a->GetName()] = to_array(a);
  }
  return out;
}

Ptr<vtkDataArray> to_vtk(const std::string& name, const DataArray& in) {
  Ptr<vtkDataArray> out;
  switch (in.type) {
    case DataArray::Type::Int32: out = Ptr<vtkIntArray>::New(); break;
    case DataArray::Type::Int64: out = Ptr<vtkLongLongArray>::New(); break;
    case DataArray::Type::Float64: out = Ptr<vtkDoubleArray>::New(); break;
  }
  out->SetName(name.c_str());
  out->SetNumberOfComponents(in.components);
  out->SetNumberOfTuples(static_cast<vtkIdType>(in.tuples()));
  for (std::size_t i = 0; i < in.values.size(); ++i) out->SetVariantValue(static_cast<vtkIdType>(i), in.values[i]);
  return out;
}

void add_arrays(vtkFieldData* out, const DataArrays& arrays, std::size_t tuples, const char* where,
                const std::string& path) {
  for (const auto& [name, array] : arrays) {
    if (tuples != static_cast<std::size_t>(-1) && array.tuples() != tuples)
      throw Error(path + ": cannot write " + where + " array '" + name + "': " +
                  std::to_string(array.tuples()) + " tuples for " + std::to_string(tuples) + " items");
    out->AddArray(to_vtk(name, array));
  }
}

Points to_points(vtkPoints* in) {
  Points out(in ? in->GetNumberOfPoints() : 0, 3);
  for (Eigen::Index i = 0; i < out.rows(); ++i) {
    double p[3];
    in->GetPoint(i, p);
    out.row(i) << p[0], p[1], p[2];
  }
  return out;
}

Ptr<vtkPoints> to_vtk(const Points& in) {
  auto out = Ptr<vtkPoints>::New();
  out->SetDataTypeToDouble();
  out->SetNumberOfPoints(in.rows());
  for (Eigen::Index i = 0; i < in.rows(); ++i) out->SetPoint(i, in(i, 0), in(i, 1), in(i, 2));
  return out;
}

std::string cell_type_name(int type) {
  const char* name = vtkCellTypes::GetClassNameFromTypeId(type);
  return std::string(name ? name : "unknown cell") + " (VTK type " + std::to_string(type) + ")";
}

Ptr<vtkUnstructuredGrid> read_unstructured_grid(const std::string& path, const char* what) {
  require_readable(path);
  const std::string ext = extension_of(path);
  if (ext == ".vtu") {
    auto reader = Ptr<vtkXMLUnstructuredGridReader>::New();
    if (!reader->CanReadFile(path.c_str()))
      throw Error(path + ": not a VTK XML unstructured grid (.vtu) file");
    reader->SetFileName(path.c_str());
    update_or_throw(reader.Get(), path, what);
    return reader->GetOutput();
  }
  if (ext == ".vtk") {
    auto reader = Ptr<vtkDataSetReader>::New();
    reader->SetFileName(path.c_str());
    reader->ReadAllScalarsOn();
    reader->ReadAllVectorsOn();
    reader->ReadAllFieldsOn();
    update_or_throw(reader.Get(), path, what);
    auto grid = vtkUnstructuredGrid::SafeDownCast(reader->GetOutput());
    if (!grid) throw Error(path + ": legacy VTK file is not an UNSTRUCTURED_GRID");
    return grid;
  }
  throw Error(path + ": unknown extension '" + ext + "' for " + what + " (expected .vtu or .vtk)");
}

}  // namespace

int validate_tet_mesh(TetMesh& mesh, const std::string& name, std::vector<std::string>* warnings) {
  const Eigen::Index np = mesh.points.rows(), nt = mesh.tets.rows();
  if (np == 0 || nt == 0) throw Error(name + ": empty mesh (" + std::to_string(np) + " points, " +
                                      std::to_string(nt) + " tetrahedra)");
  for (Eigen::Index i = 0; i < np; ++i)
    if (!mesh.points.row(i).allFinite())
      throw Error(name + ": point " + std::to_string(i) + " has a non-finite coordinate");
  for (Eigen::Index t = 0; t < nt; ++t)
    for (int k = 0; k < 4; ++k)
      if (mesh.tets(t, k) < 0 || mesh.tets(t, k) >= np)
        throw Error(name + ": tetrahedron " + std::to_string(t) + " uses point " +
                    std::to_string(mesh.tets(t, k)) + ", out of range [0, " + std::to_string(np) + ")");
  // Zero volume is judged relative to the tet's own longest edge, so the test is scale-free.
  long degenerate = 0, inverted = 0, first_degenerate = -1, first_inverted = -1;
  for (Eigen::Index t = 0; t < nt; ++t) {
    const auto& c = mesh.tets.row(t);
    double longest = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        longest = std::max(longest, (mesh.points.row(c[a]) - mesh.points.row(c[b])).squaredNorm());
    const double v6 = 6.0 * signed_volume(mesh, static_cast<int>(t));
    if (std::abs(v6) <= 1e-12 * std::pow(longest, 1.5)) {
      if (degenerate++ == 0) first_degenerate = t;
    } else if (v6 < 0) {
      if (inverted++ == 0) first_inverted = t;
      std::swap(mesh.tets(t, 1), mesh.tets(t, 2));
    }
  }
  if (degenerate)
    throw Error(name + ": " + std::to_string(degenerate) + " tetrahedra have zero volume (first: tetrahedron " +
                std::to_string(first_degenerate) + ")");
  if (inverted && warnings)
    warnings->push_back(name + ": " + std::to_string(inverted) +
                        " inverted tetrahedra reoriented (first: tetrahedron " + std::to_string(first_inverted) + ")");
  return static_cast<int>(inverted);
}

TetMesh read_tet_mesh(const std::string& path, std::vector<std::string>* warnings) {
  auto grid = read_unstructured_grid(path, "tetrahedral mesh");
  TetMesh mesh;
  mesh.points = to_points(grid->GetPoints());
  const vtkIdType nc = grid->GetNumberOfCells();
  mesh.tets.resize(nc, 4);
  const vtkIdType np = grid->GetNumberOfPoints();
  vtkCellArray* cells = grid->GetCells();
  for (vtkIdType i = 0; i < nc; ++i) {
    const int type = grid->GetCellType(i);
    if (type != VTK_TETRA)
      throw Error(path + ": cell " + std::to_string(i) + " is a " + cell_type_name(type) +
                  ", expected tetrahedra only (VTK type 10)");
    vtkIdType npts;
    const vtkIdType* ids;
    cells->GetCellAtId(i, npts, ids);
    for (int k = 0; k < 4; ++k) {
      if (ids[k] < 0 || ids[k] >= np)
        throw Error(path + ": tetrahedron " + std::to_string(i) + " uses point " + std::to_string(ids[k]) +
                    ", out of range [0, " + std::to_string(np) + ")");
      mesh.tets(i, k) = static_cast<int>(ids[k]);
    }
  }
  mesh.point_data = to_arrays(grid->GetPointData());
  mesh.cell_data = to_arrays(grid->GetCellData());
  mesh.field_data = to_arrays(grid->GetFieldData());
  validate_tet_mesh(mesh, path, warnings);
  return mesh;
}

void write_tet_mesh(const TetMesh& mesh, const std::string& path) {
  if (extension_of(path) != ".vtu") throw Error(path + ": volume meshes are written as .vtu");
  auto grid = Ptr<vtkUnstructuredGrid>::New();
  grid->SetPoints(to_vtk(mesh.points));
  auto offsets = Ptr<vtkIdTypeArray>::New();
  auto connectivity = Ptr<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(mesh.tets.rows() + 1);
  connectivity->SetNumberOfValues(mesh.tets.size());
  for (Eigen::Index t = 0; t <= mesh.tets.rows(); ++t) offsets->SetValue(t, 4 * t);
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t)
    for (int k = 0; k < 4; ++k) connectivity->SetValue(4 * t + k, mesh.tets(t, k));
  auto cells = Ptr<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  grid->SetCells(VTK_TETRA, cells);
  add_arrays(grid->GetPointData(), mesh.point_data, mesh.points.rows(), "point", path);
  add_arrays(grid->GetCellData(), mesh.cell_data, mesh.tets.rows(), "cell", path);
  add_arrays(grid->GetFieldData(), mesh.field_data, static_cast<std::size_t>(-1), "field", path);
  write_atomically(path, [&](const std::string& tmp) {
    auto writer = Ptr<vtkXMLUnstructuredGridWriter>::New();
    writer->SetFileName(tmp.c_str());
    writer->SetInputData(grid);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetCompressorTypeToZLib();
    writer->SetCompressionLevel(1);
    if (writer->Write() != 1) throw Error(path + ": cannot write (disk full or no permission?)");
  });
}

namespace {

TriangleMesh read_off(const std::string& path) {
  std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::ifstream in(path);
  if (!CGAL::IO::read_OFF(in, points, polygons) || points.empty())
    throw Error(path + ": not a readable OFF file");
  TriangleMesh mesh;
  mesh.points.resize(points.size(), 3);
  for (std::size_t i = 0; i < points.size(); ++i)
    mesh.points.row(i) << points[i].x(), points[i].y(), points[i].z();
  mesh.triangles.resize(polygons.size(), 3);
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    if (polygons[f].size() != 3)
      throw Error(path + ": face " + std::to_string(f) + " has " + std::to_string(polygons[f].size()) +
                  " vertices, expected triangles only");
    for (int k = 0; k < 3; ++k) mesh.triangles(f, k) = static_cast<int>(polygons[f][k]);
  }
  return mesh;
}

TriangleMesh from_polydata(vtkPolyData* poly, const std::string& path) {
  TriangleMesh mesh;
  mesh.points = to_points(poly->GetPoints());
  const vtkIdType nc = poly->GetNumberOfCells();
  mesh.triangles.resize(nc, 3);
  for (vtkIdType i = 0; i < nc; ++i) {
    const int type = poly->GetCellType(i);
    if (type != VTK_TRIANGLE)
      throw Error(path + ": cell " + std::to_string(i) + " is a " + cell_type_name(type) +
                  ", expected triangles only (VTK type 5)");
    vtkIdType npts;
    const vtkIdType* ids;
    poly->GetCellPoints(i, npts, ids);
    for (int k = 0; k < 3; ++k) mesh.triangles(i, k) = static_cast<int>(ids[k]);
  }
  mesh.point_data = to_arrays(poly->GetPointData());
  mesh.cell_data = to_arrays(poly->GetCellData());
  return mesh;
}

TriangleMesh from_grid(vtkUnstructuredGrid* grid, const std::string& path) {
  TriangleMesh mesh;
  mesh.points = to_points(grid->GetPoints());
  const vtkIdType nc = grid->GetNumberOfCells();
  mesh.triangles.resize(nc, 3);
  for (vtkIdType i = 0; i < nc; ++i) {
    const int type = grid->GetCellType(i);
    if (type != VTK_TRIANGLE)
      throw Error(path + ": cell " + std::to_string(i) + " is a " + cell_type_name(type) +
                  ", expected triangles only (VTK type 5)");
    vtkIdType npts;
    const vtkIdType* ids;
    grid->GetCells()->GetCellAtId(i, npts, ids);
    for (int k = 0; k < 3; ++k) mesh.triangles(i, k) = static_cast<int>(ids[k]);
  }
  mesh.point_data = to_arrays(grid->GetPointData());
  mesh.cell_data = to_arrays(grid->GetCellData());
  return mesh;
}

// Keeps the rows of every cell array whose triangle survives.
void keep_cells(DataArrays& arrays, const std::vector<int>& kept) {
  for (auto& [name, a] : arrays) {
    std::vector<double> values;
    values.reserve(kept.size() * a.components);
    for (int f : kept)
      for (int c = 0; c < a.components; ++c) values.push_back(a(f, c));
    a.values = std::move(values);
  }
}

}  // namespace

void validate_triangle_mesh(TriangleMesh& mesh, const std::string& name, std::vector<std::string>* warnings) {
  const Eigen::Index np = mesh.points.rows();
  if (np == 0 || mesh.triangles.rows() == 0)
    throw Error(name + ": empty surface (" + std::to_string(np) + " points, " +
                std::to_string(mesh.triangles.rows()) + " triangles)");
  for (Eigen::Index i = 0; i < np; ++i)
    if (!mesh.points.row(i).allFinite())
      throw Error(name + ": point " + std::to_string(i) + " has a non-finite coordinate");
  std::vector<int> kept;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles(f, k) < 0 || mesh.triangles(f, k) >= np)
        throw Error(name + ": triangle " + std::to_string(f) + " uses point " +
                    std::to_string(mesh.triangles(f, k)) + ", out of range [0, " + std::to_string(np) + ")");
    const Eigen::Vector3d a = mesh.points.row(mesh.triangles(f, 0)), b = mesh.points.row(mesh.triangles(f, 1)),
                          c = mesh.points.row(mesh.triangles(f, 2));
    const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    if ((b - a).cross(c - a).norm() > 1e-12 * longest) kept.push_back(static_cast<int>(f));
  }
  if (kept.empty()) throw Error(name + ": every triangle has zero area");
  if (kept.size() != static_cast<std::size_t>(mesh.triangles.rows())) {
    if (warnings)
      warnings->push_back(name + ": " + std::to_string(mesh.triangles.rows() - kept.size()) +
                          " zero-area triangles dropped");
    Triangles t(kept.size(), 3);
    for (std::size_t i = 0; i < kept.size(); ++i) t.row(i) = mesh.triangles.row(kept[i]);
    mesh.triangles = t;
    keep_cells(mesh.cell_data, kept);
  }

  // Orientation: two triangles sharing an edge agree when they run along it in opposite
  // directions. Breadth-first from the lowest-numbered triangle of each piece, flipping as needed.
  const int nf = static_cast<int>(mesh.triangles.rows());
  std::map<std::pair<int, int>, std::vector<int>> edge_faces;  // undirected edge -> faces
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      int a = mesh.triangles(f, k), b = mesh.triangles(f, (k + 1) % 3);
      edge_faces[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  for (const auto& [edge, faces] : edge_faces)
    if (faces.size() > 2)
      throw Error(name + ": edge (" + std::to_string(edge.first) + ", " + std::to_string(edge.second) +
                  ") is shared by " + std::to_string(faces.size()) + " triangles; a cut must be a manifold surface");
  auto runs_forward = [&](int f, int a, int b) {  // does triangle f traverse a -> b?
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles(f, k) == a && mesh.triangles(f, (k + 1) % 3) == b) return true;
    return false;
  };
  std::vector<int> flip(nf, -1);  // -1 unvisited, 0 keep, 1 flip
  int flipped = 0;
  for (int seed = 0; seed < nf; ++seed) {
    if (flip[seed] != -1) continue;
    flip[seed] = 0;
    std::queue<int> todo;
    todo.push(seed);
    while (!todo.empty()) {
      const int f = todo.front();
      todo.pop();
      for (int k = 0; k < 3; ++k) {
        int a = mesh.triangles(f, k), b = mesh.triangles(f, (k + 1) % 3);
        if (flip[f]) std::swap(a, b);  // f's direction along the edge after its own flip
        for (int g : edge_faces[{std::min(a, b), std::max(a, b)}]) {
          if (g == f) continue;
          const int needed = runs_forward(g, a, b) ? 1 : 0;  // g must run b -> a
          if (flip[g] == -1) {
            flip[g] = needed;
            flipped += needed;
            todo.push(g);
          } else if (flip[g] != needed) {
            throw Error(name + ": the surface cannot be oriented consistently (a Moebius strip?) at edge (" +
                        std::to_string(a) + ", " + std::to_string(b) + ")");
          }
        }
      }
    }
  }
  for (int f = 0; f < nf; ++f)
    if (flip[f] == 1) std::swap(mesh.triangles(f, 1), mesh.triangles(f, 2));
  if (flipped && warnings)
    warnings->push_back(name + ": " + std::to_string(flipped) +
                        " triangles flipped to agree with their neighbours' orientation");
}

TriangleMesh read_triangle_mesh(const std::string& path, std::vector<std::string>* warnings) {
  require_readable(path);
  const std::string ext = extension_of(path);
  TriangleMesh mesh;
  if (ext == ".vtp") {
    auto reader = Ptr<vtkXMLPolyDataReader>::New();
    if (!reader->CanReadFile(path.c_str())) throw Error(path + ": not a VTK XML polydata (.vtp) file");
    reader->SetFileName(path.c_str());
    update_or_throw(reader.Get(), path, "triangle surface");
    mesh = from_polydata(reader->GetOutput(), path);
  } else if (ext == ".vtk") {
    auto reader = Ptr<vtkDataSetReader>::New();
    reader->SetFileName(path.c_str());
    reader->ReadAllScalarsOn();
    reader->ReadAllVectorsOn();
    update_or_throw(reader.Get(), path, "triangle surface");
    if (auto poly = vtkPolyData::SafeDownCast(reader->GetOutput()))
      mesh = from_polydata(poly, path);
    else if (auto grid = vtkUnstructuredGrid::SafeDownCast(reader->GetOutput()))
      mesh = from_grid(grid, path);
    else
      throw Error(path + ": legacy VTK file is neither POLYDATA nor UNSTRUCTURED_GRID");
  } else if (ext == ".stl") {
    auto reader = Ptr<vtkSTLReader>::New();
    reader->SetFileName(path.c_str());
    reader->MergingOn();
    update_or_throw(reader.Get(), path, "triangle surface");
    mesh = from_polydata(reader->GetOutput(), path);
  } else if (ext == ".obj") {
    auto reader = Ptr<vtkOBJReader>::New();
    reader->SetFileName(path.c_str());
    update_or_throw(reader.Get(), path, "triangle surface");
    mesh = from_polydata(reader->GetOutput(), path);
  } else if (ext == ".off") {
    mesh = read_off(path);
  } else {
    throw Error(path + ": unknown extension '" + ext + "' for a surface (expected .vtp, .vtk, .stl, .obj or .off)");
  }
  validate_triangle_mesh(mesh, path, warnings);
  return mesh;
}

void write_triangle_mesh(const TriangleMesh& mesh, const std::string& path) {
  if (extension_of(path) != ".vtp") throw Error(path + ": surfaces are written as .vtp");
  auto poly = Ptr<vtkPolyData>::New();
  poly->SetPoints(to_vtk(mesh.points));
  auto polys = Ptr<vtkCellArray>::New();
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const vtkIdType ids[3] = {mesh.triangles(f, 0), mesh.triangles(f, 1), mesh.triangles(f, 2)};
    polys->InsertNextCell(3, ids);
  }
  poly->SetPolys(polys);
  add_arrays(poly->GetPointData(), mesh.point_data, mesh.points.rows(), "point", path);
  add_arrays(poly->GetCellData(), mesh.cell_data, mesh.triangles.rows(), "cell", path);
  write_atomically(path, [&](const std::string& tmp) {
    auto writer = Ptr<vtkXMLPolyDataWriter>::New();
    writer->SetFileName(tmp.c_str());
    writer->SetInputData(poly);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetCompressorTypeToZLib();
    writer->SetCompressionLevel(1);
    if (writer->Write() != 1) throw Error(path + ": cannot write (disk full or no permission?)");
  });
}

}  // namespace xfem
