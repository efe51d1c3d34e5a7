// SPDX-License-Identifier: MIT
#pragma once
#include <string>
#include <vector>

#include "xfem/core/mesh.h"

namespace xfem {

/// Regions of a tet mesh (several materials, image labels, gmsh physical volumes): each tet's
/// region id is the Int32 cell array "region"; names are TetMesh::region_names. A mesh without
/// the array is one region, 0 (docs/FORMATS.md "Regions").
extern const char* const region_array_name;  ///< "region"

/// The largest region id a file may hold (ids are Int32, non-negative).
constexpr long max_region_id = 2147483647L;

/// Each tet's region: the cell array "region", or all 0 when the mesh has none.
std::vector<int> tet_regions(const TetMesh& mesh);

/// Sets each tet's region (one per tet) as the Int32 cell array "region".
void set_tet_regions(TetMesh& mesh, const std::vector<int>& regions);

/// The distinct regions of the tets, ascending ({0} for a mesh without regions).
std::vector<int> region_ids(const TetMesh& mesh);

/// The mesh's regions for a message: "1 'liver', 2 'tumour', 3" (the tets' regions with their
/// names, then named regions no tet has).
std::string region_list(const TetMesh& mesh);

/// Gives the tets of `to`, each lying in the tet parent[t] of `from` (a split or refined mesh),
/// their parent's region and `from`'s region names. Nothing when `from` has no regions.
void inherit_regions(const TetMesh& from, const std::vector<int>& parent, TetMesh& to);

/// Checks the regions of `mesh` (read from `name`): the cell array "region", if present, has one
/// integer component per tet with values in [0, max_region_id], and is of an integer type; names
/// are non-empty, printable, at most 200 characters, unique, for ids in [0, max_region_id].
/// Throws xfem::Error "<name>: ..." naming the first problem.
void validate_regions(const TetMesh& mesh, const std::string& name);

}  // namespace xfem
