// SPDX-License-Identifier: MIT
#include "xfem/geometry/tet_shape.h"

#include <algorithm>

#include "xfem/core/error.h"

namespace xfem {

TetShape tet_shape(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                   const Eigen::Vector3d& p3) {
  // x = p0 + J (N_1, N_2, N_3) with J = [e1 | e2 | e3], e_i = p_i - p0, so grad N_1..N_3 are the rows
  // of J^-1: the cross products of the other two edges over det J. grad N_0 = -(their sum)
  // (partition of unity). Written out because assembly calls this once per tet.
  const Eigen::Vector3d e1 = p1 - p0, e2 = p2 - p0, e3 = p3 - p0;
  const Eigen::Vector3d c1 = e2.cross(e3), c2 = e3.cross(e1), c3 = e1.cross(e2);
  const double det = e1.dot(c1);
  const double longest2 = std::max({e1.squaredNorm(), e2.squaredNorm(), e3.squaredNorm()});
  // Degenerate when |det| <= 1e-14 l^3, compared squared to avoid a square root.
  if (!(det * det > 1e-28 * longest2 * longest2 * longest2))
    throw Error("tet_shape: degenerate tetrahedron (zero volume)");
  TetShape s;
  const double inv = 1.0 / det;
  s.grad.row(1) = c1 * inv;
  s.grad.row(2) = c2 * inv;
  s.grad.row(3) = c3 * inv;
  s.grad.row(0) = -(s.grad.row(1) + s.grad.row(2) + s.grad.row(3));
  s.centroid = (p0 + p1 + p2 + p3) / 4.0;
  s.volume = det / 6.0;
  return s;
}

TetShape tet_shape(const TetMesh& mesh, int tet) {
  const auto p = [&](int c) -> Eigen::Vector3d { return mesh.points.row(mesh.tets(tet, c)).transpose(); };
  try {
    return tet_shape(p(0), p(1), p(2), p(3));
  } catch (const Error&) {
    throw Error("tet " + std::to_string(tet) + ": degenerate tetrahedron (zero volume)");
  }
}

Eigen::Vector3d tet_point(const TetMesh& mesh, int tet, const Eigen::Vector4d& lambda) {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int c = 0; c < 4; ++c) x += lambda[c] * mesh.points.row(mesh.tets(tet, c)).transpose();
  return x;
}

}  // namespace xfem
