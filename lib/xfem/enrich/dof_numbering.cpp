// SPDX-License-Identifier: MIT
#include "xfem/enrich/dof_numbering.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

#include "xfem/core/error.h"
#include "xfem/enrich/classification_several_cuts.h"
#include "xfem/enrich/side_codes.h"
#include "xfem/geometry/crack_front.h"
#include "xfem/io/vtk_io.h"

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

namespace {

std::vector<int> ints(const DataArray& a) { return std::vector<int>(a.values.begin(), a.values.end()); }

DataArray int_array(DataArray::Type type, const std::vector<long>& v, int components = 1) {
  DataArray a = make_array(type, components, v.size() / components);
  std::copy(v.begin(), v.end(), a.values.begin());
  return a;
}

/// The product pairs present on a mesh (point arrays product_enrichment_a_b), sorted by (a, b).
std::vector<std::pair<int, int>> product_pairs(const DataArrays& point_data, const std::string& prefix) {
  std::vector<std::pair<int, int>> out;
  for (const auto& [name, a] : point_data) {
    if (name.rfind(prefix, 0) != 0) continue;
    int x = -1, y = -1;
    if (std::sscanf(name.c_str() + prefix.size(), "%d_%d", &x, &y) == 2 && x >= 0 && y > x) out.push_back({x, y});
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

DofNumbering number_classified_mesh(TetMesh& mesh, const std::string& file) {
  if (cut_count(mesh) > 1) return number_several_cuts(mesh, file);  // docs/FORMATS.md "Several cuts"
  const std::size_t V = mesh.points.rows(), T = mesh.tets.rows();
  const auto& enrichment = require_array(mesh.point_data, "enrichment", "point", 1, V, file, "xfem-classify");
  const auto& cut_class = require_array(mesh.cell_data, "cut_class", "cell", 1, T, file, "xfem-classify");
  require_array(mesh.point_data, "side", "point", 1, V, file, "xfem-classify");
  const CrackFront front = read_front(mesh, file);
  DofNumbering d;
  try {
    d = dof_numbering(mesh.tets, static_cast<long>(V), ints(enrichment), ints(cut_class));
  } catch (const Error& e) {
    throw Error(file + ": " + e.what());
  }
  if (d.nb > 0 && front.empty())
    throw Error(file + ": " + std::to_string(d.nb) + " branch nodes but field array 'front_segments' is empty");
  store_dof_numbering(d, mesh);
  return d;
}

DofNumbering number_several_cuts(TetMesh& mesh, const std::string& file) {
  const int K = cut_count(mesh);
  if (K < 2 || K > kMaxCuts)
    throw Error(file + ": field array 'cut_count' is " + std::to_string(K) + ", expected 2.." + std::to_string(kMaxCuts));
  const long V = mesh.points.rows(), T = mesh.tets.rows();
  std::vector<std::vector<int>> enr(K), cls(K);
  for (int k = 0; k < K; ++k) {
    enr[k] = ints(require_array(mesh.point_data, "enrichment" + cut_suffix(k), "point", 1, V, file, "xfem-classify"));
    cls[k] = ints(require_array(mesh.cell_data, "cut_class" + cut_suffix(k), "cell", 1, T, file, "xfem-classify"));
    for (long v = 0; v < V; ++v)
      if (enr[k][v] < 0 || enr[k][v] > 2)
        throw Error(file + ": point array 'enrichment" + cut_suffix(k) + "': point " + std::to_string(v) + " has " +
                    std::to_string(enr[k][v]) + ", expected 0, 1 or 2");
    for (long t = 0; t < T; ++t)
      if (cls[k][t] < 0 || cls[k][t] > 2)
        throw Error(file + ": cell array 'cut_class" + cut_suffix(k) + "': tet " + std::to_string(t) + " has " +
                    std::to_string(cls[k][t]) + ", expected 0, 1 or 2");
  }
  const auto pairs = product_pairs(mesh.point_data, "product_enrichment_");
  std::vector<std::vector<int>> prod;
  for (const auto& [a, b] : pairs) {
    if (b >= K) throw Error(file + ": point array 'product_enrichment" + pair_suffix(a, b) + "' names a cut beyond the " + std::to_string(K));
    prod.push_back(ints(require_array(mesh.point_data, "product_enrichment" + pair_suffix(a, b), "point", 1, V, file, "xfem-classify")));
  }

  DofNumbering d;
  d.np = V;
  std::vector<std::vector<long>> sign(K, std::vector<long>(V, -1)), branch(K, std::vector<long>(V, -1)),
      product(pairs.size(), std::vector<long>(V, -1));
  std::vector<long> blocks(4 * K), pblocks;
  long next = V;
  for (int k = 0; k < K; ++k) {
    blocks[4 * k] = next;
    for (long v = 0; v < V; ++v)
      if (enr[k][v] == 1) sign[k][v] = next++;
    blocks[4 * k + 1] = next - blocks[4 * k];
  }
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const long first = next;
    for (long v = 0; v < V; ++v)
      if (prod[p][v]) product[p][v] = next++;
    pblocks.insert(pblocks.end(), {pairs[p].first, pairs[p].second, first, next - first});
  }
  d.ns = next - V;
  for (int k = 0; k < K; ++k) {
    blocks[4 * k + 2] = next;
    for (long v = 0; v < V; ++v)
      if (enr[k][v] == 2) {
        branch[k][v] = next;
        next += 4;
      }
    blocks[4 * k + 3] = (next - blocks[4 * k + 2]) / 4;
  }
  d.nb = (next - V - d.ns) / 4;
  d.n = next;
  d.sign_dof = sign[0];
  d.branch_dof = branch[0];

  d.offsets.push_back(0);
  std::vector<std::pair<long, int>> extra;  // (first DOF, local node)
  for (long t = 0; t < T; ++t) {
    bool cut = false;
    for (int k = 0; k < K; ++k) cut = cut || cls[k][t] != 0;
    extra.clear();
    for (int c = 0; c < 4; ++c) {
      const int m = mesh.tets(t, c);
      d.dofs.push_back(m);
      d.local.push_back(c);
      for (int k = 0; k < K; ++k) {
        if (cut && sign[k][m] >= 0) extra.push_back({sign[k][m], c});
        if (branch[k][m] >= 0) extra.push_back({branch[k][m], c});
      }
      for (std::size_t p = 0; p < pairs.size(); ++p)
        if (cut && product[p][m] >= 0) extra.push_back({product[p][m], c});
    }
    std::sort(extra.begin(), extra.end());
    for (const auto& [dof, c] : extra)
      for (int j = 0; j < (dof >= d.np + d.ns ? 4 : 1); ++j) {
        d.dofs.push_back(dof + j);
        d.local.push_back(c);
      }
    d.offsets.push_back(static_cast<long>(d.dofs.size()));
  }
  for (int k = 0; k < K; ++k) {
    TetMesh view;
    view.field_data["front_segments"] = mesh.field_data["front_segments" + cut_suffix(k)];
    view.field_data["front_normals"] = mesh.field_data["front_normals" + cut_suffix(k)];
    if (blocks[4 * k + 3] > 0 && read_front(view, file).empty())
      throw Error(file + ": cut " + std::to_string(k) + " has " + std::to_string(blocks[4 * k + 3]) +
                  " branch nodes but field array 'front_segments" + cut_suffix(k) + "' is empty");
  }
  store_dof_numbering(d, mesh);
  for (int k = 1; k < K; ++k) {
    mesh.point_data["sign_dof" + cut_suffix(k)] = int_array(DataArray::Type::Int64, sign[k]);
    mesh.point_data["branch_dof" + cut_suffix(k)] = int_array(DataArray::Type::Int64, branch[k]);
  }
  for (std::size_t p = 0; p < pairs.size(); ++p)
    mesh.point_data["product_dof" + pair_suffix(pairs[p].first, pairs[p].second)] = int_array(DataArray::Type::Int64, product[p]);
  mesh.field_data["cut_dof_blocks"] = int_array(DataArray::Type::Int64, blocks, 4);
  mesh.field_data["product_dof_blocks"] = int_array(DataArray::Type::Int64, pblocks, 4);
  return d;
}


}  // namespace xfem
