// SPDX-License-Identifier: MIT
#include "xfem/fracture/crack_face_rule.h"

#include <algorithm>
#include <cmath>

#include "xfem/core/mesh.h"
#include "xfem/geometry/cut_pieces.h"
#include "xfem/integrate/conforming_quadrature.h"
#include "xfem/integrate/cut_face_quadrature.h"

namespace xfem {
namespace {

// Whether the polygon's edge (p, q) runs along the front: its ends and midpoint within `tol` of it.
bool on_front(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const std::vector<const FrontSegment*>& fronts,
              double tol) {
  for (const Eigen::Vector3d& x : {p, q, Eigen::Vector3d(0.5 * (p + q))}) {
    bool near = false;
    for (const FrontSegment* f : fronts) near = near || point_segment_distance(x, f->p0, f->p1) <= tol;
    if (!near) return false;
  }
  return true;
}

}  // namespace

std::vector<CrackFacePoint> crack_face_rule(const EnrichedMesh& em, int order, const std::vector<char>& wanted) {
  std::vector<CrackFacePoint> out;
  if (!em.cut || em.cut_class.empty()) return out;
  const int n = std::max(order, 1);
  const GaussRule01& gauss = gauss_legendre_rule_01(n);
  const std::vector<double>& g = gauss.nodes;
  const std::vector<double>& gw = gauss.weights;
  const TriangleMesh& surface = em.cut->mesh();
  for (int t = 0; t < em.tets(); ++t) {
    if (em.plain(t)) continue;  // not only split tets: a face on the cut (cut_face_points)
    if (!wanted.empty() && !wanted[static_cast<std::size_t>(t)]) continue;
    TetCorners p;
    for (int c = 0; c < 4; ++c) p[c] = em.mesh.points.row(em.mesh.tets(t, c)).transpose();
    double h = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) h = std::max(h, (p[a] - p[b]).norm());
    const double tolerance = 1e-12 * h;
    const std::vector<const FrontSegment*> fronts = fronts_near(em.front, p, tolerance);
    for (int tri : em.cut->triangles_meeting(p)) {
      const Polygon poly = clip_triangle(p, surface.points.row(surface.triangles(tri, 0)).transpose(),
                                         surface.points.row(surface.triangles(tri, 1)).transpose(),
                                         surface.points.row(surface.triangles(tri, 2)).transpose());
      if (!(polygon_area(poly) > 1e-10 * h * h)) continue;
      const Eigen::Vector3d normal = em.cut->unit_normal(tri);
      // A polygon in a face of the tet counts once, in the tet below the cut (cut_face_points).
      const int off = corner_off_face_holding(p, poly, tolerance);
      if (off >= 0 && normal.dot(p[static_cast<std::size_t>(off)] - poly[0]) > 0) continue;
      // The apex: the corner with the most front edges (both of a corner of the front), else where
      // polygon_fan_apex puts the singularity (a front piercing the polygon, a corner on the front).
      const std::size_t m = poly.size();
      int best = -1, most = 0;
      for (std::size_t i = 0; i < m; ++i) {
        const int edges = on_front(poly[(i + m - 1) % m], poly[i], fronts, 1e-9 * h) +
                          on_front(poly[i], poly[(i + 1) % m], fronts, 1e-9 * h);
        if (edges > most) most = edges, best = static_cast<int>(i);
      }
      const Eigen::Vector3d apex = best >= 0 ? poly[static_cast<std::size_t>(best)]
                                             : polygon_fan_apex(poly, normal, fronts, tolerance);
      for (std::size_t i = 0; i < m; ++i) {
        const Eigen::Vector3d &B = poly[i], &C = poly[(i + 1) % m];
        const double area2 = (B - apex).cross(C - apex).norm();
        if (!(area2 > 1e-14 * h * h)) continue;  // a fan triangle on the apex's own edges
        for (std::size_t i1 = 0; i1 < g.size(); ++i1)
          for (int half = 0; half < 2; ++half)
            for (std::size_t i2 = 0; i2 < g.size(); ++i2) {
              // s = sigma^2 (ds = 2 sigma dsigma); t = tau^2 / 2 or 1 - tau^2 / 2 (|dt| = tau dtau).
              const double sg = g[i1], s = sg * sg, tau = g[i2];
              const double tt = half == 0 ? 0.5 * tau * tau : 1.0 - 0.5 * tau * tau;
              CrackFacePoint q;
              q.tet = t;
              q.x = apex + s * (B - apex) + s * tt * (C - B);
              q.normal = normal;
              q.weight = gw[i1] * gw[i2] * area2 * s * 2.0 * sg * tau;
              if (q.weight > 0) out.push_back(q);
            }
      }
    }
  }
  return out;
}

}  // namespace xfem
