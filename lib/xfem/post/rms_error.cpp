// SPDX-License-Identifier: MIT
#include "xfem/post/rms_error.h"

#include <cmath>
#include <memory>

#include "xfem/geometry/point_location.h"

namespace xfem {

RmsReport rms_error(const ReferenceSamples& reference, const FieldAt& field) {
  RmsReport r;
  double sum = 0.0, ref_sum = 0.0;
  for (Eigen::Index k = 0; k < reference.points.rows(); ++k) {
    bool snapped = false;
    const int side = reference.side.empty() ? 0 : reference.side[k];
    const auto u = field(reference.points.row(k).transpose(), side, snapped);
    if (!u) {
      ++r.outside;
      continue;
    }
    ++r.compared;
    r.snapped += snapped;
    const Eigen::Vector3d ref = reference.displacement.row(k).transpose();
    const double e2 = (ref - *u).squaredNorm();
    sum += e2;
    ref_sum += ref.squaredNorm();
    if (std::sqrt(e2) > r.max || r.max_node < 0) {
      r.max = std::sqrt(e2);
      r.max_node = k;
    }
  }
  if (r.compared > 0) {
    r.rms = std::sqrt(sum / (3.0 * r.compared));
    r.reference_rms = std::sqrt(ref_sum / (3.0 * r.compared));
  }
  return r;
}

FieldAt plain_field(const TetMesh& mesh, const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& u,
                    double radius) {
  auto locator = std::make_shared<PointLocator>(mesh);
  // A tet's side: that of its duplicated-node copies (+1) or originals (-1), 0 off the cut.
  auto tet_side = std::make_shared<std::vector<int>>(mesh.tets.rows(), 0);
  const auto it = mesh.point_data.find("cut_side");
  if (it != mesh.point_data.end())
    for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t)
      for (int c = 0; c < 4; ++c)
        if (const int s = static_cast<int>(it->second(mesh.tets(t, c)))) (*tet_side)[t] = s;
  return [&mesh, &u, locator, tet_side, radius](const Eigen::Vector3d& x, int side,
                                                bool& snapped) -> std::optional<Eigen::Vector3d> {
    snapped = false;
    int t = -1;
    const auto candidates = locator->containing(x);
    for (int c : candidates)  // prefer a tet on the point's side, then one off the cut
      if ((*tet_side)[c] == side) {
        t = c;
        break;
      }
    if (t < 0)
      for (int c : candidates)
        if ((*tet_side)[c] == 0) {
          t = c;
          break;
        }
    if (t < 0 && !candidates.empty()) t = candidates.front();
    if (t < 0) {
      t = locator->nearest(x, radius);
      if (t < 0) return std::nullopt;
      snapped = true;
    }
    Eigen::Vector4d l = locator->barycentric(t, x).cwiseMax(0.0);
    l /= l.sum();
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    for (int c = 0; c < 4; ++c) v += l[c] * u.row(mesh.tets(t, c)).transpose();
    return v;
  };
}

}  // namespace xfem
