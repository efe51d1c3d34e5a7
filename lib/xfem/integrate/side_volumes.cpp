// SPDX-License-Identifier: MIT
#include "xfem/integrate/side_volumes.h"

#include <algorithm>
#include <cmath>

#include "xfem/core/mesh.h"
#include "xfem/geometry/tet_shape.h"
#include "xfem/integrate/polygon_split.h"

namespace xfem {

SideVolumes side_volumes(const TetMesh& mesh, const CutElementSplits& splits, int t) {
  SideVolumes out;
  const int i = splits.index.empty() ? -1 : splits.index[t];
  if (i < 0) {
    out.side.push_back(0);
    out.volume.push_back(std::abs(signed_volume(mesh, t)));
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int c = 0; c < 4; ++c) centre += mesh.points.row(mesh.tets(t, c)).transpose();
    out.point.push_back(0.25 * centre);
    return out;
  }
  for (int s = splits.first[i]; s < splits.first[i + 1]; ++s) {
    const auto& q = splits.tets[s];
    const double v = std::abs(signed_volume(q[0], q[1], q[2], q[3]));
    const auto found = std::find(out.side.begin(), out.side.end(), splits.side[s]);
    if (found == out.side.end()) {
      out.side.push_back(splits.side[s]);
      out.volume.push_back(v);
      out.point.push_back(0.25 * (q[0] + q[1] + q[2] + q[3]));
    } else {
      out.volume[found - out.side.begin()] += v;
    }
  }
  return out;
}

namespace {

// The parts of the convex polygon on either side of the plane (point, normal), corners within
// `tolerance` of it on both; a polygon the plane does not cross (lying in it included) stays whole.
void cut_polygon(const Polygon& poly, const Eigen::Vector3d& point, const Eigen::Vector3d& normal, double tolerance,
                 std::vector<Polygon>& out) {
  Polygon above, below;
  if (!split_polygon(poly, point, normal, tolerance, above, below)) {
    out.push_back(poly);
    return;
  }
  if (above.size() >= 3) out.push_back(above);
  if (below.size() >= 3) out.push_back(below);
}

// The part of the convex polygon on the side of the plane (point, normal) the normal points to
// (corners within `tolerance` of the plane kept); empty if fewer than 3 corners remain.
Polygon keep_above(const Polygon& poly, const Eigen::Vector3d& point, const Eigen::Vector3d& normal, double tolerance) {
  Polygon above, below;
  split_polygon(poly, point, normal, tolerance, above, below);
  if (above.size() < 3) above.clear();
  return above;
}

// Area vector (area times unit normal by the corners' turn) of a planar polygon.
Eigen::Vector3d area_vector(const Polygon& poly) {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  for (std::size_t k = 1; k + 1 < poly.size(); ++k) a += 0.5 * (poly[k] - poly[0]).cross(poly[k + 1] - poly[0]);
  return a;
}

}  // namespace

std::array<double, 2> side_volumes_by_divergence(const std::array<Eigen::Vector3d, 4>& p, const CutSurface& cut) {
  const Eigen::Vector3d o = 0.25 * (p[0] + p[1] + p[2] + p[3]);
  double h = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) h = std::max(h, (p[a] - p[b]).norm());
  const double tolerance = 1e-12 * h;
  const std::vector<int> meeting = cut.triangles_meeting(p);
  const TriangleMesh& cm = cut.mesh();
  std::array<double, 2> v = {0.0, 0.0};
  // The tet's faces, each split by every meeting triangle's plane: no cut triangle then crosses a
  // part's inside, so each part lies on one side, that of a point just inside the tet from it.
  std::vector<Polygon> parts, next;
  for (int k = 0; k < 4; ++k) {
    parts.assign(1, Polygon{p[(k + 1) % 4], p[(k + 2) % 4], p[(k + 3) % 4]});
    for (const int tri : meeting) {
      const Eigen::Vector3d point = cm.points.row(cm.triangles(tri, 0)).transpose();
      next.clear();
      for (const Polygon& part : parts) cut_polygon(part, point, cut.unit_normal(tri), tolerance, next);
      parts.swap(next);
    }
    for (const Polygon& part : parts) {
      Eigen::Vector3d a = area_vector(part);
      if (a.dot(part[0] - p[k]) < 0) a = -a;  // outward: away from the opposite corner
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (const auto& x : part) centre += x;
      centre /= static_cast<double>(part.size());
      const int side = cut.side(centre + 1e-7 * (o - centre));
      v[side > 0 ? 0 : 1] += a.dot(part[0] - o) / 3.0;
    }
  }
  // The cut inside the tet: the boundary of both sides, outward -n above and +n below. Parts of it
  // lying on a face bound neither side from inside (the face's part was counted above).
  for (const int tri : meeting) {
    // The triangle clipped by the tet's four faces (inward normals), corners near a face snapped.
    Polygon poly;
    for (int c = 0; c < 3; ++c) poly.push_back(cm.points.row(cm.triangles(tri, c)).transpose());
    for (int k = 0; k < 4 && !poly.empty(); ++k) {
      const Eigen::Vector3d& a = p[(k + 1) % 4];
      Eigen::Vector3d inward = (p[(k + 2) % 4] - a).cross(p[(k + 3) % 4] - a).normalized();
      if (inward.dot(p[k] - a) < 0) inward = -inward;
      poly = keep_above(poly, a, inward, tolerance);
    }
    if (poly.size() < 3) continue;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& x : poly) centre += x;
    centre /= static_cast<double>(poly.size());
    bool on_face = false;
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d& a = p[(k + 1) % 4];
      const Eigen::Vector3d nf = (p[(k + 2) % 4] - a).cross(p[(k + 3) % 4] - a).normalized();
      on_face = on_face || std::abs(nf.dot(centre - a)) <= tolerance;
    }
    if (on_face) continue;
    const Eigen::Vector3d n = cut.unit_normal(tri);
    const double flux = area_vector(poly).norm() * n.dot(poly[0] - o) / 3.0;
    v[0] -= flux;
    v[1] += flux;
  }
  return v;
}

}  // namespace xfem
