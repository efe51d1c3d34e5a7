// SPDX-License-Identifier: MIT
#include "xfem/integrate/conforming_quadrature.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "xfem/integrate/consistent_gradients.h"
#include "xfem/enrich/enriched_basis.h"
#include "xfem/enrich/split_by_cuts.h"
#include "xfem/core/error.h"
#include "xfem/geometry/tet_shape.h"

namespace xfem {
namespace {

// A vertex this close to the front (relative to the tet's longest edge) lies on it: the split's
// front points come from inexact constructions, so exact zero is not expected.
constexpr double kOnFront = 1e-6;

// A tet part is bisected while the front is nearer to it than kNear times its length, at most
// kMaxLevels times (a front through an edge's interior would otherwise split it forever; fewer for
// low orders, see append_tet_rule). A tet
// without a vertex on the front (blending elements, pieces of completely cut ones) is split only
// while the front is nearer than kNearFar times its longest edge, at most kMaxLevelsFar times: its
// integrand is bounded, and splitting every tet within one size of the front costs 20x the points.
// (kNearFar is TetRuleLayout::far_split_ratio's default.)
constexpr double kNear = 1.0;
constexpr int kMaxLevels = 8;
constexpr int kMaxLevelsFar = 8;

// A front touching an edge this close to one of its ends (as a fraction of the edge) counts as
// touching at that end: no split into a sliver.
constexpr double kTouchMargin = 1e-3;

// At most this many bisections by angle (TetRuleLayout::max_angle) from a piece: two bring a span
// of nearly two right angles under one; more would only multiply the points of pieces beyond an
// open front's end, where the angle around it is not defined.
constexpr int kMaxAngleSplits = 2;

// Where the front touches the edge pq, as the fraction t along pq of the point of pq closest to
// the front's nearest segment; -1 when the front stays farther than `within` from pq, runs parallel
// to it, or touches it within `margin` of an end.
double front_touch(const CrackFront& front, const CrackFront::Near& near, const Eigen::Vector3d& p,
                   const Eigen::Vector3d& q, double within, double margin) {
  const Eigen::Vector3d d1 = q - p;
  double best = std::numeric_limits<double>::infinity(), at = -1;
  for (const int k : near.segments) {
    const FrontSegment& f = front.segments()[k];
    // The closest points of the segments p + s d1 and f.p0 + u d2 (Ericson, Real-Time Collision
    // Detection 5.1.9), both parameters clamped to [0, 1].
    const Eigen::Vector3d d2 = f.p1 - f.p0, r = p - f.p0;
    const double a = d1.squaredNorm(), e = d2.squaredNorm(), b = d1.dot(d2), c = d1.dot(r), g = d2.dot(r);
    const double denom = a * e - b * b;
    if (!(a > 0) || !(e > 0) || !(denom > 1e-12 * a * e)) continue;  // parallel: not a point touch
    double s = std::clamp((b * g - c * e) / denom, 0.0, 1.0);
    double u = (b * s + g) / e;
    if (u < 0) u = 0, s = std::clamp(-c / a, 0.0, 1.0);
    else if (u > 1) u = 1, s = std::clamp((b - c) / a, 0.0, 1.0);
    const double dist = (p + s * d1 - f.p0 - u * d2).norm();
    if (dist < best) best = dist, at = s;
  }
  if (!(best <= within) || at < margin || at > 1 - margin) return -1;
  return at;
}

// The angle that the segment between two points spans around the front, seen from it (radians, in
// [0, pi]): the angle between their crack-tip coordinates (xa, xb). For an edge rule on the front it
// is the range of the angle variable, in which the branch functions vary like cos(theta / 2) and
// sin(3 theta / 2).
double angle_around_front(const TipCoordinates& a, const TipCoordinates& b) {
  return std::atan2(std::abs(a.xa * b.xb - a.xb * b.xa), a.xa * b.xa + a.xb * b.xb);
}

}  // namespace

void gauss_legendre_01(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  if (n < 1 || n > 64) throw Error("Gauss-Legendre rule: order must be in 1..64, got " + std::to_string(n));
  nodes.assign(n, 0.0);
  weights.assign(n, 0.0);
  const double pi = std::acos(-1.0);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    // Newton on P_n from the Chebyshev-like guess; p1 = P_n(z), dp = P_n'(z).
    double z = std::cos(pi * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p1 = 1.0, p2 = 0.0;
      for (int j = 1; j <= n; ++j) {
        const double p3 = p2;
        p2 = p1;
        p1 = ((2.0 * j - 1.0) * z * p2 - (j - 1.0) * p3) / j;
      }
      dp = n * (z * p1 - p2) / (z * z - 1.0);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    const double w = 1.0 / ((1.0 - z * z) * dp * dp);  // half the [-1, 1] weight: maps to [0, 1]
    nodes[i] = 0.5 * (1.0 - z);
    nodes[n - 1 - i] = 0.5 * (1.0 + z);
    weights[i] = weights[n - 1 - i] = w;
  }
}

const GaussRule01& gauss_legendre_rule_01(int n) {
  if (n < 1 || n > 64) throw Error("Gauss-Legendre rule: order must be in 1..64, got " + std::to_string(n));
  // Made on first use, every order at once (a static's initialisation is thread-safe).
  static const std::vector<GaussRule01> rules = [] {
    std::vector<GaussRule01> all(65);
    for (int k = 1; k <= 64; ++k) gauss_legendre_01(k, all[k].nodes, all[k].weights);
    return all;
  }();
  return rules[static_cast<std::size_t>(n)];
}

void append_edge_rule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                      const Eigen::Vector3d& d, int n, int side, PointRule& out) {
  append_edge_rule(a, b, c, d, n, n, n, side, out);
}

void append_edge_rule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                      const Eigen::Vector3d& d, int radial, int along, int across, int side, PointRule& out,
                      bool squared) {
  const GaussRule01 &rule_radial = gauss_legendre_rule_01(radial), &rule_along = gauss_legendre_rule_01(along),
                    &rule_across = gauss_legendre_rule_01(across);
  const std::vector<double>&g = rule_radial.nodes, &gw = rule_radial.weights;
  const std::vector<double>&ga = rule_along.nodes, &gaw = rule_along.weights;
  const std::vector<double>&gc = rule_across.nodes, &gcw = rule_across.weights;
  // |det(b-a, c-a, d-c)| = 6 V: the volume is the integral of 6 V s (1-s) over the unit cube.
  const double six_v = std::abs((b - a).cross(c - a).dot(d - c));
  for (int i = 0; i < radial; ++i) {
    const double sigma = g[i], s = squared ? sigma * sigma : sigma;
    // ds = 2 sigma dsigma (squared), else ds = dsigma
    const double r = squared ? gw[i] * 2.0 * sigma * s * (1.0 - s) * six_v : gw[i] * s * (1.0 - s) * six_v;
    for (int j = 0; j < along; ++j) {
      const Eigen::Vector3d on_ab = a + ga[j] * (b - a);
      for (int k = 0; k < across; ++k) {
        out.x.push_back((1.0 - s) * on_ab + s * (c + gc[k] * (d - c)));
        out.weights.push_back(r * gaw[j] * gcw[k]);
        out.side.push_back(side);
      }
    }
  }
}

void append_vertex_rule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                        const Eigen::Vector3d& d, int n, int side, PointRule& out) {
  append_vertex_rule(a, b, c, d, n, n, side, out);
}

void append_vertex_rule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                        const Eigen::Vector3d& d, int radial, int across, int side, PointRule& out) {
  const GaussRule01 &rule_radial = gauss_legendre_rule_01(radial), &rule_across = gauss_legendre_rule_01(across);
  const std::vector<double>&g = rule_radial.nodes, &gw = rule_radial.weights;
  const std::vector<double>&gc = rule_across.nodes, &gcw = rule_across.weights;
  const double six_v = std::abs((b - a).cross(c - a).dot(d - a));
  for (int i = 0; i < radial; ++i) {
    const double sigma = g[i], u = sigma * sigma;
    const double r = gw[i] * 2.0 * sigma * u * u * six_v;  // u^2 du, du = 2 sigma dsigma
    for (int j = 0; j < across; ++j) {
      const double v = gc[j];
      for (int k = 0; k < across; ++k) {
        out.x.push_back(a + u * (b - a) + u * v * (c - b) + u * v * gc[k] * (d - c));
        out.weights.push_back(r * v * gcw[j] * gcw[k]);
        out.side.push_back(side);
      }
    }
  }
}

TetRuleLayout TetRuleLayout::uniform(int n) {
  TetRuleLayout l;
  l.radial = l.along = l.across = l.far = l.distant = n;
  // Bisection pays only when the Gauss rule itself is accurate: the depth grows with the order
  // (order 3, the default: 1 level at the front, none away from it; order 7 and up: 8 and 8).
  l.near_levels = std::min(kMaxLevels, (n - 2) * (n - 2));
  l.far_levels = std::min(kMaxLevelsFar, std::max(0, 2 * (n - 3)));
  l.split_at_touch = false;
  return l;
}

TetRuleLayout TetRuleLayout::of_order(int n) {
  TetRuleLayout l = uniform(n);
  l.split_at_touch = true;
  // The branch functions vary with the angle around the front like sin(3 theta / 2): a piece at the
  // front spanning more than a right angle is bisected (ahead of the front nothing else splits it:
  // the cut's triangles stop at the front).
  l.max_angle = std::acos(-1.0) / 2;
  // At least 2 points along the front and 3 in the angle: with 1 and 2 (order 3 until issue 35's
  // eleventh part) the pieces at the front held the beam's worst tets and its opening behind the
  // front was 0.2-0.4 % off order 8 (docs/PERFORMANCE.md).
  l.along = std::max(2, n - 2);
  l.across = std::max(3, n - 1);
  l.far = n + 1;
  l.far_squared = false;
  l.distant = std::max(2, n - 1);
  l.distant_ratio = 1.0;
  if (n <= 3) {
    l.near_levels = l.far_levels = 0;
    // Beyond one longest edge from the front the symmetric 4-point rule (degree 2) instead of the
    // collapsed 2^3: as accurate there, and it pays for the points added at the front.
    l.remote = 4;
    l.remote_ratio = 1.0;
    l.remote_symmetric = true;
    // The slivers of a cut much finer than the tets (organ S: 84 % of its points on pieces away from
    // the front): the symmetric 4-point rule where it may err by at most 1 % of the tet's scale.
    l.small_piece_fraction = 1e-2;
  }
  return l;
}

int consistent_face_points(int order) { return order + 1; }

void append_symmetric_tet_rule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                               const Eigen::Vector3d& d, int points, int side, PointRule& out) {
  const double volume = std::abs((b - a).cross(c - a).dot(d - a)) / 6.0;
  // Orbits of barycentric coordinates: (alpha, alpha, alpha, 1 - 3 alpha) x 4 and
  // (alpha, alpha, 1/2 - alpha, 1/2 - alpha) x 6, weights relative to the volume.
  auto add = [&](double l0, double l1, double l2, double l3, double w) {
    out.x.push_back(l0 * a + l1 * b + l2 * c + l3 * d);
    out.weights.push_back(w * volume);
    out.side.push_back(side);
  };
  auto orbit4 = [&](double alpha, double w) {
    const double o = 1.0 - 3.0 * alpha;
    add(o, alpha, alpha, alpha, w);
    add(alpha, o, alpha, alpha, w);
    add(alpha, alpha, o, alpha, w);
    add(alpha, alpha, alpha, o, w);
  };
  auto orbit6 = [&](double alpha, double w) {
    const double o = 0.5 - alpha;
    add(alpha, alpha, o, o, w);
    add(alpha, o, alpha, o, w);
    add(alpha, o, o, alpha, w);
    add(o, alpha, alpha, o, w);
    add(o, alpha, o, alpha, w);
    add(o, o, alpha, alpha, w);
  };
  if (points == 4) {
    orbit4(0.1381966011250105, 0.25);  // (5 - sqrt 5) / 20
  } else if (points == 14) {
    orbit4(0.0927352503108912, 0.07349304311636196);
    orbit4(0.3108859192633006, 0.1126879257180159);
    orbit6(0.0455037041256496, 0.04254602077708147);
  } else {
    throw Error("symmetric tet rule: 4 or 14 points, got " + std::to_string(points));
  }
}

TetRuleLayout TetRuleLayout::fast() {
  // Measured against order 8 (docs/PERFORMANCE.md "The fast rule"): beyond half an edge the 14-point
  // rule (degree 5) is as close as the default's 64 and 8 collapsed points; a collapsed 3^3 rule
  // there (degree 3 across the collapse) was 4.5x farther in the median on the beam.
  TetRuleLayout l = of_order(3);
  l.remote = 14;
  l.remote_ratio = 0.5;
  l.remote_symmetric = true;
  return l;
}

TetRuleLayout TetRuleLayout::graded() {
  // The rule of order 3 with the front's pieces resolved further (measured on the beam's openings
  // against order 8, docs/PERFORMANCE.md): one bisection of the pieces with a vertex on the front
  // that the front passes close to; one bisection of the pieces without a vertex on it while the
  // front is nearer than half their size. (Its third point in the angle is the default's since the
  // eleventh part of issue 35.)
  TetRuleLayout l = of_order(3);
  l.near_levels = 1;
  l.far_levels = 1;
  return l;
}

namespace {

// append_tet_rule at subdivision depth `level`: a tet whose integrand is nearly singular (the front
// passes close to, but not through, the part the Gauss points resolve) is bisected at the midpoint
// of the edge concerned, the halves keeping the vertices on the front, until the front is at least
// as far as that part is long. Gauss rules converge like rho^-2n with rho growing with that ratio.
// `near`: the front's segments near a region holding p (CrackFront::near), for its distances.
// `budget` (m^2, 0: none): the error a piece away from the front may leave (small_piece_fraction).
void append_tet_rule(const std::array<Eigen::Vector3d, 4>& p, const CrackFront& front, const CrackFront::Near& near,
                     const TetRuleLayout& layout, int side, PointRule& out, int level, double budget,
                     int angle_splits = 0) {
  static const int kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  auto opposite = [](int i, int j, int& k, int& l) {
    k = -1;
    for (int m = 0; m < 4; ++m)
      if (m != i && m != j) (k < 0 ? k : l) = m;
  };
  // The tet with vertex i replaced by the point x of edge (i, j), and with vertex j replaced, each
  // with `halves_angle_splits` bisections by angle behind it.
  auto split_edge = [&](int i, int j, const Eigen::Vector3d& x, int halves_angle_splits) {
    std::array<Eigen::Vector3d, 4> q = p;
    q[i] = x;
    append_tet_rule(q, front, near, layout, side, out, level + 1, budget, halves_angle_splits);
    q = p;
    q[j] = x;
    append_tet_rule(q, front, near, layout, side, out, level + 1, budget, halves_angle_splits);
  };
  // ... at the midpoint of the edge.
  auto bisect = [&](int i, int j, int angle_split = 0) {
    split_edge(i, j, 0.5 * (p[i] + p[j]), angle_splits + angle_split);
  };
  // Bisections by angle (max_angle) stop after kMaxAngleSplits: beyond an open front's end the angle
  // around it is not defined (every direction meets its extension), and no bisection narrows it.
  const bool may_split_angle = layout.max_angle > 0 && level < kMaxLevels && angle_splits < kMaxAngleSplits;
  const bool may_split = level < layout.near_levels;
  int best = 0, n = layout.far;
  if (!front.empty()) {
    double longest = 0;
    for (const auto& e : kEdges) longest = std::max(longest, (p[e[0]] - p[e[1]]).norm());
    int on[4], count = 0;
    double corner_distance[4];
    for (int m = 0; m < 4; ++m)
      if ((corner_distance[m] = front.distance(p[m], near)) <= kOnFront * longest) on[count++] = m;
    if (layout.split_at_touch && count < 2 && level < kMaxLevels) {
      // The front touches an edge at an interior point, not at a vertex of this piece (e.g. a tet
      // beside the cut whose edge the front pierces, on a mesh with nodes in the front's plane): the
      // integrand is singular at that point, which no rule collapsed onto a whole edge resolves.
      // Split the edge there: in both halves the point is a vertex on the front (the vertex rule's
      // collapse; with a vertex of the piece already on the front, the edge rule's edge).
      for (const auto& e : kEdges) {
        const int i = e[0], j = e[1];
        if (count == 1 && (on[0] == i || on[0] == j)) continue;
        const double t = front_touch(front, near, p[i], p[j], kOnFront * longest, kTouchMargin);
        if (t < 0) continue;
        return split_edge(i, j, p[i] + t * (p[j] - p[i]), 0);  // the halves' angle bisections start afresh
      }
    }
    if (count == 1) {
      // Singular at vertex a; nearly singular in the direction of the face opposite it when the
      // front line passes close to that face: split the face's longest edge.
      int j = on[0] == 0 ? 1 : 0, k = -1, l = -1;
      opposite(on[0], j, k, l);
      if (may_split) {  // the distances only decide a bisection
        const int face[3] = {j, k, l};
        double h = std::numeric_limits<double>::infinity(), edge = 0;
        int e0 = 0, e1 = 1;
        for (int x = 0; x < 3; ++x) {
          const int u = face[x], v = face[(x + 1) % 3];
          h = std::min(h, front.distance(p[u], p[v], near));
          if ((p[u] - p[v]).norm() > edge) {
            edge = (p[u] - p[v]).norm();
            e0 = u;
            e1 = v;
          }
        }
        if (h < kNear * edge) return bisect(e0, e1);
      }
      if (may_split_angle) {
        // The face opposite the vertex seen from the front: its widest edge in angle is bisected.
        const int face[3] = {j, k, l};
        TipCoordinates tip[3];
        for (int x = 0; x < 3; ++x) tip[x] = front.coordinates(p[face[x]]);
        double widest = 0;
        int e0 = 0, e1 = 0;
        for (int x = 0; x < 3; ++x) {
          const double angle = angle_around_front(tip[x], tip[(x + 1) % 3]);
          if (angle > widest) widest = angle, e0 = face[x], e1 = face[(x + 1) % 3];
        }
        if (widest > layout.max_angle) return bisect(e0, e1, 1);
      }
      append_vertex_rule(p[on[0]], p[j], p[k], p[l], layout.radial, layout.across, side, out);
      return;
    }
    if (count >= 2) {
      int k = -1, l = -1;
      opposite(on[0], on[1], k, l);
      if (may_split && front.distance(p[k], p[l], near) < kNear * (p[k] - p[l]).norm()) return bisect(k, l);
      if (may_split_angle && angle_around_front(front.coordinates(p[k]), front.coordinates(p[l])) > layout.max_angle)
        return bisect(k, l, 1);
      append_edge_rule(p[on[0]], p[on[1]], p[k], p[l], layout.radial, layout.along, layout.across, side, out);
      return;
    }
    // A piece surely beyond remote_ratio longest edges from the front takes the symmetric rule, which
    // needs neither the nearest edge nor its distance: a point of an edge lies at least
    // (d_i + d_j - |edge|) / 2 from the front, d_i and d_j its corners' distances. (The same choice as
    // with the edges' distances, without their six searches.)
    if (layout.remote_symmetric) {
      double bound = std::numeric_limits<double>::infinity();
      for (const auto& e : kEdges)
        bound = std::min(bound, 0.5 * (corner_distance[e[0]] + corner_distance[e[1]] - (p[e[0]] - p[e[1]]).norm()));
      const double needed = std::max(layout.remote_ratio, level < layout.far_levels ? layout.far_split_ratio : 0.0);
      if (bound > needed * longest * (1 + 1e-12))
        return append_symmetric_tet_rule(p[0], p[1], p[2], p[3], layout.remote, side, out);
    }
    double nearest = std::numeric_limits<double>::infinity();
    for (int e = 0; e < 6; ++e) {
      const double dist = front.distance(p[kEdges[e][0]], p[kEdges[e][1]], near);
      if (dist < nearest) {
        nearest = dist;
        best = e;
      }
    }
    if (level < layout.far_levels && nearest < layout.far_split_ratio * longest) {
      for (int e = 0; e < 6; ++e)
        if ((p[kEdges[e][0]] - p[kEdges[e][1]]).norm() == longest) return bisect(kEdges[e][0], kEdges[e][1]);
    }
    // A piece small for its nearness to the front: on it the integrand (~ 1 / r) lies between
    // 1 / (nearest + longest) and 1 / nearest, so no rule of positive weights errs by more than
    // V (1 / nearest - 1 / (nearest + longest)); below the tet's budget, the symmetric 4-point rule.
    if (budget > 0 && nearest > 0 &&
        std::abs(signed_volume(p[0], p[1], p[2], p[3])) * longest / (nearest * (nearest + longest)) < budget)
      return append_symmetric_tet_rule(p[0], p[1], p[2], p[3], 4, side, out);
    if (nearest > layout.remote_ratio * longest) {
      if (layout.remote_symmetric) return append_symmetric_tet_rule(p[0], p[1], p[2], p[3], layout.remote, side, out);
      n = layout.remote;
    } else if (nearest > layout.distant_ratio * longest) n = layout.distant;
  }
  int k = -1, l = -1;
  opposite(kEdges[best][0], kEdges[best][1], k, l);
  append_edge_rule(p[kEdges[best][0]], p[kEdges[best][1]], p[k], p[l], n, n, n, side, out, layout.far_squared);
}

}  // namespace

void append_tet_rule(const std::array<Eigen::Vector3d, 4>& p, const CrackFront& front, int n, int side,
                     PointRule& out) {
  append_tet_rule(p, front, TetRuleLayout::of_order(n), side, out);
}

void append_tet_rule(const std::array<Eigen::Vector3d, 4>& p, const CrackFront& front, const TetRuleLayout& layout,
                     int side, PointRule& out) {
  append_tet_rule(p, front, front.near(p.data(), 4, CrackFront::NearFor::distances), layout, side, out, 0, 0.0);
}

void conforming_rule(const EnrichedMesh& em, const CutElementSplits& splits, int t, int n, PointRule& out) {
  conforming_rule(em, splits, t, TetRuleLayout::of_order(n), out);
}

void conforming_rule(const EnrichedMesh& em, const CutElementSplits& splits, int t, const TetRuleLayout& layout,
                     PointRule& out) {
  out.clear();
  const int i = splits.index.empty() ? -1 : splits.index[t];
  std::array<Eigen::Vector3d, 4> p;
  for (int c = 0; c < 4; ++c) p[c] = em.mesh.points.row(em.mesh.tets(t, c)).transpose();
  const CrackFront& front = front_of_tet(em, t);
  if (i < 0) {
    append_tet_rule(p, front, front.near(p.data(), 4, CrackFront::NearFor::distances), layout, 0, out, 0, 0.0);
    return;
  }
  // The sign enrichment is constant on each piece and the shape functions linear: one point per
  // piece integrates exactly. Branch functions need the front-singular Gauss rule.
  const bool branch = em.branch(t);
  // The error each small piece of the tet may leave: small_piece_fraction of V / h, the scale of the
  // integral of 1 / r over a tet near the front.
  const double budget = layout.small_piece_fraction > 0
                            ? layout.small_piece_fraction * std::abs(signed_volume(p[0], p[1], p[2], p[3])) / longest_edge(p)
                            : 0.0;
  for (int s = splits.first[i]; s < splits.first[i + 1]; ++s) {
    const auto& q = splits.tets[s];
    if (branch) {
      // The front segments near the piece, found once for the distances that lay out its rule.
      append_tet_rule(q, front, front.near(q.data(), 4, CrackFront::NearFor::distances), layout, splits.side[s], out, 0,
                      budget);
    } else {
      out.x.push_back(0.25 * (q[0] + q[1] + q[2] + q[3]));
      out.weights.push_back(std::abs(signed_volume(q[0], q[1], q[2], q[3])));
      out.side.push_back(splits.side[s]);
    }
  }
}

void sampled_gradients(const EnrichedMesh& em, int t, const PointRule& rule, int consistent_order,
                       FaceIntegralCache* face_cache, Eigen::MatrixXd& gradients, int near_face_points) {
  gradients.resize(rule.size(), 3 * em.size(t));
  std::vector<TipCoordinates> tips;
  sampled_gradients(em, t, rule, consistent_order, face_cache, std::vector<int>(), gradients, tips, near_face_points);
}

void sampled_gradients(const EnrichedMesh& em, int t, const PointRule& rule, int consistent_order,
                       FaceIntegralCache* face_cache, const std::vector<int>& columns,
                       Eigen::Ref<Eigen::MatrixXd> gradients, std::vector<TipCoordinates>& tips,
                       int near_face_points, const std::vector<TipCoordinates>* given_tips,
                       int straight_face_points) {
  const TetShape shape = tet_shape(em.mesh, t);
  const int n = em.size(t), q = rule.size();
  const int m = columns.empty() ? 3 * n : static_cast<int>(columns.size());
  auto column = [&](int i) { return columns.empty() ? i : columns[static_cast<std::size_t>(i)]; };
  if (gradients.rows() != q || gradients.cols() != m)
    throw Error("sampled gradients of tet " + std::to_string(t) + ": the output is not " + std::to_string(q) + " x " +
                std::to_string(m));
  BasisAt b;
  const bool branch = em.branch(t);
  // The crack-tip coordinates of a branch tet's points together (CrackFront::coordinates of many
  // points): the same bits as a search of the whole front per point.
  if (given_tips && static_cast<int>(given_tips->size()) != q)
    throw Error("sampled gradients of tet " + std::to_string(t) + ": " + std::to_string(given_tips->size()) +
                " crack-tip coordinates given for " + std::to_string(q) + " points");
  const bool near_front = given_tips || (branch && em.cuts.empty() && !em.front.empty() && q > 0);
  if (near_front && !given_tips) {
    tips.resize(q);
    em.front.coordinates(rule.x.data(), q, tips.data());
  }
  const std::vector<TipCoordinates>& at = given_tips ? *given_tips : tips;
  // A point's gradients are a row of `gradients`, which is stored by columns: written one point at a
  // time, every value would go to another cache line (a tenth of the beam's integration went to
  // those stores). The rows of kBlock points are gathered first, then stored a column's run at a time.
  constexpr int kBlock = 8;
  thread_local std::vector<int> source;  // column i of `gradients` is entry source[i] of b.dN (by columns)
  thread_local std::vector<double> block;  // kBlock rows, row-major
  source.resize(static_cast<std::size_t>(m));
  for (int i = 0; i < m; ++i) source[static_cast<std::size_t>(i)] = (column(i) % 3) * n + column(i) / 3;
  block.resize(static_cast<std::size_t>(kBlock) * static_cast<std::size_t>(m));
  for (int first = 0; first < q; first += kBlock) {
    const int rows = std::min(kBlock, q - first);
    for (int k = 0; k < rows; ++k) {
      const int p = first + k;
      if (near_front)
        enriched_basis(em, t, shape, rule.x[p], rule.side[p], at[p], b);
      else
        enriched_basis(em, t, shape, rule.x[p], rule.side[p], b);
      const double* dN = b.dN.data();
      double* row = block.data() + static_cast<std::size_t>(k) * static_cast<std::size_t>(m);
      for (int i = 0; i < m; ++i) row[i] = dN[source[static_cast<std::size_t>(i)]];
    }
    for (int i = 0; i < m; ++i)
      for (int k = 0; k < rows; ++k)
        gradients(first + k, i) = block[static_cast<std::size_t>(k) * static_cast<std::size_t>(m) + static_cast<std::size_t>(i)];
  }
  // Variationally consistent integration (consistent_gradients.h): each branch function's sampled
  // gradient shifted by a constant so that the rule integrates it to its divergence-theorem value.
  if (consistent_order > 0 && branch && q > 0) {
    const Eigen::Map<const Eigen::VectorXd> w(rule.weights.data(), q);
    const Eigen::Matrix<double, Eigen::Dynamic, 3> exact = branch_gradient_integrals(
        em, t, consistent_face_points(consistent_order), face_cache, near_face_points, straight_face_points);
    const double volume = w.sum();
    for (int i = 0; i < m; ++i) {
      const int c = column(i) / 3, a = column(i) % 3;
      if (em.dofs[em.offsets[t] + c] < em.np + em.ns) continue;
      const double shift = (exact(c, a) - w.dot(gradients.col(i))) / volume;
      gradients.col(i).array() += shift;
    }
  }
}

void element_stiffness_at_points(const EnrichedMesh& em, int t, const PointRule& rule, const Lame& material,
                                 Eigen::MatrixXd& k, int consistent_order, FaceIntegralCache* face_cache) {
  // As element_stiffness: S = G^T G, row q of G the basis gradients at point q times sqrt(weight).
  Eigen::MatrixXd gradients;
  sampled_gradients(em, t, rule, consistent_order, face_cache, gradients);
  for (int p = 0; p < rule.size(); ++p) gradients.row(p) *= std::sqrt(rule.weights[p]);
  stiffness_from_gradients(gradients, material, k);
}

}  // namespace xfem
