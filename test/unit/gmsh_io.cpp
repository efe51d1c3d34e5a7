// SPDX-License-Identifier: MIT
// gmsh meshes (.msh 2.2 and 4.1) and mixed-cell VTK meshes: tets as the body, physical groups or
// cell-array groups as point sets, and the {"group": ...} selector of problem.json.
#include "xfem/io/gmsh_io.h"

#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "xfem/core/boundary_groups.h"
#include "xfem/core/error.h"
#include "xfem/system/problem.h"
#include "xfem/io/vtk_io.h"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

namespace {

const std::string data = std::string(XFEM_TEST_DATA) + "/gmsh/";

std::string scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("xfem_unit_gmsh_io_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return (dir / name).string();
}

void write_text(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

double volume(const xfem::TetMesh& m) {
  double v = 0;
  for (int t = 0; t < m.tets.rows(); ++t) v += xfem::signed_volume(m, t);
  return v;
}

// The nodes of point array `array` set to 1, checked to be exactly the nodes where `on(x)` holds.
void require_group(const xfem::TetMesh& m, const std::string& group, bool (*on)(const Eigen::Vector3d&)) {
  const auto& a = m.point_data.at(xfem::group_array_name(group));
  REQUIRE(a.type == xfem::DataArray::Type::Int32);
  REQUIRE(a.tuples() == static_cast<std::size_t>(m.points.rows()));
  int members = 0;
  for (int k = 0; k < m.points.rows(); ++k) {
    const Eigen::Vector3d x = m.points.row(k).transpose();
    INFO(group << " node " << k << " at " << x.transpose());
    REQUIRE((a(k) == 1.0) == on(x));
    members += a(k) == 1.0;
  }
  REQUIRE(members > 0);
}

bool bottom(const Eigen::Vector3d& x) { return x.z() == 0.0; }
bool top(const Eigen::Vector3d& x) { return x.z() == 1.0; }
bool top_edge(const Eigen::Vector3d& x) { return x.z() == 1.0 && x.x() == 0.0; }
bool corner(const Eigen::Vector3d& x) { return x == Eigen::Vector3d(1, 1, 1); }

}  // namespace

TEST_CASE("gmsh: MSH 2.2 and 4.1 give the same body and the physical groups as point sets", "[gmsh]") {
  for (const char* file : {"cube22.msh", "cube41.msh"}) {
    INFO(file);
    std::vector<std::string> warnings;
    const xfem::TetMesh m = xfem::read_tet_mesh(data + file, &warnings);  // dispatches on .msh
    CHECK(warnings.empty());
    REQUIRE(m.tets.rows() > 20);
    CHECK(volume(m) == Approx(1.0).epsilon(1e-12));
    // Every point belongs to a tet: a mesher's unused nodes would be DOFs without stiffness.
    std::vector<int> used(m.points.rows(), 0);
    for (int t = 0; t < m.tets.rows(); ++t)
      for (int k = 0; k < 4; ++k) used[m.tets(t, k)] = 1;
    CHECK(std::count(used.begin(), used.end(), 0) == 0);
    CHECK(xfem::group_names(m) == std::vector<std::string>{"7", "bottom", "top", "top edge x=0"});
    require_group(m, "bottom", bottom);
    require_group(m, "top", top);
    require_group(m, "top edge x=0", top_edge);
    require_group(m, "7", corner);  // an unnamed physical group is named by its tag
  }
  const xfem::TetMesh a = xfem::read_gmsh_tet_mesh(data + "cube22.msh");
  const xfem::TetMesh b = xfem::read_gmsh_tet_mesh(data + "cube41.msh");
  CHECK(a.points.rows() == b.points.rows());  // the formats list the nodes in different orders
  CHECK(a.tets.rows() == b.tets.rows());
}

TEST_CASE("gmsh: groups survive a .vtu round trip and select nodes in problem.json", "[gmsh]") {
  const xfem::TetMesh m = xfem::read_tet_mesh(data + "cube41.msh");
  const std::string vtu = scratch("cube.vtu");
  xfem::write_tet_mesh(m, vtu);
  const xfem::TetMesh back = xfem::read_tet_mesh(vtu);
  REQUIRE(back.point_data.at("group_top").values == m.point_data.at("group_top").values);

  const xfem::Json j = xfem::Json::parse(R"({"material": {"E": 1, "nu": 0.3},
      "dirichlet": [{"selector": {"group": "bottom"}, "value": [0, 0, 0]}],
      "neumann": [{"selector": {"group": "top"}, "traction": [0, 0, 1]}]})");
  const xfem::Problem p = xfem::parse_problem(j, "problem.json");
  REQUIRE(p.dirichlet[0].selector.kind == xfem::Selector::Kind::Group);
  for (int k : xfem::select_nodes(p.dirichlet[0].selector, back, "d")) CHECK(back.points(k, 2) == 0.0);
  for (int k : xfem::select_nodes(p.neumann[0].selector, back, "n")) CHECK(back.points(k, 2) == 1.0);

  xfem::Selector unknown;
  unknown.kind = xfem::Selector::Kind::Group;
  unknown.array = "lid";
  CHECK_THROWS_WITH(xfem::select_nodes(unknown, back, "problem.json: dirichlet[0]"),
                    "problem.json: dirichlet[0]: the mesh has no group 'lid' (its groups: '7', 'bottom', 'top', "
                    "'top edge x=0')");
  xfem::TetMesh plain = back;
  plain.point_data.clear();
  CHECK_THROWS_WITH(xfem::select_nodes(unknown, plain, "d"), Contains("the mesh has no group 'lid' (it has no groups"));
  CHECK_THROWS_WITH(xfem::parse_problem(xfem::Json::parse(R"({"material": {"E": 1, "nu": 0.3},
      "dirichlet": [{"selector": {"group": 3}, "value": [0, 0, 0]}]})"), "p.json"),
                    "p.json: dirichlet[0].selector.group must be a string");
}

TEST_CASE("gmsh: a .msh surface reads its triangles as a cut", "[gmsh]") {
  const xfem::TriangleMesh s = xfem::read_triangle_mesh(data + "square41.msh");
  double area = 0;
  for (int f = 0; f < s.triangles.rows(); ++f) {
    const Eigen::Vector3d a = s.points.row(s.triangles(f, 0)), b = s.points.row(s.triangles(f, 1)),
                          c = s.points.row(s.triangles(f, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
    CHECK(a.z() == 0.5);
  }
  CHECK(area == Approx(1.0).epsilon(1e-12));
  // The triangles of a volume mesh are its boundary surface.
  const xfem::TriangleMesh boundary = xfem::read_triangle_mesh(data + "cube22.msh");
  CHECK(boundary.triangles.rows() > 12);
}

TEST_CASE("gmsh: bad .msh files give one error line naming the file", "[gmsh]") {
  const std::string garbage = scratch("garbage.msh"), truncated = scratch("truncated.msh"), hexes = scratch("hex.msh");
  write_text(garbage, "this is not a mesh\n");
  write_text(truncated, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2\n");
  // One hexahedron (gmsh type 5), MSH 2.2.
  write_text(hexes, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n"
                    "5 0 0 1\n6 1 0 1\n7 1 1 1\n8 0 1 1\n$EndNodes\n$Elements\n1\n1 5 2 0 1 1 2 3 4 5 6 7 8\n$EndElements\n");
  CHECK_THROWS_WITH(xfem::read_tet_mesh(garbage), Contains(garbage + ": cannot read the gmsh file: "));
  CHECK_THROWS_WITH(xfem::read_tet_mesh(truncated), Contains(truncated + ": cannot read the gmsh file"));
  CHECK_THROWS_WITH(xfem::read_tet_mesh(hexes), Contains(hexes + ": the mesh has Hexahedron 8 (gmsh element type 5)"));
  CHECK_THROWS_WITH(xfem::read_tet_mesh(scratch("missing.msh")), Contains("missing.msh: cannot open"));
  CHECK_THROWS_WITH(xfem::read_tet_mesh(data + "square41.msh"), Contains("square41.msh: no tetrahedra"));
  CHECK_THROWS_WITH(xfem::read_triangle_mesh(hexes), Contains(hexes + ": no triangles"));
}

TEST_CASE("gmsh: mixed-cell VTK meshes give their tets as the body, named triangles as groups", "[gmsh]") {
  // gmsh's own VTK export: vertices, lines, triangles and tets, no group names.
  const xfem::TetMesh exported = xfem::read_tet_mesh(data + "cube_gmsh.vtk");
  const xfem::TetMesh msh = xfem::read_tet_mesh(data + "cube41.msh");
  CHECK(exported.tets.rows() == msh.tets.rows());
  CHECK(volume(exported) == Approx(1.0).epsilon(1e-12));
  CHECK(xfem::group_names(exported).empty());

  // One tet, a vertex, a line and two triangles named by the "group" cell array; a point
  // used only by a triangle is dropped from the body.
  const std::string vtk = scratch("mixed.vtk");
  write_text(vtk, R"(# vtk DataFile Version 2.0
mixed
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 5 double
0 0 0  1 0 0  0 1 0  0 0 1  5 5 5
CELLS 5 18
1 0
2 0 1
4 0 1 2 3
3 0 1 2
3 1 2 4
CELL_TYPES 5
1 3 10 5 5
CELL_DATA 5
SCALARS group int 1
LOOKUP_TABLE default
0 0 0 2 8
SCALARS material double 1
LOOKUP_TABLE default
0 0 7.5 0 0
)");
  const xfem::TetMesh m = xfem::read_tet_mesh(vtk);
  REQUIRE(m.tets.rows() == 1);
  REQUIRE(m.points.rows() == 4);
  CHECK(m.cell_data.at("material").values == std::vector<double>{7.5});
  CHECK(m.cell_data.count("group") == 0);
  CHECK(m.point_data.at("group_2").values == std::vector<double>{1, 1, 1, 0});
  CHECK(m.point_data.at("group_8").values == std::vector<double>{0, 1, 1, 0});

  // A quad beside the tets is still refused, by name.
  const std::string quad = scratch("quad.vtk");
  write_text(quad, "# vtk DataFile Version 2.0\nq\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n"
                   "0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 3 12\n1 0\n4 0 1 2 3\n4 0 1 2 3\nCELL_TYPES 3\n1 10 9\n");
  CHECK_THROWS_WITH(xfem::read_tet_mesh(quad), Contains("cell 2 is a vtkQuad"));
}
