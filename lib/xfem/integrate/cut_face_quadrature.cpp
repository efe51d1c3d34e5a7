// SPDX-License-Identifier: MIT
#include "xfem/integrate/cut_face_quadrature.h"

#include <algorithm>
#include <cmath>

#include "xfem/enrich/side_codes.h"
#include "xfem/geometry/cut_pieces.h"
#include "xfem/integrate/conforming_quadrature.h"

namespace xfem {
namespace {

const CutSurface* surface_of(const EnrichedMesh& em, int k) {
  return em.cuts.empty() ? em.cut.get() : em.cuts[static_cast<std::size_t>(k)].cut.get();
}

// The collapsed n x n Gauss rule of triangle (A, B, C), x = A + s (B - A) + s t (C - B), split
// into four (at the edges' midpoints) first, recursively up to `depth` times, while a front
// segment passes closer to it than its longest edge: F ~ sqrt(r) is nearly singular there.
void triangle_rule(const Eigen::Vector3d& A, const Eigen::Vector3d& B, const Eigen::Vector3d& C, int depth,
                   const std::vector<const FrontSegment*>& fronts, const std::vector<double>& nodes,
                   const std::vector<double>& weights, std::vector<Eigen::Vector3d>& x, std::vector<double>& w) {
  const double area2 = (B - A).cross(C - A).norm();
  if (!(area2 > 0.0)) return;
  if (depth > 0) {
    const double size = std::max({(B - A).norm(), (C - B).norm(), (A - C).norm()});
    const Eigen::Vector3d centre = (A + B + C) / 3;
    bool near = false;
    for (const FrontSegment* f : fronts) near = near || point_segment_distance(centre, f->p0, f->p1) < size;
    if (near) {
      const Eigen::Vector3d ab = (A + B) / 2, bc = (B + C) / 2, ca = (C + A) / 2;
      triangle_rule(A, ab, ca, depth - 1, fronts, nodes, weights, x, w);
      triangle_rule(ab, B, bc, depth - 1, fronts, nodes, weights, x, w);
      triangle_rule(ca, bc, C, depth - 1, fronts, nodes, weights, x, w);
      triangle_rule(ab, bc, ca, depth - 1, fronts, nodes, weights, x, w);
      return;
    }
  }
  // Corners on the front: there F ~ sqrt(r) is not smooth. With x = A + s (B - A) + s t (C - B) the
  // distance to a straight front through A is ~ s, through A and B ~ s t, through A and C
  // ~ s (1 - t), through B and C ~ 1 - s: the maps s = sigma^2, t = tau^2 (or 1 - ...) make sqrt(r)
  // polynomial, as the volume rule's collapse does (a fan from a front point, whose corner A lies
  // on the front, and the fan triangle along a front on the polygon's edge).
  bool on[3] = {false, false, false};
  const Eigen::Vector3d* corner[3] = {&A, &B, &C};
  const double size = std::max({(B - A).norm(), (C - B).norm(), (A - C).norm()});
  for (const FrontSegment* f : fronts)
    for (int k = 0; k < 3; ++k) on[k] = on[k] || point_segment_distance(*corner[k], f->p0, f->p1) <= 1e-9 * size;
  const int s_map = on[0] ? 1 : (on[1] && on[2]) ? 2 : 0;                       // s = sigma^2, s = 1 - sigma^2
  const int t_map = on[0] && on[1] && !on[2] ? 1 : on[0] && on[2] && !on[1] ? 2 : 0;  // t = tau^2, t = 1 - tau^2
  for (std::size_t i1 = 0; i1 < nodes.size(); ++i1)
    for (std::size_t i2 = 0; i2 < nodes.size(); ++i2) {
      const double sigma = nodes[i1], tau = nodes[i2];
      const double s = s_map == 1 ? sigma * sigma : s_map == 2 ? 1 - sigma * sigma : sigma;
      const double t = t_map == 1 ? tau * tau : t_map == 2 ? 1 - tau * tau : tau;
      const double ds = s_map ? 2 * sigma : 1.0, dt = t_map ? 2 * tau : 1.0;
      x.push_back(A + s * (B - A) + s * t * (C - B));
      w.push_back(weights[i1] * weights[i2] * area2 * s * ds * dt);
    }
}

// The segment where triangle f of the cut crosses the plane (point, unit normal); false if none.
bool crossing_segment(const CutSurface& cut, int f, const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                      double tolerance, Eigen::Vector3d& p, Eigen::Vector3d& q) {
  const TriangleMesh& cm = cut.mesh();
  std::array<Eigen::Vector3d, 3> v;
  std::array<double, 3> d;
  for (int k = 0; k < 3; ++k) {
    v[k] = cm.points.row(cm.triangles(f, k)).transpose();
    d[k] = normal.dot(v[k] - point);
    if (std::abs(d[k]) <= tolerance) d[k] = 0;
  }
  std::vector<Eigen::Vector3d> ends;
  for (int k = 0; k < 3; ++k) {
    const int l = (k + 1) % 3;
    if (d[k] == 0) ends.push_back(v[k]);
    if ((d[k] > 0 && d[l] < 0) || (d[k] < 0 && d[l] > 0)) ends.push_back(v[k] + d[k] / (d[k] - d[l]) * (v[l] - v[k]));
  }
  if (ends.size() != 2) return false;  // missing the plane, touching it at a corner, or lying in it
  p = ends[0];
  q = ends[1];
  return true;
}

// The points of the parts of tet face (A, B, C) (its corners in increasing node id order, `normal`
// its unit normal) that lie on the cut, made exactly as branch_gradient_integrals makes its face
// points (consistent_gradients.cpp, face_integrals): the face split by split_face, each part
// fanned from polygon_fan_apex over the fronts near the face. With the same points, the jump of
// N_l F_j that the stiffness's consistent shift integrates over the face and the one a load or a
// contact pressure integrates agree to round-off; another rule of the same polygon (the cut
// triangle clipped to the tet) differs by the rules' error of sqrt(r) next to a front on the
// polygon's edge (measured: 1.7e-5 of max |u| on the crack lying in a node layer of
// e2e.contact_closed). Appends (x, w, cut triangle) of every point.
void face_points_on_cut(const CutSurface& cut, const std::vector<const FrontSegment*>& fronts,
                        const std::vector<int>& meeting, const Eigen::Vector3d& A, const Eigen::Vector3d& B,
                        const Eigen::Vector3d& C, const Eigen::Vector3d& normal, int depth,
                        const std::vector<double>& nodes, const std::vector<double>& weights,
                        std::vector<Eigen::Vector3d>& x, std::vector<double>& w, std::vector<int>& triangle) {
  const FaceParts face = split_face(&cut, fronts, meeting, A, B, C, normal);
  const double face_tolerance = face.tolerance;
  const std::vector<const FrontSegment*>& face_fronts = face.fronts;
  const std::vector<Polygon>& parts = face.parts;
  std::vector<Eigen::Vector3d> px;
  std::vector<double> pw;
  for (const Polygon& part : parts) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& v : part) centre += v;
    centre /= static_cast<double>(part.size());
    const CutSurface::Closest near = cut.closest(centre);
    if (near.distance > face_tolerance) continue;  // off the cut (beyond its front): no face there
    polygon_gauss_rule(part, polygon_fan_apex(part, normal, face_fronts, face_tolerance), depth, face_fronts, nodes, weights, px, pw);
    for (std::size_t i = 0; i < px.size(); ++i) {
      x.push_back(px[i]);
      w.push_back(pw[i]);
      triangle.push_back(near.triangle);
    }
  }
}

}  // namespace

FaceParts split_face(const CutSurface* cut, const std::vector<const FrontSegment*>& fronts,
                     const std::vector<int>& meeting, const Eigen::Vector3d& A, const Eigen::Vector3d& B,
                     const Eigen::Vector3d& C, const Eigen::Vector3d& normal) {
  const double face_h = std::max({(B - A).norm(), (C - B).norm(), (A - C).norm()});
  const double face_tolerance = 1e-12 * face_h;
  FaceParts face;
  face.tolerance = face_tolerance;
  std::vector<Polygon>& parts = face.parts;
  parts = {{A, B, C}};
  std::vector<Polygon> next;
  Polygon above, below;
  for (const int tri : cut ? meeting : std::vector<int>{}) {
    Eigen::Vector3d p, q;
    if (!crossing_segment(*cut, tri, A, normal, face_tolerance, p, q)) continue;
    const Eigen::Vector3d cut_normal = cut->unit_normal(tri);
    const Eigen::Vector3d cut_point = cut->mesh().points.row(cut->mesh().triangles(tri, 0)).transpose();
    next.clear();
    for (const Polygon& part : parts) {
      split_polygon(part, cut_point, cut_normal, face_tolerance, above, below);
      if (above.size() >= 3 && below.size() >= 3 && segment_length_in_polygon(p, q, part, normal) > 1e-9 * face_h) {
        next.push_back(above);
        next.push_back(below);
      } else {
        next.push_back(part);
      }
    }
    parts.swap(next);
  }
  std::vector<const FrontSegment*>& face_fronts = face.fronts;
  const Eigen::Vector3d flo = A.cwiseMin(B).cwiseMin(C), fhi = A.cwiseMax(B).cwiseMax(C);
  for (const FrontSegment* segment : fronts)
    if ((segment->p0.cwiseMin(segment->p1).array() <= fhi.array() + face_tolerance).all() &&
        (segment->p0.cwiseMax(segment->p1).array() >= flo.array() - face_tolerance).all())
      face_fronts.push_back(segment);
  for (const FrontSegment* segment : face_fronts) {
    if (std::abs(normal.dot(segment->p0 - A)) > face_tolerance || std::abs(normal.dot(segment->p1 - A)) > face_tolerance) continue;
    const Eigen::Vector3d cutting = (segment->p1 - segment->p0).cross(normal).normalized();
    next.clear();
    for (const Polygon& part : parts) {
      split_polygon(part, segment->p0, cutting, face_tolerance, above, below);
      if (above.size() >= 3 && below.size() >= 3 && segment_length_in_polygon(segment->p0, segment->p1, part, normal) > 1e-9 * face_h) {
        next.push_back(above);
        next.push_back(below);
      } else {
        next.push_back(part);
      }
    }
    parts.swap(next);
  }
  return face;
}

int corner_off_face_holding(const TetCorners& p, const std::vector<Eigen::Vector3d>& polygon, double tol) {
  for (int skip = 0; skip < 4; ++skip) {
    const Eigen::Vector3d& a = p[(skip + 1) % 4];
    const Eigen::Vector3d n = (p[(skip + 2) % 4] - a).cross(p[(skip + 3) % 4] - a);
    if (n.norm() == 0) continue;
    const Eigen::Vector3d u = n.normalized();
    bool all = true;
    for (const Eigen::Vector3d& v : polygon) all = all && std::abs(u.dot(v - a)) <= tol;
    if (all) return skip;
  }
  return -1;
}

// Length of the segment (p, q) inside the convex polygon of unit normal `normal` (in its plane);
// -1 if it misses the polygon.
double segment_length_in_polygon(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Polygon& poly,
                                 const Eigen::Vector3d& normal) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& x : poly) centre += x;
  centre /= static_cast<double>(poly.size());
  double lo = 0.0, hi = 1.0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector3d& a = poly[i];
    Eigen::Vector3d m = normal.cross(poly[(i + 1) % poly.size()] - a);
    if (m.dot(centre - a) < 0) m = -m;  // inward, in the polygon's plane
    const double dp = m.dot(p - a), dq = m.dot(q - a);
    if (dp < 0 && dq < 0) return -1.0;
    if (dp < 0) lo = std::max(lo, dp / (dp - dq));
    if (dq < 0) hi = std::min(hi, dp / (dp - dq));
  }
  return hi >= lo ? (hi - lo) * (q - p).norm() : -1.0;
}

// Gauss points of the convex polygon, fanned from `apex` (a corner, or a point inside it) over its
// edges, each triangle by triangle_rule with the collapse at the apex. Positions and weights (m^2).
void polygon_gauss_rule(const Polygon& poly, const Eigen::Vector3d& apex, int depth, const std::vector<const FrontSegment*>& fronts,
                  const std::vector<double>& nodes, const std::vector<double>& weights, std::vector<Eigen::Vector3d>& x,
                  std::vector<double>& w) {
  x.clear();
  w.clear();
  for (std::size_t i = 0; i < poly.size(); ++i)
    triangle_rule(apex, poly[i], poly[(i + 1) % poly.size()], depth, fronts, nodes, weights, x, w);
}

// Where the integrand is singular in the polygon: a front segment piercing its inside (that
// point), else a corner on the front (the first found), else its first corner.
Eigen::Vector3d polygon_fan_apex(const Polygon& poly, const Eigen::Vector3d& normal, const std::vector<const FrontSegment*>& fronts,
                         double tolerance) {
  for (const FrontSegment* f : fronts) {
    const double d0 = normal.dot(f->p0 - poly[0]), d1 = normal.dot(f->p1 - poly[0]);
    if ((d0 > tolerance && d1 > tolerance) || (d0 < -tolerance && d1 < -tolerance) || d0 == d1) continue;
    if (std::abs(d0) <= tolerance && std::abs(d1) <= tolerance) continue;  // lying in the plane
    const Eigen::Vector3d p = f->p0 + d0 / (d0 - d1) * (f->p1 - f->p0);
    if (segment_length_in_polygon(p, p, poly, normal) >= 0) return p;
  }
  for (const Eigen::Vector3d& v : poly)
    for (const FrontSegment* f : fronts)
      if (point_segment_distance(v, f->p0, f->p1) <= tolerance) return v;
  return poly[0];
}


std::vector<const FrontSegment*> fronts_near(const CrackFront& front, const std::array<Eigen::Vector3d, 4>& corners,
                                             double tolerance) {
  Eigen::Vector3d lo = corners[0], hi = corners[0];
  for (const auto& x : corners) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  std::vector<const FrontSegment*> fronts;
  for (const FrontSegment& segment : front.segments())
    if ((segment.p0.cwiseMin(segment.p1).array() <= hi.array() + tolerance).all() &&
        (segment.p0.cwiseMax(segment.p1).array() >= lo.array() - tolerance).all())
      fronts.push_back(&segment);
  return fronts;
}

void cut_face_points(const EnrichedMesh& em, int t, int k, int order, std::vector<CutFacePoint>& out) {
  const CutSurface* cut = surface_of(em, k);
  // Not only the tets the cut splits: a tet with a face on the cut (a cut along a node layer) has
  // no volume above the cut, yet the tet below the cut carries the jump across that face.
  if (!cut || em.plain(t)) return;
  const CrackFront& front = em.cuts.empty() ? em.front : em.cuts[static_cast<std::size_t>(k)].front;
  TetCorners p;
  for (int c = 0; c < 4; ++c) p[c] = em.mesh.points.row(em.mesh.tets(t, c)).transpose();
  // As branch_gradient_integrals does (the same points): h, tolerance, the fronts near the tet.
  double h = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) h = std::max(h, (p[a] - p[b]).norm());
  const double tolerance = 1e-12 * h;
  const std::vector<const FrontSegment*> fronts = fronts_near(front, p, tolerance);
  // The face points of the consistent shift of the rule of this order (sampled_gradients).
  const int face_order = consistent_face_points(order);
  const int n = std::max(face_order, 2);
  const int depth = std::max(0, face_order - 3);
  const GaussRule01& gauss = gauss_legendre_rule_01(n);
  const std::vector<double>& nodes = gauss.nodes;
  const std::vector<double>& weights = gauss.weights;
  std::vector<Eigen::Vector3d> x;
  std::vector<double> w;
  const TriangleMesh& surface = cut->mesh();
  const std::vector<int> meeting = cut->triangles_meeting(p);
  std::vector<int> triangle;
  bool face_done[4] = {false, false, false, false};
  auto emit = [&](int tri) {
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (!(w[i] > 0)) continue;
      CutFacePoint q;
      q.tet = t;
      q.cut = k;
      q.triangle = tri >= 0 ? tri : triangle[i];
      q.x = x[i];
      q.normal = cut->unit_normal(q.triangle);
      q.weight = w[i];
      out.push_back(q);
    }
  };
  for (int tri : meeting) {
    const Polygon poly = clip_triangle(p, surface.points.row(surface.triangles(tri, 0)).transpose(),
                                       surface.points.row(surface.triangles(tri, 1)).transpose(),
                                       surface.points.row(surface.triangles(tri, 2)).transpose());
    if (!(polygon_area(poly) > 1e-10 * h * h)) continue;
    const Eigen::Vector3d normal = cut->unit_normal(tri);
    // A polygon in a face of the tet belongs to one of the two tets sharing that face: the one
    // below the cut. Classification puts the nodes on the cut above (side +1), so the tet above
    // may be uncut and carry no enriched DOF at all (a cut along a node layer), while the tet
    // below always sees both sides; counting it once there gives the face its whole area.
    const int off = corner_off_face_holding(p, poly, tolerance);
    if (off >= 0 && normal.dot(p[off] - poly[0]) > 0) continue;
    if (off >= 0) {
      // The whole face at once, with the stiffness's own face points (face_points_on_cut), once
      // however many cut triangles cover it.
      if (face_done[off]) continue;
      face_done[off] = true;
      std::array<int, 3> f;
      for (int c = 0, m = 0; c < 4; ++c)
        if (c != off) f[m++] = c;
      std::sort(f.begin(), f.end(), [&](int a, int b) { return em.mesh.tets(t, a) < em.mesh.tets(t, b); });
      const Eigen::Vector3d face_normal = (p[f[1]] - p[f[0]]).cross(p[f[2]] - p[f[0]]).normalized();
      x.clear();
      w.clear();
      triangle.clear();
      face_points_on_cut(*cut, fronts, meeting, p[f[0]], p[f[1]], p[f[2]], face_normal, depth, nodes, weights, x, w,
                         triangle);
      emit(-1);
      continue;
    }
    polygon_gauss_rule(poly, polygon_fan_apex(poly, normal, fronts, tolerance), depth, fronts, nodes, weights, x, w);
    emit(tri);
  }
}

std::vector<CutFacePoint> cut_face_points(const EnrichedMesh& em, int k, int order) {
  std::vector<CutFacePoint> out;
  for (int t = 0; t < em.tets(); ++t) cut_face_points(em, t, k, order, out);
  return out;
}

void basis_jump(const EnrichedMesh& em, int t, int k, const Eigen::Vector3d& x, Eigen::VectorXd& jump,
                BasisAt& scratch) {
  int above = 1, below = -1;
  if (!em.cuts.empty()) {
    // Side codes (side_codes.h): x's own side of every other cut, +1 / -1 of cut k.
    const int K = static_cast<int>(em.cuts.size());
    int sides[kMaxCuts];
    for (int j = 0; j < K; ++j) sides[j] = j == k ? 1 : em.cuts[static_cast<std::size_t>(j)].cut->side(x);
    above = pack_sides(sides, K);
    sides[k] = -1;
    below = pack_sides(sides, K);
  }
  enriched_basis(em, t, x, above, scratch);
  jump = scratch.N;
  enriched_basis(em, t, x, below, scratch);
  jump -= scratch.N;
}

}  // namespace xfem
