// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

#include "xfem/core/mesh.h"

namespace xfem {

/// Reads a gmsh mesh (.msh, MSH 2.x or 4.1, ASCII or binary) with gmsh's own library, after
/// check_gmsh_elements (gmsh_check.h) has checked its element sections.
/// The linear tetrahedra are the body (points in no tet are dropped); every physical group of
/// dimension 0, 1 or 2 (points, curves, surfaces) becomes the point array group_<name> (Int32,
/// 1 on its nodes; an unnamed group is named by its tag), see boundary_groups.h. Physical
/// volumes select nothing, the body is every tet in the file, but they are its regions
/// (core/regions.h): a tet's region is the tag of its physical volume (0 in none), a volume's
/// name the region's name; a tet in two physical volumes is an error. The mesh is validated as
/// read_tet_mesh does. Throws xfem::Error "<path>: ..." for an unreadable file (gmsh's own
/// message), a file check_gmsh_elements refuses (an entity mixing orders of one shape, ...), no
/// tets, or 3D elements other than linear tets (hexahedra, second order, ...).
TetMesh read_gmsh_tet_mesh(const std::string& path, std::vector<std::string>* warnings = nullptr);

/// Reads the linear triangles of a .msh file as a surface (a cut, or a boundary to mesh inside),
/// validated as read_triangle_mesh does. Throws xfem::Error "<path>: ..." when it has none.
TriangleMesh read_gmsh_triangle_mesh(const std::string& path, std::vector<std::string>* warnings = nullptr);

}  // namespace xfem
