// SPDX-License-Identifier: MIT
#include "xfem/geometry/cut_pieces.h"

#include <algorithm>
#include <cmath>

#include "xfem/core/error.h"
#include "xfem/core/mesh.h"

namespace xfem {
namespace {

double volume(const TetCorners& t) { return std::abs(signed_volume(t[0], t[1], t[2], t[3])); }

double longest_edge(const TetCorners& p) {
  double h = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) h = std::max(h, (p[i] - p[j]).norm());
  return h;
}

// The prism with triangles (a0, a1, a2) and (b0, b1, b2), a_i b_i its side edges, as 3 tets.
void add_prism(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1, const Eigen::Vector3d& a2,
               const Eigen::Vector3d& b0, const Eigen::Vector3d& b1, const Eigen::Vector3d& b2,
               std::vector<TetCorners>& out) {
  out.push_back({a0, a1, a2, b0});
  out.push_back({a1, a2, b0, b1});
  out.push_back({a2, b0, b1, b2});
}

}  // namespace

void split_by_plane(const TetCorners& p, const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                    double tolerance, std::vector<TetCorners>& above, std::vector<TetCorners>& below) {
  double d[4];
  std::vector<int> pos, neg, zero;
  for (int k = 0; k < 4; ++k) {
    d[k] = normal.dot(p[k] - point);
    if (d[k] > tolerance) pos.push_back(k);
    else if (d[k] < -tolerance) neg.push_back(k);
    else zero.push_back(k);
  }
  if (neg.empty()) return above.push_back(p);
  if (pos.empty()) return below.push_back(p);
  // The point where the plane crosses edge (i, j), i and j strictly on opposite sides.
  auto x = [&](int i, int j) -> Eigen::Vector3d { return p[i] + d[i] / (d[i] - d[j]) * (p[j] - p[i]); };
  if (pos.size() == 1 && neg.size() == 1) {  // two corners on the plane: two tets
    const Eigen::Vector3d c = x(pos[0], neg[0]);
    above.push_back({p[pos[0]], c, p[zero[0]], p[zero[1]]});
    below.push_back({p[neg[0]], c, p[zero[0]], p[zero[1]]});
    return;
  }
  const bool lone_above = pos.size() == 1;
  std::vector<TetCorners>& lone_out = lone_above ? above : below;
  std::vector<TetCorners>& rest_out = lone_above ? below : above;
  if (zero.size() == 1) {  // one corner Z on the plane: a tet at the lone corner L, a pyramid with apex Z
    const int L = lone_above ? pos[0] : neg[0];
    const std::vector<int>& rest = lone_above ? neg : pos;
    const int Z = zero[0], O1 = rest[0], O2 = rest[1];
    const Eigen::Vector3d x1 = x(L, O1), x2 = x(L, O2);
    lone_out.push_back({p[L], x1, x2, p[Z]});
    rest_out.push_back({p[Z], p[O1], p[O2], x2});  // base O1 O2 x2 x1 (a planar quad in face L O1 O2)
    rest_out.push_back({p[Z], p[O1], x2, x1});
    return;
  }
  if (pos.size() == 2) {  // two and two: two prisms
    const int P0 = pos[0], P1 = pos[1], Q0 = neg[0], Q1 = neg[1];
    const Eigen::Vector3d e00 = x(P0, Q0), e01 = x(P0, Q1), e10 = x(P1, Q0), e11 = x(P1, Q1);
    add_prism(p[P0], e00, e01, p[P1], e10, e11, above);
    add_prism(p[Q0], e00, e10, p[Q1], e01, e11, below);
    return;
  }
  // One corner alone on its side: a tet at it, a prism between the plane and the other three.
  const int L = lone_above ? pos[0] : neg[0];
  const std::vector<int>& rest = lone_above ? neg : pos;
  const Eigen::Vector3d x0 = x(L, rest[0]), x1 = x(L, rest[1]), x2 = x(L, rest[2]);
  lone_out.push_back({p[L], x0, x1, x2});
  add_prism(x0, x1, x2, p[rest[0]], p[rest[1]], p[rest[2]], rest_out);
}

std::vector<Eigen::Vector3d> clip_triangle(const TetCorners& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                           const Eigen::Vector3d& c) {
  std::vector<Eigen::Vector3d> poly{a, b, c}, next;
  static const int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  for (int k = 0; k < 4 && !poly.empty(); ++k) {
    // Keep the side of face k where the opposite corner k lies (Sutherland-Hodgman).
    const Eigen::Vector3d& x0 = p[kFaces[k][0]];
    Eigen::Vector3d n = (p[kFaces[k][1]] - x0).cross(p[kFaces[k][2]] - x0);
    if (n.dot(p[k] - x0) < 0) n = -n;
    next.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Eigen::Vector3d& u = poly[i];
      const Eigen::Vector3d& v = poly[(i + 1) % poly.size()];
      const double du = n.dot(u - x0), dv = n.dot(v - x0);
      if (du >= 0) next.push_back(u);
      if ((du >= 0) != (dv >= 0)) next.push_back(u + du / (du - dv) * (v - u));
    }
    poly.swap(next);
  }
  return poly;
}

double polygon_area(const std::vector<Eigen::Vector3d>& polygon) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) sum += (polygon[i] - polygon[0]).cross(polygon[i + 1] - polygon[0]);
  return 0.5 * sum.norm();
}

CutPieces split_by_cut(const TetCorners& p, const CutSurface& cut) {
  return split_by_cut(p, cut, cut.triangles_meeting(p));
}

namespace {

// The length of segment (a, b) inside the closed tet p, its ends allowed `tolerance` outside;
// -1 if the segment misses p (0 if it only touches it).
double length_inside(const TetCorners& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tolerance) {
  static const int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d& x0 = p[kFaces[k][0]];
    Eigen::Vector3d n = (p[kFaces[k][1]] - x0).cross(p[kFaces[k][2]] - x0);
    const double norm = n.norm();
    if (norm == 0.0) return -1.0;
    n /= norm;
    if (n.dot(p[k] - x0) < 0) n = -n;  // inward
    const double da = n.dot(a - x0) + tolerance, db = n.dot(b - x0) + tolerance;
    if (da < 0 && db < 0) return -1.0;
    if (da < 0) lo = std::max(lo, da / (da - db));
    if (db < 0) hi = std::min(hi, da / (da - db));
  }
  return hi >= lo ? (hi - lo) * (b - a).norm() : -1.0;
}

// Splits every piece the plane (point, normal) crosses for which `splits(piece)` holds.
template <class Predicate>
void split_pieces(std::vector<TetCorners>& pieces, const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                  double tolerance, Predicate splits) {
  std::vector<TetCorners> next, above, below;
  for (const TetCorners& q : pieces) {
    above.clear();
    below.clear();
    split_by_plane(q, point, normal, tolerance, above, below);
    if (above.empty() || below.empty() || !splits(q)) {
      next.push_back(q);
      continue;
    }
    next.insert(next.end(), above.begin(), above.end());
    next.insert(next.end(), below.begin(), below.end());
  }
  pieces.swap(next);
  if (pieces.size() > 100000)
    throw Error("splitting a tet along the cut: more than 100000 pieces (the cut has too many triangles inside one element)");
}

// The pieces of p split by the plane of every cut triangle that passes through their inside.
std::vector<TetCorners> split_by_triangles(const TetCorners& p, const CutSurface& cut, const std::vector<int>& triangles) {
  const double tolerance = 1e-12 * longest_edge(p);
  const double area_tolerance = 1e-10 * longest_edge(p) * longest_edge(p);
  const TriangleMesh& cm = cut.mesh();
  std::vector<TetCorners> pieces{p};
  for (const int f : triangles) {
    const Eigen::Vector3d a = cm.points.row(cm.triangles(f, 0)).transpose();
    const Eigen::Vector3d b = cm.points.row(cm.triangles(f, 1)).transpose();
    const Eigen::Vector3d c = cm.points.row(cm.triangles(f, 2)).transpose();
    // Only a triangle that passes through the inside of the piece splits it (its plane may cross
    // pieces the triangle misses, e.g. beyond a fold, or only touches along a face: a cut
    // ending exactly on a face).
    split_pieces(pieces, a, cut.unit_normal(f), tolerance,
                 [&](const TetCorners& q) { return polygon_area(clip_triangle(q, a, b, c)) > area_tolerance; });
  }
  return pieces;
}

// The pieces with their sides (CutSurface::side at the centroid, which lies strictly inside a
// piece), dropping those of round-off volume. The centroids of one tet's pieces lie close
// together: the cut's searches for them start each from the previous one's closest point
// (CutSurface::sides), which prunes the search tree at once.
CutPieces sided(const std::vector<TetCorners>& pieces, const CutSurface& cut, double whole) {
  CutPieces out;
  std::vector<double> volumes;
  std::vector<Eigen::Vector3d> centroids;
  for (const TetCorners& q : pieces) {
    const double v = volume(q);
    if (!(v > 1e-14 * whole)) continue;
    out.tets.push_back(q);
    volumes.push_back(v);
    centroids.push_back(0.25 * (q[0] + q[1] + q[2] + q[3]));
  }
  out.side.resize(out.tets.size());
  cut.sides(centroids.data(), static_cast<int>(centroids.size()), out.side.data());
  for (std::size_t i = 0; i < out.tets.size(); ++i) (out.side[i] > 0 ? out.volume_above : out.volume_below) += volumes[i];
  return out;
}

}  // namespace

CutPieces split_at_front(const TetCorners& p, const CutSurface& cut, const std::vector<int>& triangles,
                         const std::vector<FrontSegment>& front) {
  const double whole = volume(p), h = longest_edge(p);
  const double tolerance = 1e-12 * h;
  std::vector<TetCorners> pieces = split_by_triangles(p, cut, triangles);
  for (const FrontSegment& s : front) {
    if (!(length_inside(p, s.p0, s.p1, tolerance) > 1e-9 * h)) continue;
    const Eigen::Vector3d along = s.p1 - s.p0;
    const Eigen::Vector3d normal = along.cross(s.b).normalized();
    // Every piece the front meets, even at one point: a piece touching the cut along one edge
    // would otherwise reach from behind the front to ahead of it.
    split_pieces(pieces, s.p0, normal, tolerance,
                 [&](const TetCorners& q) { return length_inside(q, s.p0, s.p1, tolerance) >= 0; });
  }
  return sided(pieces, cut, whole);
}

CutPieces split_by_cut(const TetCorners& p, const CutSurface& cut, const std::vector<int>& triangles) {
  const double whole = volume(p);
  const std::vector<TetCorners> pieces = split_by_triangles(p, cut, triangles);
  return sided(pieces, cut, whole);
}

}  // namespace xfem
