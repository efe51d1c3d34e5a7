// SPDX-License-Identifier: MIT
#include "xfem/box_mesh.h"

#include "xfem/error.h"

namespace xfem {

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

}  // namespace xfem
