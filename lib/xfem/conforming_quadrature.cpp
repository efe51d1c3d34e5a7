// SPDX-License-Identifier: MIT
#include "xfem/conforming_quadrature.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "xfem/enriched_basis.h"
#include "xfem/error.h"
#include "xfem/tet_shape.h"

namespace xfem {
namespace {

// A vertex this close to the front (relative to the tet's longest edge) lies on it: the split's
// front points come from inexact constructions, so exact zero is not expected.
constexpr double kOnFront = 1e-6;

double point_segment_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
  const Eigen::Vector3d d = q - p;
  const double dd = d.squaredNorm();
  const double t = dd > 0 ? std::clamp((x - p).dot(d) / dd, 0.0, 1.0) : 0.0;
  return (x - p - t * d).norm();
}

double segment_segment_distance(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& q0,
                                const Eigen::Vector3d& q1) {
  double best = std::min({point_segment_distance(p0, q0, q1), point_segment_distance(p1, q0, q1),
                          point_segment_distance(q0, p0, p1), point_segment_distance(q1, p0, p1)});
  // The interior minimum, when both closest points fall inside their segments.
  const Eigen::Vector3d u = p1 - p0, v = q1 - q0, w = p0 - q0;
  const double a = u.dot(u), b = u.dot(v), c = v.dot(v), d = u.dot(w), e = v.dot(w);
  const double den = a * c - b * b;
  if (den > 1e-14 * a * c) {
    const double s = (b * e - c * d) / den, t = (a * e - b * d) / den;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) best = std::min(best, (w + s * u - t * v).norm());
  }
  return best;
}

double front_distance(const Eigen::Vector3d& x, const CrackFront& front) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : front.segments()) best = std::min(best, point_segment_distance(x, s.p0, s.p1));
  return best;
}

double front_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const CrackFront& front) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : front.segments()) best = std::min(best, segment_segment_distance(p, q, s.p0, s.p1));
  return best;
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

void append_edge_rule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                      const Eigen::Vector3d& d, int n, int side, PointRule& out, bool angular) {
  std::vector<double> g, gw;
  gauss_legendre_01(n, g, gw);
  // |det(b-a, c-a, d-c)| = 6 V: the volume is the integral of 6 V s (1-s) over the unit cube.
  const double six_v = std::abs((b - a).cross(c - a).dot(d - c));
  // w at each of the n points of the last direction, with its weight (dw per unit parameter).
  std::vector<double> ws(g), wweights(gw);
  const Eigen::Vector3d e = (b - a).normalized();
  const Eigen::Vector3d pc = (c - a) - (c - a).dot(e) * e, pd = (d - a) - (d - a).dot(e) * e;
  const double scale = (b - a).norm() + (c - a).norm() + (d - a).norm();
  if (angular && pc.norm() > 1e-9 * scale && pd.norm() > 1e-9 * scale) {
    // Polar angle phi around the line ab instead of w: with q(w) = pc + w (pd - pc) in the plane
    // normal to ab, dw/dphi = |q|^2 / (pc x pd), which cancels the 1/|q| of a 1/r integrand; the
    // near-singular w-integrand of a wide wedge (cd passing close to the line) becomes smooth.
    const Eigen::Vector3d e1 = pc.normalized();
    const Eigen::Vector3d e2 = (pd - pd.dot(e1) * e1).normalized();
    const Eigen::Vector2d c2(pc.norm(), 0.0), d2(pd.dot(e1), pd.dot(e2));
    const double cross_cd = c2.x() * d2.y() - c2.y() * d2.x();
    const double phi_d = std::atan2(d2.y(), d2.x());  // in (0, pi): the wedge's opening
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector2d u(std::cos(g[k] * phi_d), std::sin(g[k] * phi_d));
      const Eigen::Vector2d dc = c2 - d2;
      const double w = (c2.x() * u.y() - c2.y() * u.x()) / (dc.x() * u.y() - dc.y() * u.x());
      const Eigen::Vector2d q = c2 + w * (d2 - c2);
      ws[k] = w;
      wweights[k] = gw[k] * phi_d * q.squaredNorm() / cross_cd;
    }
  }
  for (int i = 0; i < n; ++i) {
    const double sigma = g[i], s = sigma * sigma;
    const double radial = gw[i] * 2.0 * sigma * s * (1.0 - s) * six_v;  // ds = 2 sigma dsigma
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector3d on_ab = a + g[j] * (b - a);
      for (int k = 0; k < n; ++k) {
        out.x.push_back((1.0 - s) * on_ab + s * (c + ws[k] * (d - c)));
        out.weights.push_back(radial * gw[j] * wweights[k]);
        out.side.push_back(side);
      }
    }
  }
}

void append_vertex_rule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                        const Eigen::Vector3d& d, int n, int side, PointRule& out) {
  std::vector<double> g, gw;
  gauss_legendre_01(n, g, gw);
  const double six_v = std::abs((b - a).cross(c - a).dot(d - a));
  for (int i = 0; i < n; ++i) {
    const double sigma = g[i], u = sigma * sigma;
    const double radial = gw[i] * 2.0 * sigma * u * u * six_v;  // u^2 du, du = 2 sigma dsigma
    for (int j = 0; j < n; ++j) {
      const double v = g[j];
      for (int k = 0; k < n; ++k) {
        out.x.push_back(a + u * (b - a) + u * v * (c - b) + u * v * g[k] * (d - c));
        out.weights.push_back(radial * v * gw[j] * gw[k]);
        out.side.push_back(side);
      }
    }
  }
}

void append_tet_rule(const std::array<Eigen::Vector3d, 4>& p, const CrackFront& front, int n, int side,
                     PointRule& out) {
  static const int kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  auto opposite = [](int i, int j, int& k, int& l) {
    k = -1;
    for (int m = 0; m < 4; ++m)
      if (m != i && m != j) (k < 0 ? k : l) = m;
  };
  int best = 0;
  if (!front.empty()) {
    double longest = 0;
    for (const auto& e : kEdges) longest = std::max(longest, (p[e[0]] - p[e[1]]).norm());
    int on[4], count = 0;
    for (int m = 0; m < 4; ++m)
      if (front_distance(p[m], front) <= kOnFront * longest) on[count++] = m;
    if (count == 1) {
      int k = -1, l = -1, j = on[0] == 0 ? 1 : 0;
      opposite(on[0], j, k, l);
      append_vertex_rule(p[on[0]], p[j], p[k], p[l], n, side, out);
      return;
    }
    if (count >= 2) {
      int k = -1, l = -1;
      opposite(on[0], on[1], k, l);
      append_edge_rule(p[on[0]], p[on[1]], p[k], p[l], n, side, out, true);
      return;
    }
    double nearest = std::numeric_limits<double>::infinity();
    for (int e = 0; e < 6; ++e) {
      const double dist = front_distance(p[kEdges[e][0]], p[kEdges[e][1]], front);
      if (dist < nearest) {
        nearest = dist;
        best = e;
      }
    }
  }
  int k = -1, l = -1;
  opposite(kEdges[best][0], kEdges[best][1], k, l);
  append_edge_rule(p[kEdges[best][0]], p[kEdges[best][1]], p[k], p[l], n, side, out, false);
}

CutElementSplits split_cut_elements(const EnrichedMesh& em) {
  CutElementSplits out;
  const int tets = em.tets();
  out.index.assign(tets, -1);
  out.first.push_back(0);
  TetMesh cut_tets;
  std::vector<int> rows;
  if (!em.cut_class.empty())
    for (int t = 0; t < tets; ++t)
      if (em.cut_class[t] > 0) rows.push_back(t);
  if (rows.empty()) return out;
  if (!em.cut) throw Error("conforming integration: " + std::to_string(rows.size()) + " cut elements but no cut surface");
  cut_tets.points = em.mesh.points;
  cut_tets.tets.resize(static_cast<Eigen::Index>(rows.size()), 4);
  for (std::size_t i = 0; i < rows.size(); ++i) cut_tets.tets.row(static_cast<Eigen::Index>(i)) = em.mesh.tets.row(rows[i]);
  const std::vector<int> all_cut(rows.size(), 1);  // split_mesh splits whatever the cut crosses
  out.split = split_mesh(cut_tets, em.side, all_cut, em.cut->mesh(), em.front.segments());
  // split_mesh emits the sub-tets parent after parent.
  const int sub = static_cast<int>(out.split.tets.rows());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    out.index[rows[i]] = static_cast<int>(i);
    int end = out.first.back();
    while (end < sub && out.split.parent[end] == static_cast<int>(i)) ++end;
    out.first.push_back(end);
  }
  if (out.first.back() != sub) throw Error("conforming integration: split_mesh returned sub-tets out of order");
  return out;
}

void conforming_rule(const EnrichedMesh& em, const CutElementSplits& splits, int t, int n, PointRule& out) {
  out.clear();
  const int i = splits.index.empty() ? -1 : splits.index[t];
  if (i < 0) {
    std::array<Eigen::Vector3d, 4> p;
    for (int c = 0; c < 4; ++c) p[c] = em.mesh.points.row(em.mesh.tets(t, c)).transpose();
    append_tet_rule(p, em.front, n, 0, out);
    return;
  }
  for (int s = splits.first[i]; s < splits.first[i + 1]; ++s) {
    std::array<Eigen::Vector3d, 4> p;
    for (int c = 0; c < 4; ++c) p[c] = splits.split.points.row(splits.split.tets(s, c)).transpose();
    append_tet_rule(p, em.front, n, splits.split.tet_side[s], out);
  }
}

void element_stiffness_at_points(const EnrichedMesh& em, int t, const PointRule& rule, const Lame& material,
                                 Eigen::MatrixXd& k) {
  // As element_stiffness: S = G^T G, row q of G the basis gradients at point q times sqrt(weight).
  const TetShape shape = tet_shape(em.mesh, t);
  const int n = em.size(t), q = rule.size();
  Eigen::MatrixXd G(q, 3 * n);
  BasisAt b;
  for (int p = 0; p < q; ++p) {
    enriched_basis(em, t, shape, rule.x[p], rule.side[p], b);
    const double s = std::sqrt(rule.weights[p]);
    for (int c = 0; c < n; ++c)
      for (int a = 0; a < 3; ++a) G(p, 3 * c + a) = s * b.dN(c, a);
  }
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  S.selfadjointView<Eigen::Lower>().rankUpdate(G.transpose());
  S.triangularView<Eigen::StrictlyUpper>() = S.transpose();
  k.resize(3 * n, 3 * n);
  const double mu = material.mu, la = material.lambda;
  for (int a = 0; a < n; ++a)
    for (int c = 0; c < n; ++c) {
      const double dot = S(3 * a, 3 * c) + S(3 * a + 1, 3 * c + 1) + S(3 * a + 2, 3 * c + 2);
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
          k(3 * a + j, 3 * c + i) =
              mu * S(3 * a + i, 3 * c + j) + la * S(3 * a + j, 3 * c + i) + (i == j ? mu * dot : 0.0);
    }
}

}  // namespace xfem
