// SPDX-License-Identifier: MIT
#include "xfem/integrate/oversampling_quadrature.h"

#include <array>
#include <string>

#include "xfem/core/error.h"

namespace xfem {

std::vector<Eigen::Matrix4d> uniform_subtets(int m) {
  if (m < 1) throw Error("oversampling: subdivision count must be positive, got " + std::to_string(m));
  // Work in the Kuhn simplex S = {1 >= y0 >= y1 >= y2 >= 0}, affinely the reference tet with
  // barycentric coordinates (1 - y0, y0 - y1, y1 - y2, y2). Scaled by m, S is exactly the union of
  // the Kuhn simplices of the unit lattice cubes that lie in it (its faces are lattice planes
  // y_i = y_j, y_0 = m, y_2 = 0 of the Freudenthal triangulation): m^3 simplices of equal volume.
  static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  std::vector<Eigen::Matrix4d> out;
  out.reserve(static_cast<std::size_t>(m) * m * m);
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
        for (const auto& p : perms) {
          std::array<Eigen::Vector3d, 4> v;
          v[0] = Eigen::Vector3d(i, j, k);
          for (int s = 0; s < 3; ++s) {
            v[s + 1] = v[s];
            v[s + 1][p[s]] += 1.0;
          }
          const Eigen::Vector3d c = (v[0] + v[1] + v[2] + v[3]) / 4.0;
          if (!(c[0] < m && c[0] > c[1] && c[1] > c[2] && c[2] > 0)) continue;
          Eigen::Matrix4d corners;
          for (int q = 0; q < 4; ++q) {
            const Eigen::Vector3d y = v[q] / m;
            corners.col(q) << 1.0 - y[0], y[0] - y[1], y[1] - y[2], y[2];
          }
          out.push_back(corners);
        }
  if (static_cast<long>(out.size()) != static_cast<long>(m) * m * m)
    throw Error("oversampling: internal error, " + std::to_string(out.size()) + " sub-tets for m = " +
                std::to_string(m));
  return out;
}

Quadrature oversampling_quadrature(int requested, int refine_levels) {
  if (requested < 1)
    throw Error("oversampling: the number of integration points must be at least 1, got " + std::to_string(requested));
  if (refine_levels < 0 || refine_levels > 8)
    throw Error("oversampling: refinement levels must lie in 0..8, got " + std::to_string(refine_levels));
  int m = 1;
  while (static_cast<long>(m) * m * m <= requested) ++m;
  Quadrature q;
  q.refine_levels = refine_levels;
  q.cells = uniform_subtets(m);
  const double w = 1.0 / (static_cast<double>(m) * m * m);
  for (const auto& corners : q.cells) {
    q.lambda.push_back(corners.rowwise().mean());
    q.weights.push_back(w);
  }
  return q;
}

Quadrature refine_at_cut(const Quadrature& rule, const std::function<int(const Eigen::Vector4d&)>& side) {
  if (rule.refine_levels == 0 || rule.cells.empty()) return rule;
  static const std::vector<Eigen::Matrix4d> children = uniform_subtets(2);
  Quadrature q;
  q.refine_levels = rule.refine_levels;
  const std::function<void(const Eigen::Matrix4d&, int, double)> visit = [&](const Eigen::Matrix4d& corners, int level,
                                                                              double weight) {
    const Eigen::Vector4d centroid = corners.rowwise().mean();
    bool split = false;
    if (level < rule.refine_levels) {
      const int s = side(centroid);
      for (int c = 0; c < 4 && !split; ++c) split = side(corners.col(c)) != s;
    }
    if (!split) {
      q.lambda.push_back(centroid);
      q.weights.push_back(weight);
      q.cells.push_back(corners);
      return;
    }
    // Child corners in the tet's barycentric coordinates: the parent's corners weighted by the
    // child's corners in the parent's.
    for (const Eigen::Matrix4d& child : children) visit(corners * child, level + 1, weight / 8.0);
  };
  for (std::size_t k = 0; k < rule.cells.size(); ++k) visit(rule.cells[k], 0, rule.weights[k]);
  return q;
}

}  // namespace xfem
