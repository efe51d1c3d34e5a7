// SPDX-License-Identifier: MIT
#include "xfem/generate/mesh_ordering.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "xfem/core/error.h"

namespace xfem {
namespace {

constexpr int grid_bits = 21;  // 3 x 21 = 63 bits: the whole key fits one uint64

// Indices 0..n-1 sorted by key, ties by index (a stable sort of the identity).
std::vector<int> order_by(const std::vector<std::uint64_t>& keys) {
  std::vector<int> order(keys.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&keys](int a, int b) { return keys[a] < keys[b]; });
  return order;
}

DataArrays permuted(const DataArrays& arrays, const std::vector<int>& order, const char* where) {
  DataArrays out;
  for (const auto& [name, a] : arrays) {
    const std::size_t c = static_cast<std::size_t>(a.components);
    if (c == 0 || a.values.size() != order.size() * c)
      throw Error(std::string("spatial ordering: ") + where + " array '" + name + "' has " +
                  std::to_string(a.values.size()) + " values, not " + std::to_string(order.size()) + " tuples of " +
                  std::to_string(a.components));
    DataArray b = a;
    for (std::size_t i = 0; i < order.size(); ++i)
        std::copy_n(a.values.begin() + order[i] * c, c, b.values.begin() + i * c);
    out.emplace(name, std::move(b));
  }
  return out;
}

}  // namespace

std::uint64_t hilbert_index(std::array<std::uint32_t, 3> x, int bits) {
  if (bits < 1 || bits > grid_bits)
    throw Error("hilbert_index: bits must be in 1.." + std::to_string(grid_bits) + " (got " + std::to_string(bits) +
                ")");
  for (int i = 0; i < 3; ++i)
    if (x[i] >> bits)
      throw Error("hilbert_index: coordinate " + std::to_string(x[i]) + " does not fit in " + std::to_string(bits) +
                  " bits");
  // Skilling's AxestoTranspose: undo the excess rotations and reflections level by level,
  // then Gray-encode; the transposed bits interleaved give the index.
  const std::uint32_t top = 1u << (bits - 1);
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t p = q - 1;
    for (int i = 0; i < 3; ++i)
      if (x[i] & q) {
        x[0] ^= p;  // invert the low bits
      } else {      // exchange the low bits of x[0] and x[i]
        const std::uint32_t t = (x[0] ^ x[i]) & p;
        x[0] ^= t;
        x[i] ^= t;
      }
  }
  for (int i = 1; i < 3; ++i) x[i] ^= x[i - 1];
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1)
    if (x[2] & q) t ^= q - 1;
  for (int i = 0; i < 3; ++i) x[i] ^= t;
  std::uint64_t index = 0;
  for (int b = bits - 1; b >= 0; --b)
    for (int i = 0; i < 3; ++i) index = (index << 1) | ((x[i] >> b) & 1u);
  return index;
}

MeshOrdering spatial_ordering(const TetMesh& mesh) {
  const Eigen::Index np = mesh.points.rows(), nt = mesh.tets.rows();
  if (!mesh.points.allFinite()) throw Error("spatial ordering: the mesh has a coordinate that is not finite");
  for (Eigen::Index t = 0; t < nt; ++t)
    for (int k = 0; k < 4; ++k)
      if (mesh.tets(t, k) < 0 || mesh.tets(t, k) >= np)
        throw Error("spatial ordering: tet " + std::to_string(t) + " names point " + std::to_string(mesh.tets(t, k)) +
                    " of " + std::to_string(np));
  // The bounding cube rather than the box: equal cells in x, y, z keep the curve's locality
  // isotropic on elongated bodies (the beam is 7x longer than thick).
  Eigen::RowVector3d lo = Eigen::RowVector3d::Zero();
  double extent = 0;
  if (np > 0) {
    lo = mesh.points.colwise().minCoeff();
    extent = (mesh.points.colwise().maxCoeff() - lo).maxCoeff();
  }
  const double cells = static_cast<double>(1u << grid_bits);
  const double scale = extent > 0 ? cells / extent : 0;
  const auto key = [&](const Eigen::RowVector3d& p) {
    std::array<std::uint32_t, 3> q;
    for (int a = 0; a < 3; ++a)
      q[a] = static_cast<std::uint32_t>(std::clamp((p[a] - lo[a]) * scale, 0.0, cells - 1));
    return hilbert_index(q, grid_bits);
  };
  std::vector<std::uint64_t> point_keys(np), tet_keys(nt);
  for (Eigen::Index i = 0; i < np; ++i) point_keys[i] = key(mesh.points.row(i));
  for (Eigen::Index t = 0; t < nt; ++t) {
    Eigen::RowVector3d c = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 4; ++k) c += mesh.points.row(mesh.tets(t, k));
    tet_keys[t] = key(c / 4);
  }
  return {order_by(point_keys), order_by(tet_keys)};
}

TetMesh spatially_ordered(const TetMesh& mesh) {
  const MeshOrdering o = spatial_ordering(mesh);
  std::vector<int> new_id(o.point_order.size());
  for (std::size_t i = 0; i < o.point_order.size(); ++i) new_id[o.point_order[i]] = static_cast<int>(i);
  TetMesh out;
  out.points.resize(mesh.points.rows(), 3);
  for (std::size_t i = 0; i < o.point_order.size(); ++i) out.points.row(i) = mesh.points.row(o.point_order[i]);
  out.tets.resize(mesh.tets.rows(), 4);
  for (std::size_t t = 0; t < o.tet_order.size(); ++t)
    for (int k = 0; k < 4; ++k) out.tets(t, k) = new_id[mesh.tets(o.tet_order[t], k)];
  out.point_data = permuted(mesh.point_data, o.point_order, "point");
  out.cell_data = permuted(mesh.cell_data, o.tet_order, "cell");
  out.field_data = mesh.field_data;
  out.region_names = mesh.region_names;  // the ids are the cell array "region", permuted above
  return out;
}

}  // namespace xfem
