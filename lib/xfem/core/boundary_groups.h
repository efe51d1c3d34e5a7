// SPDX-License-Identifier: MIT
#pragma once
#include <array>
#include <map>
#include <string>
#include <vector>

#include "xfem/core/mesh.h"

namespace xfem {

/// Named boundary sets (gmsh physical groups, or triangles named by a VTK cell array) travel with
/// a volume mesh as Int32 point arrays `group_<name>`: 1 on member nodes, 0 elsewhere
/// (docs/FORMATS.md "Named boundary groups"). Every stage keeps point arrays it does not
/// understand, so the sets reach problem.json's {"group": "NAME"} selector unchanged.
std::string group_array_name(const std::string& group);

/// The group names of `mesh` (its point arrays `group_<name>`, without the prefix), sorted.
std::vector<std::string> group_names(const TetMesh& mesh);

/// A volume mesh as a mesher writes it: tets beside lower-dimensional cells.
struct MixedMesh {
  Points points;
  std::vector<std::array<int, 4>> tets;          ///< rows of `points`
  std::vector<long> tet_cells;                   ///< per tet: its row in `cell_data` (all cells)
  DataArrays point_data, cell_data, field_data;  ///< as read; cell_data has one tuple per input cell
  std::map<std::string, std::vector<int>> groups;  ///< group name -> member nodes (rows of `points`)
};

/// The tets of `mixed` as the body: points used by no tet are dropped (a mesher's geometry
/// points and surface-only nodes would otherwise be DOFs without stiffness), the rest keep their
/// order; point arrays follow the points, cell arrays keep the tets' rows; each group becomes an
/// Int32 point array group_<name>. Throws xfem::Error "<name>: ..." when there is no tet, or a
/// group name would collide with an existing point array. Not validated (validate_tet_mesh).
TetMesh body_of(const MixedMesh& mixed, const std::string& name);

}  // namespace xfem
