// SPDX-License-Identifier: MIT
#include "xfem/core/regions.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "xfem/core/error.h"

namespace xfem {

const char* const region_array_name = "region";

std::vector<int> tet_regions(const TetMesh& mesh) {
  const std::size_t nt = static_cast<std::size_t>(mesh.tets.rows());
  std::vector<int> out(nt, 0);
  const auto it = mesh.cell_data.find(region_array_name);
  if (it == mesh.cell_data.end()) return out;
  const DataArray& a = it->second;
  if (a.components != 1 || a.tuples() != nt)
    throw Error(std::string("cell array '") + region_array_name + "' has " + std::to_string(a.tuples()) + " x " +
                std::to_string(a.components) + " values for " + std::to_string(nt) + " tetrahedra");
  for (std::size_t t = 0; t < nt; ++t) out[t] = static_cast<int>(a.values[t]);
  return out;
}

void set_tet_regions(TetMesh& mesh, const std::vector<int>& regions) {
  DataArray a = make_array(DataArray::Type::Int32, 1, regions.size());
  for (std::size_t t = 0; t < regions.size(); ++t) a.values[t] = regions[t];
  mesh.cell_data[region_array_name] = std::move(a);
}

std::vector<int> region_ids(const TetMesh& mesh) {
  std::vector<int> ids = tet_regions(mesh);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  if (ids.empty()) ids.push_back(0);
  return ids;
}

std::string region_list(const TetMesh& mesh) {
  std::vector<int> ids = region_ids(mesh);
  for (const auto& [id, name] : mesh.region_names)
    if (!std::binary_search(ids.begin(), ids.end(), id)) ids.push_back(id);  // named, but no tet has it
  std::string out;
  for (int id : ids) {
    if (!out.empty()) out += ", ";
    out += std::to_string(id);
    const auto it = mesh.region_names.find(id);
    if (it != mesh.region_names.end()) out += " '" + it->second + "'";
  }
  return out;
}

void inherit_regions(const TetMesh& from, const std::vector<int>& parent, TetMesh& to) {
  if (!from.cell_data.count(region_array_name)) return;
  const std::vector<int> region = tet_regions(from);
  std::vector<int> inherited(parent.size());
  for (std::size_t t = 0; t < parent.size(); ++t) inherited[t] = region.at(static_cast<std::size_t>(parent[t]));
  set_tet_regions(to, inherited);
  to.region_names = from.region_names;
}

void validate_regions(const TetMesh& mesh, const std::string& name) {
  const auto it = mesh.cell_data.find(region_array_name);
  if (it != mesh.cell_data.end()) {
    const DataArray& a = it->second;
    const std::string what = name + ": cell array 'region'";
    if (a.type == DataArray::Type::Float64)
      throw Error(what + " must be an integer array (Int32), not floating point");
    if (a.components != 1)
      throw Error(what + " has " + std::to_string(a.components) + " components, expected 1");
    if (a.tuples() != static_cast<std::size_t>(mesh.tets.rows()))
      throw Error(what + " has " + std::to_string(a.tuples()) + " values for " + std::to_string(mesh.tets.rows()) +
                  " tetrahedra");
    for (std::size_t t = 0; t < a.values.size(); ++t) {
      const double v = a.values[t];
      if (!(v >= 0 && v <= static_cast<double>(max_region_id) && v == std::floor(v)))
        throw Error(what + ": tetrahedron " + std::to_string(t) + " has region " + short_number(v) +
                    ", not an integer in [0, " + std::to_string(max_region_id) + "]");
    }
  }
  std::set<std::string> seen;
  for (const auto& [id, region] : mesh.region_names) {
    const std::string what = name + ": region " + std::to_string(id);
    if (id < 0) throw Error(what + ": region ids are non-negative");
    if (region.empty()) throw Error(what + " has an empty name");
    if (region.size() > 200) throw Error(what + " has a name of " + std::to_string(region.size()) + " characters (at most 200)");
    for (unsigned char c : region)
      if (c < 0x20 || c == 0x7f) throw Error(what + " has a name with a control character");
    if (!seen.insert(region).second) throw Error(what + ": the name '" + region + "' names two regions");
  }
}

}  // namespace xfem
