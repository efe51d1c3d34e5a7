// SPDX-License-Identifier: MIT
#include "xfem/geometry/crack_front.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "xfem/core/error.h"

namespace xfem {

namespace {

double segment_distance_squared(const FrontSegment& s, const Eigen::Vector3d& x) {
  const Eigen::Vector3d d = s.p1 - s.p0;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((x - s.p0).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (s.p0 + t * d - x).squaredNorm();
}

}  // namespace

CrackFront::CrackFront(std::vector<FrontSegment> segments) : segments_(std::move(segments)) {
  for (std::size_t i = 0; i < segments_.size(); ++i) {
    const FrontSegment& s = segments_[i];
    if (!((s.p1 - s.p0).norm() > 0) || !(s.b.norm() > 0) || !s.p0.allFinite() || !s.p1.allFinite() ||
        !s.b.allFinite())
      throw Error("crack front: segment " + std::to_string(i) + " is degenerate (zero length or zero normal)");
  }
  if (segments_.empty()) return;
  chains_ = std::make_shared<const std::vector<FrontPolyline>>(front_polylines(segments_));
  auto index = std::make_shared<Index>();
  std::vector<Eigen::Vector3d> p0, p1;
  for (const FrontSegment& g : segments_) p0.push_back(g.p0), p1.push_back(g.p1);
  index->by_segment = SegmentTree(p0, p1);
  p0.clear();
  p1.clear();
  for (std::size_t c = 0; c < chains_->size(); ++c) {
    const FrontPolyline& ch = (*chains_)[c];
    const int np = static_cast<int>(ch.points.size());
    for (int i = 0; i < ch.segments(); ++i) {
      p0.push_back(ch.points[i]);
      p1.push_back(ch.points[(i + 1) % np]);
      index->chain_of.push_back(static_cast<int>(c));
      index->segment_of.push_back(i);
      index->longest = std::max(index->longest, (p1.back() - p0.back()).norm());
    }
  }
  index->by_chain = SegmentTree(p0, p1);
  index_ = std::move(index);
}

double CrackFront::distance(const Eigen::Vector3d& x) const {
  double best = std::numeric_limits<double>::infinity();
  if (!index_) return best;
  double best2 = index_->by_segment.nearest_bound2(x);
  index_->by_segment.visit_near(x, best2, [&](int k) {
    best = std::min(best, point_segment_distance(x, segments_[k].p0, segments_[k].p1));
    best2 = std::min(best2, best * best);
  });
  return best;
}

double CrackFront::distance(const Eigen::Vector3d& p, const Eigen::Vector3d& q) const {
  double best2 = std::numeric_limits<double>::infinity(), best = best2;
  if (!index_) return best;
  index_->by_segment.visit_near(p, q, best2, [&](int k) {
    best = std::min(best, segment_segment_distance(p, q, segments_[k].p0, segments_[k].p1));
    best2 = best * best;
  });
  return best;
}

namespace {
bool in_ball(const CrackFront::Near& near, const Eigen::Vector3d& x) {
  return near.radius >= 0 && (x - near.centre).norm() <= near.radius;
}
}  // namespace

double CrackFront::distance(const Eigen::Vector3d& x, const Near& near) const {
  if (!index_ || !in_ball(near, x)) return distance(x);
  // The minimum of the same distances over a list holding the nearest segment: the same number.
  double best = std::numeric_limits<double>::infinity();
  for (const int k : near.segments) best = std::min(best, point_segment_distance(x, segments_[k].p0, segments_[k].p1));
  return best;
}

double CrackFront::distance(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Near& near) const {
  if (!index_ || !in_ball(near, p) || !in_ball(near, q)) return distance(p, q);
  double best = std::numeric_limits<double>::infinity();
  for (const int k : near.segments)
    best = std::min(best, segment_segment_distance(p, q, segments_[k].p0, segments_[k].p1));
  return best;
}

namespace {

void vertex_frame(const FrontPolyline& p, int v, Eigen::Vector3d& cv, Eigen::Vector3d& bv);
void cached_vertex_frame(const FrontPolyline& p, int v, Eigen::Vector3d& cv, Eigen::Vector3d& bv);

// The fraction along segment i of a chain at arc length s (wrapped or clamped to the chain).
double fraction_on(const FrontPolyline& p, int i, double s) {
  const double end = i + 1 < static_cast<int>(p.arc.size()) ? p.arc[i + 1] : p.length;
  return end > p.arc[i] ? std::clamp((s - p.arc[i]) / (end - p.arc[i]), 0.0, 1.0) : 0.0;
}

// The point at fraction f along segment i of a chain.
Eigen::Vector3d point_on(const FrontPolyline& p, int i, double f) {
  return (1 - f) * p.points[i] + f * p.points[(i + 1) % static_cast<int>(p.points.size())];
}

// The frame interpolated at fraction f along segment i of a chain (FrontPolyline::frame):
// c = c~ / |c~| with c~ = (1 - f) c0 + f c1, b = beta / |beta| with beta = b~ - (b~ . c) c and
// b~ = (1 - f) b0 + f b1, from the vertices' tangents c0, c1 and normals b0, b1. The unnormalised
// vectors and their norms are kept for the frame's derivative (tip_coordinates_at_foot).
struct SegmentFrame {
  Eigen::Vector3d c0, b0, c1, b1, c_tilde, c, b_tilde, beta, b;
  double c_norm = 0, beta_norm = 0;
};

SegmentFrame segment_frame(const FrontPolyline& p, int i, double f) {
  SegmentFrame s;
  cached_vertex_frame(p, i, s.c0, s.b0);
  cached_vertex_frame(p, i + 1, s.c1, s.b1);
  // v / |v| is what Eigen's normalized() computes: each norm is taken once.
  s.c_tilde = (1 - f) * s.c0 + f * s.c1;
  s.c_norm = s.c_tilde.norm();
  s.c = s.c_norm > 0 ? (s.c_tilde / s.c_norm).eval() : s.c_tilde;
  s.b_tilde = (1 - f) * s.b0 + f * s.b1;
  s.beta = s.b_tilde - s.b_tilde.dot(s.c) * s.c;
  s.beta_norm = s.beta.norm();
  s.b = s.beta_norm > 0 ? (s.beta / s.beta_norm).eval() : s.beta;
  return s;
}

// Where x's normal plane meets the chain segment p_i -> p_j (vertex tangents c_i, c_j), as the
// fraction f in [0, 1] along it, or -1 if it does not. Along the segment P(f) = p_i + f d and the
// tangent is c(f) = c~(f) / |c~(f)| with c~(f) = c_i + f (c_j - c_i) (FrontPolyline::frame), so
// g(f) = (x - P(f)) . c(f) has the sign of the quadratic h(f) = (w - f d) . (c_i + f e),
// w = x - p_i, e = c_j - c_i. Solved in closed form: this is called for every integration point of
// a branch-enriched tet, and the bisection it replaces dominated xfem-assemble on curved fronts. As
// before, a segment whose ends have the same strict sign of g holds no foot (its two roots, if any,
// belong to a fold of the normal planes beyond the front's radius of curvature).
double normal_plane_root(const Eigen::Vector3d& pi, const Eigen::Vector3d& pj, const Eigen::Vector3d& ci,
                         const Eigen::Vector3d& cj, const Eigen::Vector3d& x) {
  const double h0 = (x - pi).dot(ci), h1 = (x - pj).dot(cj);
  if ((h0 > 0 && h1 > 0) || (h0 < 0 && h1 < 0)) return -1.0;
  if (h0 == 0) return 0.0;
  if (h1 == 0) return 1.0;
  const Eigen::Vector3d w = x - pi, d = pj - pi, e = cj - ci;
  const double A = h0, B = w.dot(e) - d.dot(ci), C = -d.dot(e);  // h(f) = A + B f + C f^2
  // h changes sign on [0, 1], so exactly one root lies there; the stable pair of formulas finds
  // both roots of the quadratic without cancellation, and the one in [0, 1] is kept.
  double f;
  const double disc = std::max(B * B - 4 * A * C, 0.0);
  const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
  if (q == 0) {
    f = 0.0;
  } else {
    const double r1 = A / q, r2 = C != 0 ? q / C : std::numeric_limits<double>::infinity();
    f = std::abs(r1 - 0.5) <= std::abs(r2 - 0.5) ? r1 : r2;
  }
  f = std::clamp(f, 0.0, 1.0);
  // One Newton step on h removes the rounding of the formula's branch choice.
  const double dh = B + 2 * C * f;
  if (dh != 0) f = std::clamp(f - (A + (B + C * f) * f) / dh, 0.0, 1.0);
  return f;
}

// The same on segment i of a chain (its vertices' interpolated tangents, FrontPolyline::frame).
double normal_plane_root(const FrontPolyline& ch, int i, const Eigen::Vector3d& x) {
  Eigen::Vector3d ci, cj, b;
  cached_vertex_frame(ch, i, ci, b);
  cached_vertex_frame(ch, i + 1, cj, b);
  return normal_plane_root(ch.points[i], ch.points[(i + 1) % static_cast<int>(ch.points.size())], ci, cj, x);
}

// The crack-tip coordinates of x and their gradients given its foot: arc length s on segment seg
// of chain ch, `inside` whether the foot moves with x (a normal-plane foot strictly inside the
// chain).
TipCoordinates tip_coordinates_at_foot(const FrontPolyline& ch, int seg, double s, bool inside,
                                       const Eigen::Vector3d& x) {
  const Eigen::Vector3d d = ch.points[(seg + 1) % static_cast<int>(ch.points.size())] - ch.points[seg];
  const double len = d.norm();
  // The foot's fraction along its known segment, as FrontPolyline::position and ::frame find it
  // after their search (s lies in [arc[seg], arc[seg] + len]: where their search would take the
  // next segment, s is that segment's start, and both give the same bits at the shared vertex),
  // without the search: this runs for every integration point of a branch-enriched tet.
  const double f = fraction_on(ch, seg, s);
  const Eigen::Vector3d P = point_on(ch, seg, f);
  const SegmentFrame fr = segment_frame(ch, seg, f);
  const Eigen::Vector3d &c = fr.c, &b = fr.b;
  const Eigen::Vector3d a = b.cross(c), v = x - P;
  TipCoordinates out;
  out.xa = a.dot(v);
  out.xb = b.dot(v);
  out.grad.row(0) = a.transpose();
  out.grad.row(1) = b.transpose();
  if (inside) {
    // P and the frame move with s(x): grad xa = a + (a'(s) . v - a . u) grad s, likewise xb, with
    // u = P'(s) the segment's direction and, from g(s(x), x) = 0, grad s = c / (u . c - v . c'(s)).
    // The frame's derivative in closed form (df/ds = 1 / len), the derivative of a normalisation
    // y / |y| being (I - y^ y^T) y' / |y|.
    const Eigen::Vector3d u = d / len;
    const Eigen::Vector3d dc_tilde = (fr.c1 - fr.c0) / len, db_tilde = (fr.b1 - fr.b0) / len;
    const Eigen::Vector3d dc = (dc_tilde - c.dot(dc_tilde) * c) / fr.c_norm;
    const Eigen::Vector3d dbeta = db_tilde - (db_tilde.dot(c) + fr.b_tilde.dot(dc)) * c - fr.b_tilde.dot(c) * dc;
    const Eigen::Vector3d db = (dbeta - b.dot(dbeta) * b) / fr.beta_norm;
    // (b x c') . v vanishes at the foot (c' lies in span(a, b), so b x c' is along c, and c . v = 0
    // there): kept for a = b x c's derivative in full.
    const Eigen::Vector3d da = db.cross(c) + b.cross(dc);
    const Eigen::Vector3d grad_s = c / (u.dot(c) - v.dot(dc));
    out.grad.row(0) += (da.dot(v) - a.dot(u)) * grad_s.transpose();
    out.grad.row(1) += (db.dot(v) - b.dot(u)) * grad_s.transpose();
  }
  return out;
}

}  // namespace

TipCoordinates CrackFront::coordinates(const Eigen::Vector3d& x) const {
  if (segments_.empty()) throw Error("crack front: no segments (the cut has no front inside the body)");
  const SegmentTree& tree = index_->by_chain;
  return coordinates_visiting(
      x, [&](double& bound2, auto&& f) { bound2 = tree.nearest_bound2(x), tree.visit_near(x, bound2, f); },
      [&](double& reach2, auto&& f) { tree.visit_near(x, reach2, f); });
}

TipCoordinates CrackFront::coordinates(const Eigen::Vector3d& x, const Near& near) const {
  if (segments_.empty()) throw Error("crack front: no segments (the cut has no front inside the body)");
  // Outside the region the list was made for it may miss the nearest segment: the tree then.
  if (!in_ball(near, x)) return coordinates(x);
  const auto scan = [&](double&, auto&& f) {
    for (const int k : near.chain_segments) f(k);
  };
  return coordinates_visiting(x, scan, scan);
}

void CrackFront::coordinates(const Eigen::Vector3d* x, int count, TipCoordinates* out) const {
  if (count > 0 && segments_.empty()) throw Error("crack front: no segments (the cut has no front inside the body)");
  // Runs of 64 points: a list per run costs about two tree searches, the scans of a run's points over
  // it less than their own searches. Once the foot's frame stopped searching the chain, runs of 32
  // to 64 beat the 8 of before by ~5 % of xfem-assemble's one-thread CPU on organ S and the organ
  // example, one list per call lost part of it again (docs/PERFORMANCE.md, issue 35, tenth part).
  constexpr int kRun = 64;
  // A run's segments unpacked once: the scans below repeat coordinates_visiting's arithmetic,
  // operation for operation (the same bits; test/unit/crack_front.cpp compares them).
  struct Candidate {
    const FrontPolyline* chain;
    int segment;
    Eigen::Vector3d p0, d;
    double len2, len;
    Eigen::Vector3d p1, c0, c1;  // the far end and the vertex tangents, for normal_plane_root
  };
  std::vector<Candidate> candidates;
  std::vector<double> d2s;
  for (int begin = 0; begin < count; begin += kRun) {
    const int end = std::min(count, begin + kRun);
    const Near near = this->near(x + begin, end - begin, NearFor::coordinates);
    candidates.clear();
    for (const int k : near.chain_segments) {
      const FrontPolyline& ch = (*chains_)[index_->chain_of[k]];
      const int i = index_->segment_of[k], np = static_cast<int>(ch.points.size());
      const Eigen::Vector3d& p1 = ch.points[(i + 1) % np];
      const Eigen::Vector3d d = p1 - ch.points[i];
      Eigen::Vector3d c0, c1, b;
      cached_vertex_frame(ch, i, c0, b);
      cached_vertex_frame(ch, i + 1, c1, b);
      candidates.push_back({&ch, i, ch.points[i], d, d.squaredNorm(), d.norm(), p1, c0, c1});
    }
    d2s.resize(candidates.size());
    for (int p = begin; p < end; ++p) {
      const Eigen::Vector3d& y = x[p];
      if (!in_ball(near, y)) {
        out[p] = coordinates(y);
        continue;
      }
      // Pass 1: the closest point of the front (coordinates_visiting).
      double best2 = std::numeric_limits<double>::infinity(), s = 0;
      const FrontPolyline* best = nullptr;
      int seg = 0;
      bool inside = false;
      for (std::size_t c = 0; c < candidates.size(); ++c) {
        const Candidate& g = candidates[c];
        const double t = g.len2 > 0 ? std::clamp((y - g.p0).dot(g.d) / g.len2, 0.0, 1.0) : 0.0;
        const double d2 = d2s[c] = (g.p0 + t * g.d - y).squaredNorm();
        if (d2 < best2) best = g.chain, best2 = d2, s = g.chain->arc[g.segment] + t * std::sqrt(g.len2), seg = g.segment;
      }
      // Pass 2: the feet in normal planes.
      const double d0 = std::sqrt(best2);
      double best_root = std::numeric_limits<double>::infinity();
      for (std::size_t c = 0; c < candidates.size(); ++c) {
        const Candidate& g = candidates[c];
        const double reach = 1.5 * d0 + 1e-12 * g.len;
        if (d2s[c] > reach * reach) continue;
        const double f = normal_plane_root(g.p0, g.p1, g.c0, g.c1, y);
        if (f < 0) continue;
        const double root = g.chain->arc[g.segment] + f * g.len, dist = (y - (g.p0 + f * g.d)).norm();
        if (dist < best_root) {
          best_root = dist, best = g.chain, s = root, seg = g.segment;
          inside = g.chain->closed || (root > 0 && root < g.chain->length);
        }
      }
      out[p] = tip_coordinates_at_foot(*best, seg, s, inside, y);
    }
  }
}

CrackFront::Near CrackFront::near(const Eigen::Vector3d* points, int count, NearFor use) const {
  Near out;
  if (segments_.empty() || count <= 0) return out;
  const Index& index = *index_;
  Eigen::Vector3d lo = points[0], hi = points[0];
  for (int i = 1; i < count; ++i) lo = lo.cwiseMin(points[i]), hi = hi.cwiseMax(points[i]);
  out.centre = 0.5 * (lo + hi);
  double radius = 0;
  for (int i = 0; i < count; ++i) radius = std::max(radius, (points[i] - out.centre).norm());
  // A hair larger, so that the points themselves (and the Gauss points between them) fall inside.
  out.radius = radius * (1 + 1e-12) + 1e-300;
  // The distance from the centre to the nearest segment of a tree, each list from its own tree (the
  // chains' vertices and the segments' ends agree only to the joining tolerance).
  const auto nearest = [&](const SegmentTree& tree, auto&& distance) {
    double bound2 = tree.nearest_bound2(out.centre), d = std::numeric_limits<double>::infinity();
    tree.visit_near(out.centre, bound2, [&](int k) {
      d = std::min(d, distance(k));
      bound2 = std::min(bound2, d * d);
    });
    return d;
  };
  // U bounds the distance to the front of every point of the ball: for the segment nearest to the
  // centre, |x - P| <= |x - centre| + d(centre). A point's nearest segment lies within U of it, its
  // feet within 1.5 U (+ the 1e-12 slack of coordinates()): every segment that can serve a point
  // of the ball lies within radius + 1.5 U + slack of the centre. Relative margins far above
  // rounding: a longer list only costs time, a shorter one bits.
  if (use != NearFor::distances) {
    const auto chain_distance = [&](int k) {
      const FrontPolyline& ch = (*chains_)[index.chain_of[k]];
      const int i = index.segment_of[k], np = static_cast<int>(ch.points.size());
      return point_segment_distance(out.centre, ch.points[i], ch.points[(i + 1) % np]);
    };
    const double U = out.radius + nearest(index.by_chain, chain_distance);
    const double reach = (out.radius + 1.5 * U + 1e-12 * index.longest) * (1 + 1e-9) + 1e-300;
    double reach2 = reach * reach;
    index.by_chain.visit_near(out.centre, reach2, [&](int k) {
      if (chain_distance(k) <= reach) out.chain_segments.push_back(k);
    });
  }
  // distance(): the nearest segment of a point of the ball (or of a segment in it) lies within U of
  // the point, so within radius + U of the centre.
  if (use != NearFor::coordinates) {
    const auto segment_distance = [&](int k) {
      return point_segment_distance(out.centre, segments_[k].p0, segments_[k].p1);
    };
    const double within = (2 * out.radius + nearest(index.by_segment, segment_distance)) * (1 + 1e-9) + 1e-300;
    double within2 = within * within;
    index.by_segment.visit_near(out.centre, within2, [&](int k) {
      if (segment_distance(k) <= within) out.segments.push_back(k);
    });
  }
  return out;
}

template <class Visit1, class Visit2>
TipCoordinates CrackFront::coordinates_visiting(const Eigen::Vector3d& x, Visit1&& visit1, Visit2&& visit2) const {
  // The foot of x on the front: the s whose normal plane (normal to the tangent interpolated
  // along the front) contains x, the nearest such if several. Unlike the closest point of the
  // polyline, which jumps between the two segments of a corner for the points on its concave
  // side, the normal planes turn continuously with s, so s(x) is continuous (up to the front's
  // radius of curvature). Beyond the ends of an open chain the end point is the foot.
  // Pass 1: the closest point of the front, the foot when no normal plane holds x (beyond an open
  // chain's end). Squared distances, no square roots in the scans: this runs for every
  // integration point of a branch-enriched tet.
  // Both passes visit only the segments the front's segment tree finds near x, in the order of a
  // scan over every chain's segments (the same answer as that scan, bit for bit).
  const Index& index = *index_;
  const auto segment_distance2 = [&](int k, double& t, double& len2) {
    const FrontPolyline& ch = (*chains_)[index.chain_of[k]];
    const int i = index.segment_of[k], np = static_cast<int>(ch.points.size());
    const Eigen::Vector3d& p0 = ch.points[i];
    const Eigen::Vector3d d = ch.points[(i + 1) % np] - p0;
    len2 = d.squaredNorm();
    t = len2 > 0 ? std::clamp((x - p0).dot(d) / len2, 0.0, 1.0) : 0.0;
    return (p0 + t * d - x).squaredNorm();
  };
  // The tree's search is bounded from the start by its quick upper bound: it then skips at once
  // what lies farther. The bound only prunes; the choice is the scan's.
  double bound2 = std::numeric_limits<double>::infinity();
  double best2 = std::numeric_limits<double>::infinity();
  const FrontPolyline* best = nullptr;
  double s = 0;
  int seg = 0;
  bool inside = false;
  visit1(bound2, [&](int k) {
    double t, len2;
    const double d2 = segment_distance2(k, t, len2);
    if (d2 < best2) {
      best = &(*chains_)[index.chain_of[k]];
      best2 = d2, s = best->arc[index.segment_of[k]] + t * std::sqrt(len2), seg = index.segment_of[k];
      bound2 = std::min(bound2, d2);
    }
  });
  // Pass 2: the feet in normal planes, on the segments near enough to hold one.
  const double d0 = std::sqrt(best2);
  double best_root = std::numeric_limits<double>::infinity();
  double reach2 = 1.5 * d0 + 1e-12 * index.longest;
  reach2 *= reach2;
  visit2(reach2, [&](int k) {
    double t, len2;
    const double d2 = segment_distance2(k, t, len2);
    const FrontPolyline& ch = (*chains_)[index.chain_of[k]];
    const int i = index.segment_of[k], np = static_cast<int>(ch.points.size());
    const Eigen::Vector3d& p0 = ch.points[i];
    const Eigen::Vector3d d = ch.points[(i + 1) % np] - p0;
    const double len = d.norm(), reach = 1.5 * d0 + 1e-12 * len;
    if (d2 > reach * reach) return;  // too far to hold the foot
    const double f = normal_plane_root(ch, i, x);
    if (f < 0) return;
    const double root = ch.arc[i] + f * len, dist = (x - (p0 + f * d)).norm();
    if (dist < best_root) {
      best_root = dist, best = &ch, s = root, seg = i;
      inside = ch.closed || (root > 0 && root < ch.length);
    }
  });
  return tip_coordinates_at_foot(*best, seg, s, inside, x);
}

int CrackFront::closest_segment(const Eigen::Vector3d& x) const {
  if (segments_.empty()) throw Error("crack front: no segments (the cut has no front inside the body)");
  // The segment tree visits in increasing index, and a strict '<' gives ties to the lowest index.
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity(), bound = index_->by_segment.nearest_bound2(x);
  index_->by_segment.visit_near(x, bound, [&](int i) {
    const double d = segment_distance_squared(segments_[i], x);
    if (d < best_d) {
      best_d = d;
      best = i;
      bound = std::min(bound, d);
    }
  });
  return best;
}

CrackTipFrame CrackFront::frame(const Eigen::Vector3d& x) const {
  const FrontSegment& s = segments_[closest_segment(x)];
  const Eigen::Vector3d c = (s.p1 - s.p0).normalized();
  // b is the triangle's normal, orthogonal to its own edge up to rounding; re-orthogonalise so
  // that R is a rotation to machine precision.
  const Eigen::Vector3d b = (s.b - s.b.dot(c) * c).normalized();
  CrackTipFrame f;
  f.R.col(0) = b.cross(c);
  f.R.col(1) = b;
  f.R.col(2) = c;
  f.origin = s.p0;
  return f;
}

std::vector<FrontPolyline> front_polylines(const CrackFront& front) {
  if (front.empty()) throw Error("crack front: no segments (the cut has no front inside the body)");
  return front.chains();
}

std::vector<FrontPolyline> front_polylines(const std::vector<FrontSegment>& S) {
  if (S.empty()) throw Error("crack front: no segments (the cut has no front inside the body)");
  const int n = static_cast<int>(S.size());
  Eigen::Vector3d lo = S[0].p0, hi = S[0].p0;
  for (const auto& g : S) {
    lo = lo.cwiseMin(g.p0).cwiseMin(g.p1);
    hi = hi.cwiseMax(g.p0).cwiseMax(g.p1);
  }
  const double tol = 1e-9 * std::max((hi - lo).norm(), 1e-300);
  std::vector<int> next(n, -1), prev(n, -1);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (j != i && prev[j] < 0 && (S[i].p1 - S[j].p0).norm() <= tol) {
        next[i] = j;
        prev[j] = i;
        break;
      }
  std::vector<char> used(n, 0);
  std::vector<FrontPolyline> out;
  const auto chain_from = [&](int start) {
    FrontPolyline p;
    int i = start;
    while (i >= 0 && !used[i]) {
      used[i] = 1;
      p.points.push_back(S[i].p0);
      p.normals.push_back(S[i].b.normalized());
      if (next[i] < 0) p.points.push_back(S[i].p1);
      i = next[i];
    }
    p.closed = i == start;
    if (i >= 0 && !p.closed) p.points.push_back(S[i].p0);  // ran into a chain taken already
    const int m = static_cast<int>(p.points.size());
    p.arc.assign(m, 0.0);
    for (int k = 1; k < m; ++k) p.arc[k] = p.arc[k - 1] + (p.points[k] - p.points[k - 1]).norm();
    p.length = p.arc[m - 1] + (p.closed ? (p.points[0] - p.points[m - 1]).norm() : 0.0);
    p.vertex_c.resize(p.segments() + 1);
    p.vertex_b.resize(p.segments() + 1);
    for (int v = 0; v <= p.segments(); ++v) vertex_frame(p, v, p.vertex_c[v], p.vertex_b[v]);
    out.push_back(std::move(p));
  };
  for (int i = 0; i < n; ++i)
    if (prev[i] < 0 && !used[i]) chain_from(i);
  for (int i = 0; i < n; ++i)
    if (!used[i]) chain_from(i);  // loops
  return out;
}

namespace {

// Segment i of a chain containing arc length s (already wrapped or clamped) and the fraction along it.
void locate(const FrontPolyline& p, double s, int& i, double& f) {
  const int m = p.segments();
  i = static_cast<int>(std::upper_bound(p.arc.begin(), p.arc.end(), s) - p.arc.begin()) - 1;
  i = std::clamp(i, 0, m - 1);
  f = fraction_on(p, i, s);
}

double wrap(const FrontPolyline& p, double s) {
  if (!p.closed) return std::clamp(s, 0.0, p.length);
  s = std::fmod(s, p.length);
  return s < 0 ? s + p.length : s;
}

}  // namespace

Eigen::Vector3d FrontPolyline::position(double s) const {
  int i;
  double f;
  locate(*this, wrap(*this, s), i, f);
  return point_on(*this, i, f);
}

namespace {

// Tangent c and normal b at vertex v of a chain: the mean of the two segments meeting there (one
// at an open chain's ends), what FrontPolyline::frame interpolates along each segment.
void vertex_frame(const FrontPolyline& p, int v, Eigen::Vector3d& cv, Eigen::Vector3d& bv) {
  const int m = p.segments(), np = static_cast<int>(p.points.size());
  const auto seg_dir = [&](int k) { return (p.points[(k + 1) % np] - p.points[k]).normalized().eval(); };
  const int before = p.closed ? (v + m - 1) % m : v - 1, after = p.closed ? v % m : v;
  cv = Eigen::Vector3d::Zero();
  bv = Eigen::Vector3d::Zero();
  if (before >= 0) cv += seg_dir(before), bv += p.normals[before];
  if (after < m) cv += seg_dir(after), bv += p.normals[after];
  if (!(cv.norm() > 1e-12)) cv = seg_dir(after < m ? after : before);  // a cusp: keep one side
  cv.normalize();
}

void cached_vertex_frame(const FrontPolyline& p, int v, Eigen::Vector3d& cv, Eigen::Vector3d& bv) {
  if (static_cast<std::size_t>(v) < p.vertex_c.size()) {
    cv = p.vertex_c[v];
    bv = p.vertex_b[v];
  } else {
    vertex_frame(p, v, cv, bv);
  }
}

}  // namespace

void FrontPolyline::frame(double s, Eigen::Vector3d& c, Eigen::Vector3d& b) const {
  // Tangent and normal at the vertices (mean of the two segments meeting there), interpolated
  // linearly along each segment: a frame continuous along the chain.
  int i;
  double f;
  locate(*this, wrap(*this, s), i, f);
  const SegmentFrame fr = segment_frame(*this, i, f);
  c = fr.c;
  b = fr.b;
}

void FrontPolyline::closest(const Eigen::Vector3d& x, double& s, double& distance, int* segment, bool* inside) const {
  const int m = segments(), np = static_cast<int>(points.size());
  double best = std::numeric_limits<double>::infinity();
  s = 0.0;
  for (int i = 0; i < m; ++i) {
    const Eigen::Vector3d p0 = points[i], d = points[(i + 1) % np] - p0;
    const double len2 = d.squaredNorm();
    const double t_free = len2 > 0 ? (x - p0).dot(d) / len2 : 0.0;
    const double t = std::clamp(t_free, 0.0, 1.0);
    const double d2 = (p0 + t * d - x).squaredNorm();
    if (d2 < best) {
      best = d2;
      s = arc[i] + t * std::sqrt(len2);
      if (segment) *segment = i;
      if (inside) *inside = t_free > 0.0 && t_free < 1.0;
    }
  }
  distance = std::sqrt(best);
}

double FrontPolyline::arc_offset(double s0, double s) const {
  double d = s - s0;
  if (closed) {
    d = std::fmod(d, length);
    if (d > 0.5 * length) d -= length;
    if (d <= -0.5 * length) d += length;
  }
  return d;
}

CrackFront read_front(const TetMesh& mesh, const std::string& file) {
  const DataArray& seg =
      require_array(mesh.field_data, "front_segments", "field", 6, static_cast<std::size_t>(-1), file, "xfem-classify");
  const DataArray& nrm =
      require_array(mesh.field_data, "front_normals", "field", 3, seg.tuples(), file, "xfem-classify");
  std::vector<FrontSegment> segments(seg.tuples());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    segments[i].p0 = Eigen::Vector3d(seg(i, 0), seg(i, 1), seg(i, 2));
    segments[i].p1 = Eigen::Vector3d(seg(i, 3), seg(i, 4), seg(i, 5));
    segments[i].b = Eigen::Vector3d(nrm(i, 0), nrm(i, 1), nrm(i, 2));
  }
  try {
    return CrackFront(std::move(segments));
  } catch (const Error& e) {
    throw Error(file + ": field array 'front_segments': " + e.what());
  }
}

void store_front(const CrackFront& front, TetMesh& mesh) {
  const auto& s = front.segments();
  DataArray seg = make_array(DataArray::Type::Float64, 6, s.size());
  DataArray nrm = make_array(DataArray::Type::Float64, 3, s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      seg.values[6 * i + k] = s[i].p0[k];
      seg.values[6 * i + 3 + k] = s[i].p1[k];
      nrm.values[3 * i + k] = s[i].b[k];
    }
  }
  mesh.field_data["front_segments"] = std::move(seg);
  mesh.field_data["front_normals"] = std::move(nrm);
}

}  // namespace xfem
