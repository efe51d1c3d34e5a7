// SPDX-License-Identifier: MIT
#include "xfem/integrate/straight_front_rule.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "xfem/core/mesh.h"
#include "xfem/enrich/branch_functions.h"
#include "xfem/enrich/side_codes.h"
#include "xfem/geometry/tet_shape.h"
#include "xfem/integrate/side_volumes.h"

namespace xfem {

namespace {

// Longest stretch in v (u = p sinh v) one Gauss rule covers: the integrand is analytic within
// |Im v| < pi / 2, so on stretches of this length the rule converges geometrically (ratio ~1/4.4
// per point pair).
constexpr double kStretch = 1.5;

// The farthest a tet's prisms may reach from its centroid, in longest edges (straight_front_rule).
constexpr double kReach = 100;

// The most a face's barycentric functions may reach at the front line (straight_front_face_integrals):
// a face at a grazing angle to the line has a thin shadow.
constexpr double kFaceReach = 1e4;

// Tets whose centroid lies farther than this many longest edges from the line keep the exact
// pieces (straight_front_rule).
constexpr double kFar = 2;

// The front's line near the tet: a point on it and the frame, xa = a . (x - O), xb = b . (x - O).
struct Line {
  Eigen::Vector3d origin, a, b, c;
  Eigen::Vector3d local(const Eigen::Vector3d& x) const {
    const Eigen::Vector3d d = x - origin;
    return Eigen::Vector3d(a.dot(d), b.dot(d), c.dot(d));
  }
};

double cross2(const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); }

// The front's line near the points x[0..count) (a tet's or a face's corners), when the front there
// is one straight line with one frame and every cut triangle meeting their box lies in the line's
// plane behind it: the nearest segment's line, a = b x c as CrackTipFrame. The front's own crack-tip
// coordinates are checked against the line's at the corners, the midpoints of each pair and the
// centroid (a curved front fails there, at the cost of those points), and every chain segment
// within reach (the centroid's distance to the front plus 2 longest edges) must lie on the line
// with the line's frame at both ends (so that the frame interpolated along it is the line's).
bool find_line(const CrackFront& front, const CutSurface* cut, const std::array<Eigen::Vector3d, 4>& box,
               const Eigen::Vector3d* x, int count, double h, Line& line) {
  const double tol = 1e-9 * h;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int i = 0; i < count; ++i) centre += x[i] / count;
  const FrontSegment& nearest = front.segments()[static_cast<std::size_t>(front.closest_segment(centre))];
  line.origin = nearest.p0;
  line.c = (nearest.p1 - nearest.p0).normalized();
  line.b = nearest.b;
  if (!(std::abs(line.b.dot(line.c)) <= 1e-12)) return false;
  line.a = line.b.cross(line.c);
  for (const int tri : cut ? cut->triangles_meeting(box) : std::vector<int>())
    for (int v = 0; v < 3; ++v) {
      const Eigen::Vector3d l = line.local(cut->mesh().points.row(cut->mesh().triangles(tri, v)).transpose());
      if (std::abs(l.y()) > tol || l.x() > tol) return false;
    }
  std::array<Eigen::Vector3d, 11> sample;
  int n = 0;
  for (int i = 0; i < count; ++i) {
    sample[n++] = x[i];
    for (int j = i + 1; j < count; ++j) sample[n++] = 0.5 * (x[i] + x[j]);
  }
  sample[n++] = centre;
  std::array<TipCoordinates, 11> code;
  front.coordinates(sample.data(), n, code.data());
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d l = line.local(sample[i]);
    if (std::abs(code[i].xa - l.x()) > tol || std::abs(code[i].xb - l.y()) > tol) return false;
    if ((code[i].grad.row(0).transpose() - line.a).norm() > 1e-9 || (code[i].grad.row(1).transpose() - line.b).norm() > 1e-9)
      return false;
  }
  // A point of the region lies within h of the centre, so its nearest front point (its foot's
  // segment) within the centre's distance + 2 h; the frames at both ends of every such segment
  // (averages with the neighbours') are checked. (Within xfem-sweep's element key: +3 h.)
  const double reach = point_segment_distance(centre, nearest.p0, nearest.p1) + 2 * h;
  for (const FrontPolyline& chain : front.chains()) {
    const int points = static_cast<int>(chain.points.size());
    for (int i = 0; i < chain.segments(); ++i) {
      const int j = (i + 1) % points;
      if (point_segment_distance(centre, chain.points[i], chain.points[j]) > reach) continue;
      const double arcs[2] = {chain.arc[i], j == 0 ? chain.length : chain.arc[j]};
      for (int e = 0; e < 2; ++e) {
        const Eigen::Vector3d l = line.local(chain.points[e == 0 ? i : j]);
        if (std::hypot(l.x(), l.y()) > tol) return false;
        Eigen::Vector3d c, b;
        chain.frame(arcs[e], c, b);
        if ((c - line.c).norm() > 1e-12 || (b - line.b).norm() > 1e-12) return false;
      }
    }
  }
  return true;
}

// Points for a stretch of length `span` in v: `most` for a stretch of kStretch, fewer for shorter
// ones. Gauss's error on an interval of half-length l for a function analytic in |Im v| < pi / 2
// falls like rho^-2n, rho = q + sqrt(q^2 + 1), q = (pi / 2) / l: the same accuracy with
// n = most log rho(kStretch / 2) / log rho(span / 2) points (an edge far from the front spans
// little angle and needs few).
int stretch_points(double span, int most) {
  auto log_rho = [](double half) {
    const double q = 0.5 * M_PI / std::max(half, 1e-300);
    return std::log(q + std::sqrt(q * q + 1));
  };
  const int n = static_cast<int>(std::ceil(most * log_rho(0.5 * kStretch) / log_rho(0.5 * span)));
  return std::min(most, std::max(2, n));
}

// The angle's points of the triangle (origin, A, B) of the (xi, eta) plane, for the integral
// int d theta int_0^rho_edge(theta) f rho d rho taken from A to B (negative when B is clockwise of
// A): visit(unit direction, rho_edge, side, d theta weight) per point. The edge is split where it
// crosses eta = 0 (the cut behind the front, theta = +-pi; theta = 0 ahead) and parametrized by
// u = p sinh v along it (p the origin's distance to its line), in which the integrand is analytic
// in a strip of half-width pi / 2 however close the line passes; stretches longer than kStretch in v
// are divided. An edge whose line holds the origin bounds no area: no points.
template <class Visit>
void edge_angles(const Eigen::Vector2d& A, const Eigen::Vector2d& B, int most, Visit&& visit) {
  const Eigen::Vector2d d = B - A;
  const double length = d.norm();
  if (length == 0) return;
  const Eigen::Vector2d dir = d / length;
  const double uA = A.dot(dir);
  const Eigen::Vector2d foot = A - uA * dir;
  const double p = foot.norm();
  if (p <= 1e-12 * std::max(A.norm(), B.norm())) return;
  const double turn = cross2(foot, dir) > 0 ? 1.0 : -1.0;  // sign of d theta / d u
  double ends[3] = {uA, uA + length, uA + length};
  int count = 2;
  if (dir.y() != 0) {
    const double u = -foot.y() / dir.y();
    if (u > uA + 1e-12 * length && u < uA + length - 1e-12 * length) ends[1] = u, ends[2] = uA + length, count = 3;
  }
  for (int s = 0; s + 1 < count; ++s) {
    const double u0 = ends[s], u1 = ends[s + 1];
    const int side = foot.y() + 0.5 * (u0 + u1) * dir.y() > 0 ? 1 : -1;
    const double v0 = std::asinh(u0 / p), v1 = std::asinh(u1 / p);
    const int pieces = std::max(1, static_cast<int>(std::ceil((v1 - v0) / kStretch)));
    for (int piece = 0; piece < pieces; ++piece) {
      const double va = v0 + (v1 - v0) * piece / pieces, span = (v1 - v0) / pieces;
      const int n = stretch_points(span, most);
      const GaussRule01& gauss = gauss_legendre_rule_01(n);
      const std::vector<double>&nodes = gauss.nodes, &weights = gauss.weights;
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        const double v = va + span * nodes[i];
        const Eigen::Vector2d X = foot + p * std::sinh(v) * dir;
        const double rho_edge = X.norm();
        visit(Eigen::Vector2d(X / rho_edge), rho_edge, side, turn * span * weights[i] / std::cosh(v));
      }
    }
  }
}

}  // namespace

int straight_front_angle_points(int order) { return order + 5; }

bool straight_front_rule(const EnrichedMesh& em, const CutElementSplits& splits, int t, int angle_points,
                         StraightFrontRule& out) {
  out.points.clear();
  out.tips.clear();
  out.negative_begin = 0;
  // The tet's branch cut (one, classify_cuts makes sure); with several cuts no other may meet the
  // tet (its sides there are then the tet centre's, as its pieces' codes; side_volumes checks).
  const int branch_cut = branch_cut_of_tet(em, t);
  const CrackFront& front = front_of_tet(em, t);
  const CutSurface* cut = cut_of_tet(em, t);
  if (branch_cut < 0 || !cut || front.empty() || angle_points < 1) return false;
  std::array<Eigen::Vector3d, 4> P;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k) {
    P[k] = em.mesh.points.row(em.mesh.tets(t, k)).transpose();
    centre += 0.25 * P[k];
  }
  double h = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) h = std::max(h, (P[i] - P[j]).norm());
  const double tol = 1e-9 * h;

  // 1. The line (find_line). Farther than kFar h from it the integrand is smooth on the tet's scale
  // and the exact pieces' rule is accurate (and cheaper: radius enrichment makes many such tets).
  Line line;
  if (!find_line(front, cut, P, P.data(), 4, h, line)) return false;
  const Eigen::Vector3d c_local = line.local(centre);
  if (c_local.head<2>().norm() > kFar * h) return false;
  int sides[kMaxCuts];  // each cut's side; the branch cut's entry is set per point
  const int cuts = static_cast<int>(em.cuts.size());
  for (int k = 0; k < cuts; ++k)
    if (k != branch_cut) {
      if (em.cuts[k].cut_class[t] != 0 || !em.cuts[k].cut->triangles_meeting(P).empty()) return false;
      sides[k] = em.cuts[k].cut->side(centre);
    }
  // A point's side: +-1 for one cut, the side code of its sides with several (side_codes.h).
  auto side_of = [&](int branch_side) {
    if (cuts == 0) return branch_side;
    sides[branch_cut] = branch_side;
    return pack_sides(sides, cuts);
  };

  // 2. The tet in the line's coordinates.
  std::array<Eigen::Vector3d, 4> L;
  std::array<Eigen::Vector2d, 4> q;
  for (int k = 0; k < 4; ++k) {
    L[k] = line.local(P[k]);
    q[k] = L[k].head<2>();
  }
  // The half-plane behind the front crossing the tet: only a cut tet (two regions) may hold it.
  bool crossed_behind = false;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if ((q[i].y() > tol && q[j].y() < -tol) || (q[i].y() < -tol && q[j].y() > tol)) {
        const double s = q[i].y() / (q[i].y() - q[j].y());
        crossed_behind = crossed_behind || q[i].x() + s * (q[j].x() - q[i].x()) < -tol;
      }
  const SideVolumes regions = side_volumes(em.mesh, splits, t);
  if (regions.size() > 2 || (regions.size() == 1 && crossed_behind)) return false;

  // 3. The faces not parallel to c (a face parallel to it has no shadow): each one's corners, its
  // outward normal's (a, b, c) components, for its plane zeta = Z(xi, eta), and the sign of its prism.
  // And how far the prisms reach: from zeta0 to each face's plane over its triangles (origin, edge),
  // so to Z(0, 0) on the line. The integrand grows like (reach / h)^2 there (N_l linear) and the
  // prisms' contributions cancel to the tet's: their angle sampling's error is amplified by about
  // (reach / h)^3. A tet whose faces reach beyond kReach h (far from the front, or a face at a
  // small angle to it) keeps the exact pieces; within, the angle gets a point more per factor ~19
  // of amplification (Gauss's rate on a stretch of kStretch).
  struct Face {
    int corner[3];
    Eigen::Vector3d n;
    double sign;
    double zeta(const std::array<Eigen::Vector3d, 4>& L, double xi, double eta) const {
      const Eigen::Vector3d& F0 = L[corner[0]];
      return F0.z() - (n.x() * (xi - F0.x()) + n.y() * (eta - F0.y())) / n.z();
    }
  };
  std::array<Face, 4> faces;
  int face_count = 0;
  double reach = std::max(h, c_local.head<2>().norm());
  for (int m = 0; m < 4; ++m) {
    Face& face = faces[face_count];
    for (int v = 0, k = 0; v < 4; ++v)
      if (v != m) face.corner[k++] = v;
    const int* f = face.corner;
    Eigen::Vector3d normal = (P[f[1]] - P[f[0]]).cross(P[f[2]] - P[f[0]]);
    if (normal.dot(P[m] - P[f[0]]) > 0) normal = -normal;  // outward
    const double nc = normal.dot(line.c) / normal.norm();
    if (std::abs(nc) <= 1e-12) continue;  // parallel to the line: no shadow
    if (std::abs(nc) < 1e-6) return false;  // nearly: its prism's height cancels in round-off
    face.n = Eigen::Vector3d(normal.dot(line.a), normal.dot(line.b), normal.dot(line.c));
    const double orient = cross2(q[f[1]] - q[f[0]], q[f[2]] - q[f[0]]) > 0 ? 1.0 : -1.0;
    face.sign = (nc > 0 ? 1.0 : -1.0) * orient;
    reach = std::max(reach, Eigen::Vector3d(-c_local.x(), -c_local.y(), face.zeta(L, 0, 0) - c_local.z()).norm());
    ++face_count;
  }
  if (reach > kReach * h) return false;
  const double amplification = std::pow(reach / h, 3);
  const int extra = static_cast<int>(std::ceil(std::log(amplification) / std::log(19.4)));

  // 4. The points: each face's prism, its shadow by the triangles (origin, edge).
  const int most = angle_points + std::max(0, extra);
  const GaussRule01 &rule_s = gauss_legendre_rule_01(4), &rule_t = gauss_legendre_rule_01(2);
  const std::vector<double>&gs = rule_s.nodes, &gsw = rule_s.weights, &gt = rule_t.nodes, &gtw = rule_t.weights;
  const double zeta0 = c_local.z();
  PointRule negative;
  std::vector<TipCoordinates> negative_tips;
  TipCoordinates tip;
  tip.grad.row(0) = line.a.transpose();
  tip.grad.row(1) = line.b.transpose();
  for (int i = 0; i < face_count; ++i) {
    const Face& face = faces[i];
    const int* f = face.corner;
    for (int e = 0; e < 3; ++e)
      edge_angles(q[f[e]], q[f[(e + 1) % 3]], most, [&](const Eigen::Vector2d& unit, double rho_edge, int side, double dtheta) {
        for (std::size_t is = 0; is < gs.size(); ++is) {
          const double sigma = gs[is], rho = rho_edge * sigma * sigma;
          const double radial = 2 * rho_edge * rho_edge * sigma * sigma * sigma * gsw[is];  // rho d rho
          const double xi = rho * unit.x(), eta = rho * unit.y();
          const double height = face.zeta(L, xi, eta) - zeta0;
          for (std::size_t it = 0; it < gt.size(); ++it) {
            const double w = face.sign * dtheta * radial * height * gtw[it];
            if (w == 0) continue;
            const double zeta = zeta0 + gt[it] * height;
            PointRule& to = w > 0 ? out.points : negative;
            to.x.push_back(line.origin + xi * line.a + eta * line.b + zeta * line.c);
            to.weights.push_back(w);
            to.side.push_back(side_of(side));
            tip.xa = xi;
            tip.xb = eta;
            (w > 0 ? out.tips : negative_tips).push_back(tip);
          }
        }
      });
  }
  out.negative_begin = out.points.size();
  out.points.x.insert(out.points.x.end(), negative.x.begin(), negative.x.end());
  out.points.weights.insert(out.points.weights.end(), negative.weights.begin(), negative.weights.end());
  out.points.side.insert(out.points.side.end(), negative.side.begin(), negative.side.end());
  out.tips.insert(out.tips.end(), negative_tips.begin(), negative_tips.end());

  // 5. The rule's volume on each side against the exact pieces' (two independent computations).
  const double volume = std::abs(tet_shape(em.mesh, t).volume);
  const int above_code = side_of(1), below_code = side_of(-1);
  double above = 0, below = 0;
  for (int i = 0; i < out.points.size(); ++i) (out.points.side[i] == above_code ? above : below) += out.points.weights[i];
  bool agree = std::abs(above + below - volume) <= 1e-9 * volume;
  if (regions.size() == 2)
    for (int r = 0; r < 2; ++r)
      agree = agree && (regions.side[r] == above_code || regions.side[r] == below_code) &&
              std::abs((regions.side[r] == above_code ? above : below) - regions.volume[r]) <= 1e-9 * volume;
  if (!agree) {
    out.points.clear();
    out.tips.clear();
    out.negative_begin = 0;
  }
  return agree;
}

bool straight_front_face_integrals(const CrackFront& front, const CutSurface* cut, const Eigen::Vector3d& A,
                                   const Eigen::Vector3d& B, const Eigen::Vector3d& C, int angle_points,
                                   Eigen::Matrix<double, 3, 4>& integral) {
  integral.setZero();
  if (front.empty() || angle_points < 1) return false;
  const std::array<Eigen::Vector3d, 3> P = {A, B, C};
  const double h = std::max({(B - A).norm(), (C - B).norm(), (A - C).norm()});
  const double tol = 1e-9 * h;
  Line line;
  if (!find_line(front, cut, {A, B, C, C}, P.data(), 3, h, line)) return false;
  std::array<Eigen::Vector3d, 3> L;
  for (int k = 0; k < 3; ++k) L[k] = line.local(P[k]);
  if (std::abs(L[0].y()) <= tol && std::abs(L[1].y()) <= tol && std::abs(L[2].y()) <= tol)
    return false;  // in the cut's plane: the sides' rule (face_points_on_cut) keeps its points
  Eigen::Vector3d normal = (B - A).cross(C - A);
  const double area2 = normal.norm();
  if (area2 == 0) return false;
  normal /= area2;
  const double nc = normal.dot(line.c);
  // As the tet's prisms (straight_front_rule, section 3): the triangles (origin, edge) reach the line,
  // where N_v extrapolates to |N_v(origin)|, by which the angle's error is amplified (up to kFaceReach).
  double amplification = 1;
  if (std::abs(nc) > 1e-6) {
    Eigen::Matrix2d J;
    J << (L[1] - L[0]).head<2>(), (L[2] - L[0]).head<2>();
    const Eigen::Vector2d st = J.inverse() * (-L[0].head<2>());
    const double most = std::max({std::abs(1 - st.x() - st.y()), std::abs(st.x()), std::abs(st.y()), 1.0});
    if (most > kFaceReach) return false;
    amplification = most;
  }
  const int most = angle_points + static_cast<int>(std::ceil(std::log(amplification) / std::log(19.4)));
  const GaussRule01 &rule_s = gauss_legendre_rule_01(4), &rule_t = gauss_legendre_rule_01(2);
  const std::vector<double>&gs = rule_s.nodes, &gsw = rule_s.weights, &gt = rule_t.nodes, &gtw = rule_t.weights;
  TipCoordinates tip;
  tip.grad.row(0) = line.a.transpose();
  tip.grad.row(1) = line.b.transpose();
  auto add = [&](double xi, double eta, const Eigen::Vector3d& barycentric, int side, double w) {
    tip.xa = xi;
    tip.xb = eta;
    const BranchValues F = branch_functions(tip, side);
    integral += w * barycentric * F.F.transpose();
  };
  if (std::abs(nc) > 1e-6) {
    // The face over its shadow on the (xi, eta) plane (dA = d shadow / |n . c|), the shadow by the
    // triangles (origin, edge) in polar coordinates: N_v sqrt(rho) rho d rho is a polynomial of
    // degree 6 in sigma (rho = rho_edge sigma^2), exact with 4 points.
    std::array<Eigen::Vector2d, 3> q;
    for (int k = 0; k < 3; ++k) q[k] = L[k].head<2>();
    Eigen::Matrix2d J;
    J << q[1] - q[0], q[2] - q[0];
    const Eigen::Matrix2d inverse = J.inverse();
    const double sign = J.determinant() > 0 ? 1.0 : -1.0;
    const double scale = sign / std::abs(nc);
    for (int e = 0; e < 3; ++e)
      edge_angles(q[e], q[(e + 1) % 3], most, [&](const Eigen::Vector2d& unit, double rho_edge, int side, double dtheta) {
        for (std::size_t is = 0; is < gs.size(); ++is) {
          const double sigma = gs[is];
          const Eigen::Vector2d x = rho_edge * sigma * sigma * unit;
          const Eigen::Vector2d st = inverse * (x - q[0]);
          add(x.x(), x.y(), Eigen::Vector3d(1 - st.x() - st.y(), st.x(), st.y()), side,
              scale * dtheta * 2 * rho_edge * rho_edge * sigma * sigma * sigma * gsw[is]);
        }
      });
    return true;
  }
  if (std::abs(nc) > 1e-12) return false;  // nearly parallel to the line: face_integrals' rule
  // A face containing the direction c: its shadow is a segment of a line l of the (xi, eta) plane.
  // In the face's orthonormal coordinates (s along l from the origin's foot on l, zeta), N_v is
  // linear and F depends on s alone: sqrt(rho(s)) f(theta(s)), rho = hypot(p, s). The triangle in
  // (s, zeta) is cut at its middle corner's s, where eta = 0 and (p = 0) at s = 0; each stretch in
  // u = p sinh v (p > 0) or |s| = w^2 (p = 0, l through the origin: F = sqrt(|s|) f), zeta by 2
  // Gauss points (N_v linear in it).
  Eigen::Vector2d dir = Eigen::Vector2d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if ((L[j].head<2>() - L[i].head<2>()).norm() > dir.norm()) dir = L[j].head<2>() - L[i].head<2>();
  if (dir.norm() <= tol) return false;
  dir.normalize();
  const Eigen::Vector2d foot = L[0].head<2>() - L[0].head<2>().dot(dir) * dir;
  const double p = foot.norm() <= tol ? 0.0 : foot.norm();
  std::array<Eigen::Vector2d, 3> sz;  // (s, zeta) of the corners
  for (int k = 0; k < 3; ++k) sz[k] = Eigen::Vector2d(L[k].head<2>().dot(dir), L[k].z());
  Eigen::Matrix2d J;
  J << sz[1] - sz[0], sz[2] - sz[0];
  if (J.determinant() == 0) return false;
  const Eigen::Matrix2d inverse = J.inverse();
  std::array<int, 3> order = {0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int i, int j) { return sz[i].x() < sz[j].x(); });
  const Eigen::Vector2d lo = sz[order[0]], mid = sz[order[1]], hi = sz[order[2]];
  auto zeta_on = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, double s) {
    return b.x() == a.x() ? a.y() : a.y() + (s - a.x()) / (b.x() - a.x()) * (b.y() - a.y());
  };
  std::vector<double> ends = {lo.x(), mid.x(), hi.x()};
  if (dir.y() != 0) ends.push_back(-foot.y() / dir.y());  // eta = 0 on l
  if (p == 0) ends.push_back(0.0);
  std::sort(ends.begin(), ends.end());
  for (std::size_t k = 0; k + 1 < ends.size(); ++k) {
    const double s0 = std::max(ends[k], lo.x()), s1 = std::min(ends[k + 1], hi.x());
    if (!(s1 > s0 + 1e-12 * h)) continue;
    const double smid = 0.5 * (s0 + s1);
    const int side = foot.y() + smid * dir.y() > 0 ? 1 : -1;
    // the stretch's nodes in s with their weights ds
    std::vector<std::pair<double, double>> nodes;
    if (p > 0) {
      const double v0 = std::asinh(s0 / p), v1 = std::asinh(s1 / p);
      const int pieces = std::max(1, static_cast<int>(std::ceil((v1 - v0) / kStretch)));
      const double span = (v1 - v0) / pieces;
      const GaussRule01& gauss = gauss_legendre_rule_01(stretch_points(span, angle_points));
      for (int piece = 0; piece < pieces; ++piece)
        for (std::size_t i = 0; i < gauss.nodes.size(); ++i) {
          const double v = v0 + span * (piece + gauss.nodes[i]);
          nodes.push_back({p * std::sinh(v), p * std::cosh(v) * span * gauss.weights[i]});
        }
    } else {
      const double sign = smid > 0 ? 1.0 : -1.0;
      const double w0 = std::sqrt(std::min(std::abs(s0), std::abs(s1))), w1 = std::sqrt(std::max(std::abs(s0), std::abs(s1)));
      // sqrt(|s|) N_v (zeta range) ds = polynomial of degree <= 6 in w: 4 points
      for (int i = 0; i < 4; ++i) {
        const double w = w0 + (w1 - w0) * gs[i];
        nodes.push_back({sign * w * w, 2 * w * (w1 - w0) * gsw[i]});
      }
    }
    for (const auto& [s, ds] : nodes) {
      const double upper = zeta_on(lo, hi, s), lower = s <= mid.x() ? zeta_on(lo, mid, s) : zeta_on(mid, hi, s);
      const Eigen::Vector2d x = foot + s * dir;
      for (std::size_t it = 0; it < gt.size(); ++it) {
        const double zeta = lower + gt[it] * (upper - lower);
        const Eigen::Vector2d st = inverse * (Eigen::Vector2d(s, zeta) - sz[0]);
        add(x.x(), x.y(), Eigen::Vector3d(1 - st.x() - st.y(), st.x(), st.y()), side, ds * std::abs(upper - lower) * gtw[it]);
      }
    }
  }
  return true;
}

}  // namespace xfem
