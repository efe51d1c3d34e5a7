// SPDX-License-Identifier: MIT
#include "xfem/enrich/dof_numbering.h"

#include <algorithm>
#include <string>
#include <utility>

#include "xfem/core/error.h"

namespace xfem {

DofNumbering dof_numbering(const Tets& tets, long points, const std::vector<int>& enrichment,
                           const std::vector<int>& cut_class) {
  const long T = tets.rows();
  if (static_cast<long>(enrichment.size()) != points)
    throw Error("dof_numbering: " + std::to_string(enrichment.size()) + " enrichment values for " +
                std::to_string(points) + " points");
  if (static_cast<long>(cut_class.size()) != T)
    throw Error("dof_numbering: " + std::to_string(cut_class.size()) + " cut classes for " + std::to_string(T) +
                " tets");
  DofNumbering d;
  d.np = points;
  d.sign_dof.assign(points, -1);
  d.branch_dof.assign(points, -1);
  for (long m = 0; m < points; ++m) {
    if (enrichment[m] < 0 || enrichment[m] > 2)
      throw Error("point " + std::to_string(m) + ": enrichment " + std::to_string(enrichment[m]) +
                  " is not 0 (none), 1 (sign) or 2 (branch)");
    d.ns += enrichment[m] == 1;
    d.nb += enrichment[m] == 2;
  }
  long next_sign = d.np, next_branch = d.np + d.ns;
  for (long m = 0; m < points; ++m) {
    if (enrichment[m] == 1) d.sign_dof[m] = next_sign++;
    if (enrichment[m] == 2) {
      d.branch_dof[m] = next_branch;
      next_branch += 4;
    }
  }
  d.n = next_branch;

  d.offsets.reserve(T + 1);
  d.offsets.push_back(0);
  std::vector<std::pair<long, int>> extra;  // (first DOF id, local node)
  for (long t = 0; t < T; ++t) {
    if (cut_class[t] < 0 || cut_class[t] > 2)
      throw Error("tet " + std::to_string(t) + ": cut_class " + std::to_string(cut_class[t]) +
                  " is not 0 (uncut), 1 (partial) or 2 (complete)");
    extra.clear();
    for (int k = 0; k < 4; ++k) {
      const int m = tets(t, k);
      if (m < 0 || m >= points) throw Error("tet " + std::to_string(t) + ": point id " + std::to_string(m) + " out of range");
      d.dofs.push_back(m);
      d.local.push_back(k);
      if (d.sign_dof[m] >= 0 && cut_class[t] != 0) extra.push_back({d.sign_dof[m], k});
      if (d.branch_dof[m] >= 0) extra.push_back({d.branch_dof[m], k});
    }
    std::sort(extra.begin(), extra.end());
    for (const auto& [dof, k] : extra) {
      const int count = dof >= d.np + d.ns ? 4 : 1;
      for (int j = 0; j < count; ++j) {
        d.dofs.push_back(dof + j);
        d.local.push_back(k);
      }
    }
    d.offsets.push_back(static_cast<long>(d.dofs.size()));
  }
  return d;
}

void store_dof_numbering(const DofNumbering& d, TetMesh& mesh) {
  auto int64 = [](const std::vector<long>& v) {
    DataArray a = make_array(DataArray::Type::Int64, 1, v.size());
    std::copy(v.begin(), v.end(), a.values.begin());
    return a;
  };
  mesh.field_data["dof_counts"] = int64({d.np, d.ns, d.nb, d.n});
  mesh.field_data["extended_offsets"] = int64(d.offsets);
  mesh.field_data["extended_dofs"] = int64(d.dofs);
  DataArray local = make_array(DataArray::Type::Int32, 1, d.local.size());
  std::copy(d.local.begin(), d.local.end(), local.values.begin());
  mesh.field_data["extended_local"] = std::move(local);
  mesh.point_data["sign_dof"] = int64(d.sign_dof);
  mesh.point_data["branch_dof"] = int64(d.branch_dof);
}

}  // namespace xfem
