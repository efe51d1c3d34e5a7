// SPDX-License-Identifier: MIT
// gmsh meshes (.msh 2.2 and 4.1) and mixed-cell VTK meshes: tets as the body, physical groups or
// cell-array groups as point sets, and the {"group": ...} selector of problem.json.
#include "xfem/io/gmsh_io.h"

#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "xfem/core/boundary_groups.h"
#include "xfem/core/error.h"
#include "xfem/core/regions.h"
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
  CHECK_THROWS_WITH(xfem::read_tet_mesh(truncated),  // the $Nodes check reads it first
                    Contains(truncated + ": the smallest node tag in the $Nodes section is not a whole number"));
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

namespace {

// Nodes 1..35 (1-4 the unit tet's corners, the others anywhere: gmsh does not check where a
// high-order node lies), as MSH 2.2 or MSH 4.1 text.
Eigen::Vector3d node(int k) {
  if (k <= 4) return k == 1 ? Eigen::Vector3d(0, 0, 0) : Eigen::Vector3d::Unit(k - 2);
  return Eigen::Vector3d(0.01 * k, 0.02 * k, 0.005 * k);
}

// The node list of an element of n nodes: the unit tet's or triangle's corners first.
std::string nodes_of(int n) {
  std::string s;
  for (int k = 1; k <= n; ++k) s += " " + std::to_string(k);
  return s;
}

// One linear element (gmsh type `linear`, `corners` nodes) and, in the same entity 1, one of
// `type` with `n` nodes (type 0: none); MSH 2.2 ASCII.
std::string msh22(int linear, int corners, int type, int n) {
  std::string s = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n35\n";
  for (int k = 1; k <= 35; ++k) {
    const Eigen::Vector3d x = node(k);
    s += std::to_string(k) + " " + std::to_string(x.x()) + " " + std::to_string(x.y()) + " " + std::to_string(x.z()) + "\n";
  }
  s += "$EndNodes\n$Elements\n" + std::string(type ? "2" : "1") + "\n";
  s += "1 " + std::to_string(linear) + " 2 0 1" + nodes_of(corners) + "\n";
  if (type) s += "2 " + std::to_string(type) + " 2 0 1" + nodes_of(n) + "\n";
  return s + "$EndElements\n";
}

// The same in MSH 4.1 ASCII: entity (dim, 1) holds a block of the linear element and a block of `type`.
std::string msh41(int dim, int linear, int corners, int type, int n) {
  std::string s = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 " + std::string(dim == 2 ? "1 0" : "0 1") +
                  "\n1 0 0 0 1 1 1 0 0\n$EndEntities\n$Nodes\n1 35 1 35\n" + std::to_string(dim) + " 1 0 35\n";
  for (int k = 1; k <= 35; ++k) s += std::to_string(k) + "\n";
  for (int k = 1; k <= 35; ++k) {
    const Eigen::Vector3d x = node(k);
    s += std::to_string(x.x()) + " " + std::to_string(x.y()) + " " + std::to_string(x.z()) + "\n";
  }
  s += "$EndNodes\n$Elements\n" + std::string(type ? "2 2 1 2\n" : "1 1 1 1\n");
  s += std::to_string(dim) + " 1 " + std::to_string(linear) + " 1\n1" + nodes_of(corners) + "\n";
  if (type) s += std::to_string(dim) + " 1 " + std::to_string(type) + " 1\n2" + nodes_of(n) + "\n";
  return s + "$EndElements\n";
}

}  // namespace

TEST_CASE("gmsh: an entity mixing orders of one shape is one error line and never a crash", "[gmsh]") {
  // gmsh's library reads every tet of an entity as the first one's type: a 10-node tet after a
  // 4-node one in the same volume made it write out of bounds (SIGABRT in every mesh reader).
  struct Case {
    int type, nodes;
    const char* name;
  };
  for (const Case& c : {Case{11, 10, "Tetrahedron 10"}, Case{29, 20, "Tetrahedron 20"}, Case{30, 35, "Tetrahedron 35"}}) {
    INFO(c.name);
    const std::string v22 = scratch("mixed22_" + std::to_string(c.type) + ".msh"),
                      v41 = scratch("mixed41_" + std::to_string(c.type) + ".msh");
    write_text(v22, msh22(4, 4, c.type, c.nodes));
    write_text(v41, msh41(3, 4, 4, c.type, c.nodes));
    const std::string mixes = ": entity 1 of dimension 3 mixes Tetrahedron 4 (gmsh element type 4) and " +
                              std::string(c.name) + " (gmsh element type " + std::to_string(c.type) + ") elements";
    CHECK_THROWS_WITH(xfem::read_tet_mesh(v22), Contains(v22 + mixes));
    CHECK_THROWS_WITH(xfem::read_tet_mesh(v41), Contains(v41 + mixes));
    CHECK_THROWS_WITH(xfem::read_triangle_mesh(v22), Contains(v22 + mixes));  // the cut reader checks too
  }
  // A 6-node triangle among a cut's 3-node triangles.
  const std::string t22 = scratch("mixed_tri22.msh"), t41 = scratch("mixed_tri41.msh");
  write_text(t22, msh22(2, 3, 9, 6));
  write_text(t41, msh41(2, 2, 3, 9, 6));
  const std::string mixes = ": entity 1 of dimension 2 mixes Triangle 3 (gmsh element type 2) and Triangle 6 (gmsh "
                            "element type 9) elements";
  CHECK_THROWS_WITH(xfem::read_triangle_mesh(t22), Contains(t22 + mixes));
  CHECK_THROWS_WITH(xfem::read_triangle_mesh(t41), Contains(t41 + mixes));
  CHECK_THROWS_WITH(xfem::read_tet_mesh(t41), Contains(t41 + mixes));

  // The linear elements alone still read: one tet of volume 1/6, one triangle.
  const std::string l22 = scratch("linear22.msh"), l41 = scratch("linear41.msh"), s22 = scratch("tri22.msh");
  write_text(l22, msh22(4, 4, 0, 0));
  write_text(l41, msh41(3, 4, 4, 0, 0));
  write_text(s22, msh22(2, 3, 0, 0));
  for (const std::string& f : {l22, l41}) {
    INFO(f);
    const xfem::TetMesh m = xfem::read_tet_mesh(f);
    REQUIRE(m.tets.rows() == 1);
    CHECK(m.points.rows() == 4);
    CHECK(volume(m) == Approx(1.0 / 6).epsilon(1e-12));
  }
  const xfem::TriangleMesh s = xfem::read_triangle_mesh(s22);
  CHECK(s.triangles.rows() == 1);
  CHECK(s.points.rows() == 3);
  // One order per entity is what gmsh reads: a 10-node tet in an entity of its own reaches the
  // documented refusal of second-order meshes.
  std::string own = msh22(4, 4, 11, 10);
  own.replace(own.find("2 11 2 0 1"), 10, "2 11 2 0 2");
  const std::string separate = scratch("separate.msh");
  write_text(separate, own);
  CHECK_THROWS_WITH(xfem::read_tet_mesh(separate),
                    Contains(separate + ": the mesh has Tetrahedron 10 (gmsh element type 11) elements; only linear"));
}

namespace {

/// The error reading `text` as the file `name` gives, or "read" when it is read.
std::string refused(const std::string& name, const std::string& text) {
  const std::string path = scratch(name);
  write_text(path, text);
  try {
    xfem::read_tet_mesh(path);
  } catch (const xfem::Error& e) {
    return std::string(e.what());
  }
  return std::string("read");
}

}  // namespace

TEST_CASE("gmsh: the element sections are checked before gmsh reads them", "[gmsh]") {
  std::string text = msh22(4, 4, 0, 0);
  text.replace(text.find("1 4 2 0 1"), 9, "1 999 2 0 1");
  CHECK(refused("type999.msh", text) == scratch("type999.msh") + ": element type 999 is not a gmsh element type");
  text = msh41(3, 4, 4, 0, 0);
  text.replace(text.find("3 1 4 1\n"), 8, "2 1 4 1\n");
  CHECK(refused("dim.msh", text) ==
        scratch("dim.msh") + ": entity 1 of dimension 2 holds Tetrahedron 4 (gmsh element type 4) elements, of dimension 3");
  text = msh22(4, 4, 0, 0);
  text.replace(text.find("2.2 0 8"), 7, "3.0 0 8");
  CHECK(refused("v3.msh", text) ==
        scratch("v3.msh") + ": MSH version '3.0' is not read (save as MSH 4.1 or 2.2: gmsh -format msh41)");
  text = msh22(4, 4, 0, 0);
  text.replace(text.find("1 4 2 0 1 1 2 3 4"), 17, "1 4 2 0 1 1 2 3");  // an element one node short
  CHECK(refused("short.msh", text) == scratch("short.msh") +
                                          ": an element's node in the $Elements section is not a whole number of at "
                                          "most 17 digits (or the file ends there)");
  text = msh41(3, 4, 4, 0, 0);
  text.replace(text.find("1 1 1 1\n"), 8, "1 99999999999999999999 1 1\n");
  CHECK(refused("huge.msh", text) == scratch("huge.msh") +
                                         ": the element count or tags in the $Elements section is not a whole number of "
                                         "at most 17 digits (or the file ends there)");
}

namespace {

// Bytes of a binary .msh file, in this machine's byte order (as gmsh writes them).
struct Bytes {
  std::string s;
  template <class T>
  Bytes& put(T v) {
    s.append(reinterpret_cast<const char*>(&v), sizeof v);
    return *this;
  }
  Bytes& text(const std::string& t) {
    s += t;
    return *this;
  }
};

// msh22 and msh41 (a tet mesh) as binary files: a linear tet and, in the same entity, one of
// `type` (0: none).
std::string msh22_binary(int type, int n) {
  Bytes b;
  b.text("$MeshFormat\n2.2 1 8\n").put<std::int32_t>(1).text("\n$EndMeshFormat\n$Nodes\n35\n");
  for (int k = 1; k <= 35; ++k) b.put<std::int32_t>(k).put(node(k).x()).put(node(k).y()).put(node(k).z());
  b.text("\n$EndNodes\n$Elements\n" + std::string(type ? "2" : "1") + "\n");
  b.put<std::int32_t>(4).put<std::int32_t>(1).put<std::int32_t>(2).put<std::int32_t>(1).put<std::int32_t>(0).put<std::int32_t>(1);
  for (int k = 1; k <= 4; ++k) b.put<std::int32_t>(k);
  if (type) {
    b.put<std::int32_t>(type).put<std::int32_t>(1).put<std::int32_t>(2).put<std::int32_t>(2).put<std::int32_t>(0).put<std::int32_t>(1);
    for (int k = 1; k <= n; ++k) b.put<std::int32_t>(k);
  }
  return b.text("\n$EndElements\n").s;
}

std::string msh41_binary(int type, int n) {
  Bytes b;
  b.text("$MeshFormat\n4.1 1 8\n").put<std::int32_t>(1).text("\n$EndMeshFormat\n$Entities\n");
  b.put<std::size_t>(0).put<std::size_t>(0).put<std::size_t>(0).put<std::size_t>(1).put<std::int32_t>(1);
  for (double v : {0, 0, 0, 1, 1, 1}) b.put(v);
  b.put<std::size_t>(0).put<std::size_t>(0).text("\n$EndEntities\n$Nodes\n");
  b.put<std::size_t>(1).put<std::size_t>(35).put<std::size_t>(1).put<std::size_t>(35);
  b.put<std::int32_t>(3).put<std::int32_t>(1).put<std::int32_t>(0).put<std::size_t>(35);
  for (std::size_t k = 1; k <= 35; ++k) b.put(k);
  for (int k = 1; k <= 35; ++k) b.put(node(k).x()).put(node(k).y()).put(node(k).z());
  const std::size_t blocks = type ? 2 : 1;
  b.text("\n$EndNodes\n$Elements\n").put(blocks).put(blocks).put<std::size_t>(1).put(blocks);
  b.put<std::int32_t>(3).put<std::int32_t>(1).put<std::int32_t>(4).put<std::size_t>(1).put<std::size_t>(1);
  for (std::size_t k = 1; k <= 4; ++k) b.put(k);
  if (type) {
    b.put<std::int32_t>(3).put<std::int32_t>(1).put<std::int32_t>(type).put<std::size_t>(1).put<std::size_t>(2);
    for (std::size_t k = 1; k <= static_cast<std::size_t>(n); ++k) b.put(k);
  }
  return b.text("\n$EndElements\n").s;
}

}  // namespace

TEST_CASE("gmsh: binary files are checked as the ASCII ones", "[gmsh]") {
  // gmsh's binary export of the test cubes (gmsh cube41.msh -save -format msh41 -bin) reads as the ASCII files.
  for (const char* v : {"22", "41"}) {
    INFO(v);
    const xfem::TetMesh ascii = xfem::read_tet_mesh(data + "cube" + v + ".msh");
    const xfem::TetMesh binary = xfem::read_tet_mesh(data + "cube" + v + "_bin.msh");
    CHECK(binary.points == ascii.points);
    CHECK(binary.tets == ascii.tets);
    CHECK(xfem::group_names(binary) == xfem::group_names(ascii));
  }
  const std::string b22 = scratch("mixed22_bin.msh"), b41 = scratch("mixed41_bin.msh");
  write_text(b22, msh22_binary(11, 10));
  write_text(b41, msh41_binary(11, 10));
  const std::string mixes =
      ": entity 1 of dimension 3 mixes Tetrahedron 4 (gmsh element type 4) and Tetrahedron 10 (gmsh element type 11) elements";
  CHECK_THROWS_WITH(xfem::read_tet_mesh(b22), Contains(b22 + mixes));
  CHECK_THROWS_WITH(xfem::read_tet_mesh(b41), Contains(b41 + mixes));
  // The same writers with one order read (the tet and its 35 nodes, 31 of them unused and dropped).
  write_text(b22, msh22_binary(0, 0));
  write_text(b41, msh41_binary(0, 0));
  CHECK(volume(xfem::read_tet_mesh(b22)) == Approx(1.0 / 6).epsilon(1e-12));
  CHECK(volume(xfem::read_tet_mesh(b41)) == Approx(1.0 / 6).epsilon(1e-12));
  // Cut short inside its element (5 size_t: the tag and 4 nodes).
  const std::string whole = msh41_binary(0, 0);
  write_text(b41, whole.substr(0, whole.find("$EndElements") - 40));
  CHECK_THROWS_WITH(xfem::read_tet_mesh(b41), Contains(b41 + ": the file ends inside its binary $Elements section"));
}

namespace {
// Three tets in MSH 2.2: the first in physical volume 4 "liver", the second in 9 "tumour", the
// third (elementary entity 3) in none; `elements` replaces the element section to vary that.
std::string three_tets(const std::string& elements, bool names = true) {
  return std::string("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n") +
         (names ? "$PhysicalNames\n2\n3 4 \"liver\"\n3 9 \"tumour\"\n$EndPhysicalNames\n" : "") +
         "$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n6 2 2 2\n$EndNodes\n$Elements\n" +
         elements + "$EndElements\n";
}
// msh41_binary(0, 0) with the std::size_t at byte `offset` after "$Nodes\n" (or after
// "$Elements\n") replaced by `value`.
std::string patched_msh41(const char* section, std::size_t offset, std::size_t value) {
  std::string s = msh41_binary(0, 0);
  const std::size_t at = s.find(section) + std::strlen(section) + offset;
  std::memcpy(&s[at], &value, sizeof value);
  return s;
}


}  // namespace

TEST_CASE("gmsh: physical volumes are the regions, with their names", "[gmsh][regions]") {
  const std::string path = scratch("regions.msh");
  write_text(path, three_tets("3\n1 4 2 4 1 1 2 3 4\n2 4 2 9 2 2 3 4 5\n3 4 2 0 3 2 3 5 6\n"));
  const xfem::TetMesh m = xfem::read_tet_mesh(path);
  REQUIRE(m.tets.rows() == 3);
  // Each tet by its points, whatever order gmsh lists them in.
  for (int t = 0; t < 3; ++t) {
    const double x = m.points.row(m.tets(t, 0)).sum() + m.points.row(m.tets(t, 1)).sum() +
                     m.points.row(m.tets(t, 2)).sum() + m.points.row(m.tets(t, 3)).sum();
    const int expected = x == 3.0 ? 4 : x == 6.0 ? 9 : 0;  // coordinate sums 3, 6, 11
    INFO("tet " << t << " coordinate sum " << x);
    CHECK(xfem::tet_regions(m)[t] == expected);
  }
  CHECK(m.region_names == std::map<int, std::string>{{4, "liver"}, {9, "tumour"}});
  // Through a .vtu, as xfem-classify and xfem-enrich pass it on.
  const std::string vtu = scratch("regions.vtu");
  xfem::write_tet_mesh(m, vtu);
  const xfem::TetMesh back = xfem::read_tet_mesh(vtu);
  CHECK(xfem::tet_regions(back) == xfem::tet_regions(m));
  CHECK(back.region_names == m.region_names);

  // The project's cube: one physical volume "body" (tag 1) holds every tet.
  const xfem::TetMesh cube = xfem::read_tet_mesh(data + "cube41.msh");
  CHECK(xfem::region_ids(cube) == std::vector<int>{1});
  CHECK(cube.region_names == std::map<int, std::string>{{1, "body"}});
}

TEST_CASE("gmsh: a mesh without physical volumes has no regions; a tet in two is an error", "[gmsh][regions]") {
  const std::string plain = scratch("plain.msh"), twice = scratch("twice.msh");
  write_text(plain, three_tets("2\n1 4 2 0 1 1 2 3 4\n2 4 2 0 2 2 3 4 5\n", false));
  const xfem::TetMesh m = xfem::read_tet_mesh(plain);
  CHECK(m.cell_data.count("region") == 0);
  CHECK(xfem::region_ids(m) == std::vector<int>{0});
  // Elementary entity 1 is listed in the physical volumes 4 and 9: its tets would have two materials.
  write_text(twice, three_tets("2\n1 4 2 4 1 1 2 3 4\n2 4 2 9 1 2 3 4 5\n"));
  CHECK_THROWS_WITH(xfem::read_tet_mesh(twice), Contains(twice + ": tetrahedron ") &&
                                                    Contains(" is in the physical volumes 4 and 9 (one region per tet)"));
}

TEST_CASE("gmsh: the $Nodes section is checked before gmsh reads it", "[gmsh]") {
  // $Nodes of MSH 4.1 binary: 4 size_t (blocks, nodes, min tag, max tag), then a block: 3 int32
  // (dim, entity, parametric) and a size_t (count), its 35 tags (size_t), their coordinates.
  const std::size_t first_tag = 4 * 8 + 3 * 4 + 8;
  // A node tag beyond the header's largest: libgmsh wrote out of bounds (SIGSEGV).
  CHECK(refused("tag_high.msh", patched_msh41("$Nodes\n", first_tag + 34 * 8, 1000000)) ==
        scratch("tag_high.msh") + ": node tag 1000000 in the $Nodes section is outside the range 1 to 35 its header gives");
  CHECK(refused("tag_zero.msh", patched_msh41("$Nodes\n", first_tag, 0)) ==
        scratch("tag_zero.msh") + ": node tag 0 in the $Nodes section is outside the range 1 to 35 its header gives");
  CHECK(refused("tag_twice.msh", patched_msh41("$Nodes\n", first_tag + 8, 1)) ==
        scratch("tag_twice.msh") + ": node tag 1 is given twice in the $Nodes section");
  // Counts that disagree: the header's node count, the block's, the tag range.
  CHECK(refused("count.msh", patched_msh41("$Nodes\n", 8, 34)) ==
        scratch("count.msh") + ": the $Nodes section's header gives 34 nodes, its blocks hold at least 35");
  CHECK(refused("range.msh", patched_msh41("$Nodes\n", 24, 20)) ==
        scratch("range.msh") + ": the $Nodes section's header gives 35 nodes with tags 1 to 20");
  CHECK(refused("blocks.msh", patched_msh41("$Nodes\n", 0, std::size_t(1) << 60)) ==
        scratch("blocks.msh") + ": the file ends inside its binary $Nodes section (in the node blocks)");
  CHECK(refused("block.msh", patched_msh41("$Nodes\n", 4 * 8 + 3 * 4, std::size_t(1) << 60)) ==
        scratch("block.msh") + ": the $Nodes section's header gives 35 nodes, its blocks hold at least 1152921504606846976");
  const std::size_t fourth_node = 4 * 8 + 3 * 4 + 8 + 8 + 3 * 8;
  // An element naming a node the $Nodes section does not have.
  // $Elements: 4 size_t, then dim, entity, type (int32), count (size_t), then the element's tag and 4 nodes.
  CHECK(refused("element_node.msh", patched_msh41("$Elements\n", fourth_node, 36)) ==
        scratch("element_node.msh") + ": an element in the $Elements section has node 36, outside the node tags 1 to 35");
  // Element node tags that libgmsh turns into negative ints crashed it (SIGSEGV), one above 2^32
  // read as node 1.
  for (const std::size_t tag : {std::size_t(2147483651u), ~std::size_t(0), (std::size_t(1) << 32) + 1}) {
    INFO(tag);
    CHECK(refused("element_huge.msh", patched_msh41("$Elements\n", fourth_node, tag)) ==
          scratch("element_huge.msh") + ": an element in the $Elements section has node " + std::to_string(tag) +
              ", outside the node tags 1 to 35");
  }
  // A node tag above 2^32 (read as its low 32 bits) is out of the header's range.
  CHECK(refused("tag_wrap.msh", patched_msh41("$Nodes\n", first_tag, (std::size_t(1) << 32) + 1)) ==
        scratch("tag_wrap.msh") + ": node tag 4294967297 in the $Nodes section is outside the range 1 to 35 its header gives");
  // The file as written still reads.
  CHECK(refused("whole.msh", msh41_binary(0, 0)) == "read");
}

TEST_CASE("gmsh: MSH 2 node tags that gmsh's int cannot hold are refused", "[gmsh]") {
  // libgmsh read 2^32 + 1 as node 1: the mesh read without a word, wrong.
  std::string text = msh22(4, 4, 0, 0);
  text.replace(text.find("1 4 2 0 1 1 2 3 4"), 17, "1 4 2 0 1 1 2 3 4294967300");
  CHECK(refused("element_wrap.msh", text) == scratch("element_wrap.msh") +
                                                 ": an element in the $Elements section has node 4294967300, outside "
                                                 "gmsh's node tags 1 to 2147483647");
  text = msh22(4, 4, 0, 0);
  text.replace(text.find("\n4 "), 3, "\n4294967300 ");
  CHECK(refused("node_wrap.msh", text) == scratch("node_wrap.msh") +
                                              ": the $Nodes section has node tag 4294967300, outside gmsh's node tags 1 "
                                              "to 2147483647");
  text = msh22(4, 4, 0, 0);
  text.replace(text.find("\n35 "), 4, "\n0 ");
  CHECK(refused("node_zero.msh", text) ==
        scratch("node_zero.msh") + ": the $Nodes section has node tag 0, outside gmsh's node tags 1 to 2147483647");
  CHECK(refused("whole22.msh", msh22(4, 4, 0, 0)) == "read");
}
