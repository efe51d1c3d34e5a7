// SPDX-License-Identifier: MIT
#include "xfem/generate/box_mesh.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "xfem/core/error.h"

namespace xfem {
namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

// Index of the interior grid plane at `value` along one axis (lo..hi in n cells), or an error
// naming the nearest planes. The tolerance (1e-9 of a cell) only absorbs decimal rounding such
// as 0.1 / 0.2 * 120.
int interior_plane(double value, double lo, double hi, int n, const char* what) {
  const double h = (hi - lo) / n;
  const double t = (value - lo) / h;
  const long k = std::lround(t);
  if (std::isfinite(t) && std::abs(t - double(k)) <= 1e-9 && k >= 1 && k <= n - 1) return static_cast<int>(k);
  std::string msg = std::string("box mesh: cut ") + what + " = " + number(value) + " is not an interior grid plane";
  if (std::isfinite(t) && t > 0 && t < n) {
    const double below = lo + std::floor(t) * h, above = lo + std::ceil(t) * h;
    msg += " (cells are " + number(h) + " m; nearest planes " + what + " = " + number(below) + " and " +
           number(above) + ")";
  } else {
    msg += " (the box spans " + number(lo) + " .. " + number(hi) + "; the cut must lie strictly inside)";
  }
  throw Error(msg);
}

}  // namespace

TetMesh box_mesh(const Eigen::Vector3i& cells, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  if ((cells.array() <= 0).any()) throw Error("box mesh: cell counts must be positive");
  if ((hi.array() <= lo.array()).any()) throw Error("box mesh: empty box (hi must exceed lo in x, y and z)");
  const int nx = cells[0], ny = cells[1], nz = cells[2];
  const auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  TetMesh mesh;
  mesh.points.resize(static_cast<Eigen::Index>(nx + 1) * (ny + 1) * (nz + 1), 3);
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const Eigen::Vector3d t(double(i) / nx, double(j) / ny, double(k) / nz);
        mesh.points.row(id(i, j, k)) = (lo.array() + t.array() * (hi - lo).array()).matrix().transpose();
      }
  // Kuhn split: each tet walks from corner 000 to 111 along one permutation of the axes.
  static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  mesh.tets.resize(static_cast<Eigen::Index>(6) * nx * ny * nz, 4);
  Eigen::Index t = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& p : perms) {
          int c[3] = {i, j, k};
          int v[4];
          v[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[p[s]];
            v[s + 1] = id(c[0], c[1], c[2]);
          }
          // Odd permutations walk the other way round: swap to keep the volume positive.
          const bool odd = (p[0] == 0 && p[1] == 2) || (p[0] == 1 && p[1] == 0) || (p[0] == 2 && p[1] == 1);
          if (odd) std::swap(v[1], v[2]);
          mesh.tets.row(t++) << v[0], v[1], v[2], v[3];
        }
  return mesh;
}

TetMesh box_mesh(const Eigen::Vector3i& cells, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                 const BoxCut& cut) {
  TetMesh mesh = box_mesh(cells, lo, hi);
  const int nx = cells[0], ny = cells[1];
  const int kc = interior_plane(cut.z, lo[2], hi[2], cells[2], "z");
  const int i_front = interior_plane(cut.x_front, lo[0], hi[0], nx, "x_front");
  const Eigen::Index grid = mesh.points.rows();
  const auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };

  // 1. Copies of the plane's nodes with i < i_front, after the grid nodes (i fastest, then j).
  const Eigen::Index copies = static_cast<Eigen::Index>(i_front) * (ny + 1);
  mesh.points.conservativeResize(grid + copies, 3);
  DataArray side = make_array(DataArray::Type::Int32, 1, grid + copies, 0.0);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i < i_front; ++i) {
      const Eigen::Index copy = grid + i + static_cast<Eigen::Index>(i_front) * j;
      mesh.points.row(copy) = mesh.points.row(id(i, j, kc));
      side.values[copy] = +1.0;
      side.values[id(i, j, kc)] = -1.0;
    }

  // 2. The cube layer just above the plane (cube index k = kc) switches to the copies. Tets are
  // numbered 6 per cube, cubes i fastest, so this layer is one contiguous block.
  const Eigen::Index first = static_cast<Eigen::Index>(6) * nx * ny * kc, last = first + 6 * nx * ny;
  for (Eigen::Index t = first; t < last; ++t)
    for (int c = 0; c < 4; ++c) {
      const int v = mesh.tets(t, c);
      const int i = v % (nx + 1), j = (v / (nx + 1)) % (ny + 1), k = v / ((nx + 1) * (ny + 1));
      if (k == kc && i < i_front) mesh.tets(t, c) = static_cast<int>(grid + i + static_cast<Eigen::Index>(i_front) * j);
    }
  mesh.point_data["cut_side"] = std::move(side);
  return mesh;
}

}  // namespace xfem
