// SPDX-License-Identifier: MIT
#include "xfem/geometry/point_location.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "xfem/core/error.h"

namespace xfem {

Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

PointLocator::PointLocator(const TetMesh& mesh) : mesh_(mesh) {
  const int nt = static_cast<int>(mesh.tets.rows());
  if (nt == 0) throw Error("point location: mesh without tetrahedra");
  lo_ = mesh.points.colwise().minCoeff().transpose();
  const Eigen::Vector3d hi = mesh.points.colwise().maxCoeff().transpose();
  const Eigen::Vector3d extent = (hi - lo_).cwiseMax(1e-300);
  // About one tet per bucket: the bucket edge is the side of a cube holding volume / nt.
  const double h = std::cbrt(extent.prod() / nt);
  for (int d = 0; d < 3; ++d) dims_[d] = std::clamp(static_cast<int>(std::ceil(extent[d] / h)), 1, 1024);
  cell_ = extent.cwiseQuotient(dims_.cast<double>());

  inverse_.resize(nt);
  std::vector<std::pair<long, int>> entries;  // (bucket, tet)
  for (int t = 0; t < nt; ++t) {
    Eigen::Matrix4d A;
    for (int k = 0; k < 4; ++k) A.col(k) << mesh.points.row(mesh.tets(t, k)).transpose(), 1.0;
    inverse_[t] = A.inverse();
    Eigen::Vector3d bmin = mesh.points.row(mesh.tets(t, 0)), bmax = bmin;
    for (int k = 1; k < 4; ++k) {
      bmin = bmin.cwiseMin(mesh.points.row(mesh.tets(t, k)).transpose());
      bmax = bmax.cwiseMax(mesh.points.row(mesh.tets(t, k)).transpose());
    }
    const Eigen::Vector3i b0 = bucket_of(bmin), b1 = bucket_of(bmax);
    for (int k = b0[2]; k <= b1[2]; ++k)
      for (int j = b0[1]; j <= b1[1]; ++j)
        for (int i = b0[0]; i <= b1[0]; ++i)
          entries.emplace_back(i + static_cast<long>(dims_[0]) * (j + static_cast<long>(dims_[1]) * k), t);
  }
  std::sort(entries.begin(), entries.end());
  start_.assign(static_cast<std::size_t>(dims_.prod()) + 1, 0);
  items_.resize(entries.size());
  for (std::size_t e = 0; e < entries.size(); ++e) {
    ++start_[entries[e].first + 1];
    items_[e] = entries[e].second;
  }
  for (std::size_t b = 1; b < start_.size(); ++b) start_[b] += start_[b - 1];
}

Eigen::Vector3i PointLocator::bucket_of(const Eigen::Vector3d& x) const {
  Eigen::Vector3i b;
  for (int d = 0; d < 3; ++d)
    b[d] = std::clamp(static_cast<int>(std::floor((x[d] - lo_[d]) / cell_[d])), 0, dims_[d] - 1);
  return b;
}

Eigen::Vector4d PointLocator::barycentric(int t, const Eigen::Vector3d& x) const {
  return inverse_[t] * Eigen::Vector4d(x[0], x[1], x[2], 1.0);
}

std::vector<int> PointLocator::containing(const Eigen::Vector3d& x, double tol) const {
  std::vector<int> found;
  const Eigen::Vector3i b = bucket_of(x);
  const long id = b[0] + static_cast<long>(dims_[0]) * (b[1] + static_cast<long>(dims_[1]) * b[2]);
  for (int e = start_[id]; e < start_[id + 1]; ++e)
    if (barycentric(items_[e], x).minCoeff() >= -tol) found.push_back(items_[e]);
  return found;  // bucket items are sorted by tet
}

int PointLocator::nearest(const Eigen::Vector3d& x, double radius, double* distance) const {
  const auto inside = containing(x);
  if (!inside.empty()) {
    if (distance) *distance = 0.0;
    return inside.front();
  }
  const Eigen::Vector3d r = Eigen::Vector3d::Constant(radius);
  const Eigen::Vector3i b0 = bucket_of(x - r), b1 = bucket_of(x + r);
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (int k = b0[2]; k <= b1[2]; ++k)
    for (int j = b0[1]; j <= b1[1]; ++j)
      for (int i = b0[0]; i <= b1[0]; ++i) {
        const long id = i + static_cast<long>(dims_[0]) * (j + static_cast<long>(dims_[1]) * k);
        for (int e = start_[id]; e < start_[id + 1]; ++e) {
          const int t = items_[e];
          // x is outside every tet here, so the closest point of a tet lies on one of its faces.
          double d = std::numeric_limits<double>::infinity();
          for (int skip = 0; skip < 4; ++skip) {
            Eigen::Vector3d v[3];
            for (int c = 0, n = 0; c < 4; ++c)
              if (c != skip) v[n++] = mesh_.points.row(mesh_.tets(t, c)).transpose();
            d = std::min(d, (closest_on_triangle(x, v[0], v[1], v[2]) - x).norm());
          }
          if (d < best_d || (d == best_d && t < best)) {
            best_d = d;
            best = t;
          }
        }
      }
  if (best_d > radius) return -1;
  if (distance) *distance = best_d;
  return best;
}

}  // namespace xfem
