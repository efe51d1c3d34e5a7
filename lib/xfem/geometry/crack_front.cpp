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

void vertex_frame(const FrontPolyline& p, int v, Eigen::Vector3d& cv, Eigen::Vector3d& bv);
void cached_vertex_frame(const FrontPolyline& p, int v, Eigen::Vector3d& cv, Eigen::Vector3d& bv);

// Where x's normal plane meets segment i of a chain, as the fraction f in [0, 1] along it, or -1
// if it does not. Along the segment P(f) = p_i + f d and the tangent is c(f) = c~(f) / |c~(f)|
// with c~(f) = c_i + f (c_j - c_i) (FrontPolyline::frame), so g(f) = (x - P(f)) . c(f) has the
// sign of the quadratic h(f) = (w - f d) . (c_i + f e), w = x - p_i, e = c_j - c_i. Solved in
// closed form: this is called for every integration point of a branch-enriched tet, and the
// bisection it replaces dominated xfem-assemble on curved fronts. As before, a segment whose ends
// have the same strict sign of g holds no foot (its two roots, if any, belong to a fold of the
// normal planes beyond the front's radius of curvature).
double normal_plane_root(const FrontPolyline& ch, int i, const Eigen::Vector3d& x) {
  const int j = (i + 1) % static_cast<int>(ch.points.size());
  Eigen::Vector3d ci, cj, b;
  cached_vertex_frame(ch, i, ci, b);
  cached_vertex_frame(ch, i + 1, cj, b);
  const Eigen::Vector3d w = x - ch.points[i], d = ch.points[j] - ch.points[i], e = cj - ci;
  const double h0 = w.dot(ci), h1 = (x - ch.points[j]).dot(cj);
  if ((h0 > 0 && h1 > 0) || (h0 < 0 && h1 < 0)) return -1.0;
  if (h0 == 0) return 0.0;
  if (h1 == 0) return 1.0;
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

}  // namespace

TipCoordinates CrackFront::coordinates(const Eigen::Vector3d& x) const {
  if (segments_.empty()) throw Error("crack front: no segments (the cut has no front inside the body)");
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
  // The search is bounded from the start by the segment tree's quick upper bound: it then skips at
  // once what lies farther. The bound only prunes; the choice is the scan's.
  double bound2 = index.by_chain.nearest_bound2(x);
  double best2 = std::numeric_limits<double>::infinity();
  const FrontPolyline* best = nullptr;
  double s = 0;
  int seg = 0;
  bool inside = false;
  index.by_chain.visit_near(x, bound2, [&](int k) {
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
  index.by_chain.visit_near(x, reach2, [&](int k) {
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
  const FrontPolyline& ch = *best;
  const int np = static_cast<int>(ch.points.size());
  const Eigen::Vector3d d = ch.points[(seg + 1) % np] - ch.points[seg];
  const double len = d.norm();
  const Eigen::Vector3d P = ch.position(s);
  Eigen::Vector3d c, b;
  ch.frame(s, c, b);
  const Eigen::Vector3d a = b.cross(c), v = x - P;
  TipCoordinates out;
  out.xa = a.dot(v);
  out.xb = b.dot(v);
  out.grad.row(0) = a.transpose();
  out.grad.row(1) = b.transpose();
  if (inside) {
    // P and the frame move with s(x): grad xa = a + (a'(s) . v - a . u) grad s, likewise xb, with
    // u = P'(s) the segment's direction and, from g(s(x), x) = 0, grad s = c / (u . c - v . c'(s)).
    // The frame's derivative by a central difference inside the segment.
    const Eigen::Vector3d u = d / len;
    const double h = 1e-6 * len, lo = std::max(ch.arc[seg], s - h), hi = std::min(ch.arc[seg] + len, s + h);
    Eigen::Vector3d c_lo, b_lo, c_hi, b_hi;
    ch.frame(lo, c_lo, b_lo);
    ch.frame(hi, c_hi, b_hi);
    const Eigen::Vector3d da = (b_hi.cross(c_hi) - b_lo.cross(c_lo)) / (hi - lo), db = (b_hi - b_lo) / (hi - lo),
                          dc = (c_hi - c_lo) / (hi - lo);
    const Eigen::Vector3d grad_s = c / (u.dot(c) - v.dot(dc));
    out.grad.row(0) += (da.dot(v) - a.dot(u)) * grad_s.transpose();
    out.grad.row(1) += (db.dot(v) - b.dot(u)) * grad_s.transpose();
  }
  return out;
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
  const double end = i + 1 < static_cast<int>(p.arc.size()) ? p.arc[i + 1] : p.length;
  f = end > p.arc[i] ? std::clamp((s - p.arc[i]) / (end - p.arc[i]), 0.0, 1.0) : 0.0;
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
  const int j = (i + 1) % static_cast<int>(points.size());
  return (1 - f) * points[i] + f * points[j];
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
  Eigen::Vector3d c0, b0, c1, b1;
  cached_vertex_frame(*this, i, c0, b0);
  cached_vertex_frame(*this, i + 1, c1, b1);
  c = ((1 - f) * c0 + f * c1).normalized();
  b = (1 - f) * b0 + f * b1;
  b = (b - b.dot(c) * c).normalized();
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
