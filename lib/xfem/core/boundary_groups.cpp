// SPDX-License-Identifier: MIT
#include "xfem/core/boundary_groups.h"

#include <algorithm>

#include "xfem/core/error.h"

namespace xfem {
namespace {
const std::string prefix = "group_";
}

std::string group_array_name(const std::string& group) { return prefix + group; }

std::vector<std::string> group_names(const TetMesh& mesh) {
  std::vector<std::string> names;
  for (const auto& [array, values] : mesh.point_data)
    if (array.size() > prefix.size() && array.compare(0, prefix.size(), prefix) == 0)
      names.push_back(array.substr(prefix.size()));
  return names;  // std::map keeps them sorted
}

TetMesh body_of(const MixedMesh& mixed, const std::string& name) {
  if (mixed.tets.empty())
    throw Error(name + ": no tetrahedra (" + std::to_string(mixed.points.rows()) +
                " points); a volume mesh needs a 3D mesh (gmsh -3)");
  const Eigen::Index np = mixed.points.rows();
  std::vector<int> new_id(np, -1);
  for (const auto& tet : mixed.tets)
    for (int v : tet) {
      if (v < 0 || v >= np)
        throw Error(name + ": a tetrahedron uses point " + std::to_string(v) + ", out of range [0, " +
                    std::to_string(np) + ")");
      new_id[v] = 0;
    }
  std::vector<int> kept;
  for (Eigen::Index i = 0; i < np; ++i)
    if (new_id[i] == 0) {
      new_id[i] = static_cast<int>(kept.size());
      kept.push_back(static_cast<int>(i));
    }

  TetMesh mesh;
  mesh.points.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (std::size_t i = 0; i < kept.size(); ++i) mesh.points.row(i) = mixed.points.row(kept[i]);
  mesh.tets.resize(static_cast<Eigen::Index>(mixed.tets.size()), 4);
  for (std::size_t t = 0; t < mixed.tets.size(); ++t)
    for (int k = 0; k < 4; ++k) mesh.tets(t, k) = new_id[mixed.tets[t][k]];

  auto pick = [](const DataArray& a, const std::vector<long>& rows) {
    DataArray out = a;
    out.values.clear();
    for (long r : rows)
      for (int c = 0; c < a.components; ++c) out.values.push_back(a(static_cast<std::size_t>(r), c));
    return out;
  };
  const std::vector<long> kept_rows(kept.begin(), kept.end());
  for (const auto& [array, values] : mixed.point_data)
    if (values.tuples() == static_cast<std::size_t>(np)) mesh.point_data[array] = pick(values, kept_rows);
  long last_cell = -1;
  for (long r : mixed.tet_cells) last_cell = std::max(last_cell, r);
  for (const auto& [array, values] : mixed.cell_data)
    if (static_cast<long>(values.tuples()) > last_cell) mesh.cell_data[array] = pick(values, mixed.tet_cells);
  mesh.field_data = mixed.field_data;

  for (const auto& [group, nodes] : mixed.groups) {
    const std::string array = group_array_name(group);
    if (mesh.point_data.count(array))
      throw Error(name + ": group '" + group + "' would overwrite the point array '" + array + "' of the file");
    DataArray flag = make_array(DataArray::Type::Int32, 1, kept.size(), 0.0);
    for (int v : nodes)
      if (v >= 0 && v < np && new_id[v] >= 0) flag.values[new_id[v]] = 1.0;
    mesh.point_data[array] = std::move(flag);
  }
  return mesh;
}

}  // namespace xfem
