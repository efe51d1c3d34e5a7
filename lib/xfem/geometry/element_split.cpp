// SPDX-License-Identifier: MIT
#include "xfem/geometry/element_split.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>

#include "xfem/geometry/cut_pieces.h"
#include "xfem/geometry/cut_surface.h"
#include "xfem/core/error.h"
#include "xfem/core/parallel_for.h"

namespace xfem {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Triangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point to_cgal(const Eigen::Vector3d& p) { return Point(p[0], p[1], p[2]); }

// A cut through a node puts the edge point on the node (a separate point, one copy per side): the
// pieces between it and the node have zero volume and are left out (kDegenerate), so the volumes
// on each side stay exact.
constexpr double kEdgeClamp = 0.0;

// Pieces below this fraction of their element's volume, and wound triangles below this fraction of
// the element's longest edge squared, are degenerate (a cut through a node, an edge or a face).
constexpr double kDegenerate = 1e-14;

// Front segments reach this fraction of their length beyond their ends when faces are pierced.
constexpr double kFrontReach = 1e-6;

// A point of an element's subdivision before it gets an output id: a mesh node, an edge point,
// a face (front) point or the element's centre M.
enum Kind { Node = 0, EdgePoint = 1, FacePoint = 2, Centre = 3 };
struct Ref {
  Kind kind;
  int index;
};

struct FaceTriangle {
  std::array<Ref, 3> v;
  int side;  // +1 / -1, 0 where it spans both sides (ahead of the front)
};

// The state of one split: caches of edge and front points (shared by the tets around an edge or
// face) and the new points. A plain struct used by split_mesh only.
struct Splitter {
  Splitter(const TetMesh& mesh, const std::vector<int>& side, const TriangleMesh& cut,
           const std::vector<FrontSegment>& front)
      : mesh_(mesh), side_(side), cut_(cut), front_(front) {
    for (Eigen::Index f = 0; f < cut.triangles.rows(); ++f)
      triangles_.emplace_back(to_cgal(cut.points.row(cut.triangles(f, 0))), to_cgal(cut.points.row(cut.triangles(f, 1))),
                              to_cgal(cut.points.row(cut.triangles(f, 2))));
    if (!triangles_.empty()) {
      tree_.insert(triangles_.begin(), triangles_.end());
      tree_.build();
    }
  }

  Eigen::Vector3d node(int k) const { return mesh_.points.row(k).transpose(); }

  // Index into edge_points_ of the split point of edge (a, b), -1 when the edge is not split.
  int edge_point(int a, int b) {
    if (a > b) std::swap(a, b);
    const auto key = std::make_pair(a, b);
    const auto it = edges_.find(key);
    if (it != edges_.end()) return it->second;
    Eigen::Vector3d p;
    return add_edge(a, b, crossing(a, b, p), p);
  }

  // Caches the split points of `edges` (a < b each, no repeats), computed in parallel: edge_point
  // then only looks them up.
  void add_edges(const std::vector<std::pair<int, int>>& edges) {
    std::vector<Eigen::Vector3d> points(edges.size());
    std::vector<char> split(edges.size());
    parallel_for(static_cast<long>(edges.size()), [&](long begin, long end) {
      for (long i = begin; i < end; ++i) split[i] = crossing(edges[i].first, edges[i].second, points[i]);
    }, {}, 64);
    for (std::size_t i = 0; i < edges.size(); ++i) add_edge(edges[i].first, edges[i].second, split[i], points[i]);
  }

  int add_edge(int a, int b, bool split, const Eigen::Vector3d& p) {
    const int result = split ? static_cast<int>(edge_points_.size()) : -1;
    if (split) edge_points_.push_back(p);
    edges_.emplace(std::make_pair(a, b), result);
    return result;
  }

  // Is edge (a, b), a < b, split, and where (p)? A function of the edge and the cut only.
  bool crossing(int a, int b, Eigen::Vector3d& p) const {
    if (side_[a] != side_[b] && !triangles_.empty()) {
      const Eigen::Vector3d pa = node(a), pb = node(b), d = pb - pa;
      std::vector<TriangleIterator> hits;
      tree_.all_intersected_primitives(Segment(to_cgal(pa), to_cgal(pb)), std::back_inserter(hits));
      double best = 2.0;
      for (const auto& h : hits) {
        const int f = static_cast<int>(h - triangles_.begin());
        const Eigen::Vector3d p0 = cut_.points.row(cut_.triangles(f, 0)).transpose();
        const Eigen::Vector3d n = (cut_.points.row(cut_.triangles(f, 1)).transpose() - p0)
                                      .cross(cut_.points.row(cut_.triangles(f, 2)).transpose() - p0);
        const double den = n.dot(d);
        if (den == 0.0) continue;  // the edge lies in the triangle's plane: not a crossing
        best = std::min(best, std::clamp(n.dot(p0 - pa) / den, 0.0, 1.0));
      }
      // Sides that differ although the segment misses the cut: an end point was put on the cut
      // by the round-off rule D1 (docs/CLASSIFICATION.md) while lying a hair off it. The cut
      // passes through that end point.
      if (best > 1.0) {
        const double da = tree_.squared_distance(to_cgal(pa)), db = tree_.squared_distance(to_cgal(pb));
        if (std::min(da, db) <= 1e-12 * d.squaredNorm()) best = da <= db ? 0.0 : 1.0;
      }
      if (best <= 1.0) {
        best = std::clamp(best, kEdgeClamp, 1.0 - kEdgeClamp);
        p = pa + best * d;
        return true;
      }
    }
    return false;
  }

  // Index into face_points_ of the point where the cut front pierces face (a, b, c), -1 if none.
  int face_point(std::array<int, 3> f) {
    std::sort(f.begin(), f.end());
    const auto it = faces_.find(f);
    if (it != faces_.end()) return it->second;
    const Eigen::Vector3d p0 = node(f[0]), p1 = node(f[1]), p2 = node(f[2]);
    const Triangle tri(to_cgal(p0), to_cgal(p1), to_cgal(p2));
    const Eigen::Vector3d n = (p1 - p0).cross(p2 - p0);
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int count = 0;
    for (const auto& s : front_) {
      // Fronts are clipped to the body, so a front ending on a boundary face may stop a rounding
      // error short of it: each segment is lengthened by kFrontReach of its length at both ends.
      const Eigen::Vector3d a = s.p0 - kFrontReach * (s.p1 - s.p0), b = s.p1 + kFrontReach * (s.p1 - s.p0);
      if (!CGAL::do_intersect(tri, Segment(to_cgal(a), to_cgal(b)))) continue;
      const double den = n.dot(b - a);
      if (den == 0.0) continue;  // front segment lying in the face: no single piercing point
      sum += a + std::clamp(n.dot(p0 - a) / den, 0.0, 1.0) * (b - a);
      ++count;  // a front vertex on the face is reported by both its segments: averaged
    }
    int result = -1;
    if (count > 0) {
      result = static_cast<int>(face_points_.size());
      face_points_.push_back(sum / count);
    }
    faces_.emplace(f, result);
    return result;
  }

  int common_side(std::initializer_list<int> nodes) const {
    const int s = side_[*nodes.begin()];
    for (int k : nodes)
      if (side_[k] != s) return 0;
    return s;
  }

  // Triangulates face (a, b, c) from its own edge and front points only, so that both tets sharing
  // it triangulate it alike; appends the cut's segments on it to `crack`.
  void split_face(int a, int b, int c, std::vector<FaceTriangle>& out, std::vector<std::array<Ref, 2>>& crack) {
    const std::array<int, 3> v = {a, b, c};
    std::array<int, 3> e;  // e[i]: point of edge (v[i], v[i+1])
    int split = 0;
    for (int i = 0; i < 3; ++i) {
      e[i] = edge_point(v[i], v[(i + 1) % 3]);
      if (e[i] >= 0) ++split;
    }
    auto N = [](int k) { return Ref{Node, k}; };
    auto E = [](int k) { return Ref{EdgePoint, k}; };
    if (split == 0) {
      out.push_back({{N(a), N(b), N(c)}, common_side({a, b, c})});
    } else if (split == 2) {
      // The lone node L is the one both split edges meet at; P, Q are the others.
      int i = 0;
      while (!(e[i] >= 0 && e[(i + 2) % 3] >= 0)) ++i;
      const int L = v[i], P = v[(i + 1) % 3], Q = v[(i + 2) % 3];
      const Ref EP = E(e[i]), EQ = E(e[(i + 2) % 3]);
      out.push_back({{N(L), EP, EQ}, side_[L]});
      if (P < Q) {
        out.push_back({{EP, N(P), EQ}, side_[P]});
        out.push_back({{N(P), N(Q), EQ}, side_[P]});
      } else {
        out.push_back({{EP, N(P), N(Q)}, side_[P]});
        out.push_back({{EP, N(Q), EQ}, side_[P]});
      }
      crack.push_back({EP, EQ});
    } else {
      int i = 0;
      while (e[i] < 0) ++i;
      const int X = v[i], Y = v[(i + 1) % 3], Z = v[(i + 2) % 3];
      const Ref EX = E(e[i]);
      const int fp = face_point({a, b, c});
      if (fp >= 0) {
        const Ref F{FacePoint, fp};
        out.push_back({{F, N(X), EX}, side_[X]});
        out.push_back({{F, EX, N(Y)}, side_[Y]});
        out.push_back({{F, N(Y), N(Z)}, common_side({Y, Z})});
        out.push_back({{F, N(Z), N(X)}, common_side({Z, X})});
        crack.push_back({EX, F});
      } else {
        std::array<int, 3> key = v;
        std::sort(key.begin(), key.end());
        degenerate_.insert(key);
        out.push_back({{EX, N(Y), N(Z)}, common_side({Y, Z})});
        out.push_back({{N(X), EX, N(Z)}, common_side({X, Z})});
      }
    }
  }

  // Output id of a point copy; nodes keep their own id, other points one id per (point, side).
  int output_id(const Ref& r, int side, int tet, const std::array<int, 3>& centre_ids) {
    if (r.kind == Node) return r.index;
    if (r.kind == Centre) return centre_ids[side + 1];
    if (r.kind == FacePoint) side = 0;  // on the front: both sides meet there
    const auto key = std::make_tuple(static_cast<int>(r.kind), r.index, side);
    const auto it = copies_.find(key);
    if (it != copies_.end()) return it->second;
    const int id = add_point(r.kind == EdgePoint ? edge_points_[r.index] : face_points_[r.index], side, tet);
    copies_.emplace(key, id);
    return id;
  }

  int add_point(const Eigen::Vector3d& x, int side, int tet) {
    points_.push_back(x);
    point_side_.push_back(side);
    point_tet_.push_back(tet);
    return static_cast<int>(mesh_.points.rows() + points_.size()) - 1;  // new points follow the nodes
  }

  const TetMesh& mesh_;
  const std::vector<int>& side_;
  const TriangleMesh& cut_;
  const std::vector<FrontSegment>& front_;
  std::vector<Triangle> triangles_;
  Tree tree_;
  std::map<std::pair<int, int>, int> edges_;
  std::map<std::array<int, 3>, int> faces_;
  std::set<std::array<int, 3>> degenerate_;
  std::map<std::tuple<int, int, int>, int> copies_;
  std::vector<Eigen::Vector3d> edge_points_, face_points_;
  std::vector<Eigen::Vector3d> points_;  // new points (after the NP nodes)
  std::vector<int> point_side_, point_tet_;
};

// Do the cut triangles meeting the tet all lie in one plane? Then the face-by-face split through
// the edge points is exact and conforming; otherwise (a fold inside) the tet is split into its
// exact pieces.
bool planar_inside(const CutSurface& cut, const std::vector<int>& triangles, const TetCorners& p) {
  if (triangles.size() <= 1) return true;
  double h = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) h = std::max(h, (p[i] - p[j]).norm());
  const TriangleMesh& m = cut.mesh();
  const Eigen::Vector3d n0 = cut.unit_normal(triangles[0]), x0 = m.points.row(m.triangles(triangles[0], 0)).transpose();
  for (const int f : triangles) {
    if (cut.unit_normal(f).dot(n0) < 1 - 1e-12) return false;
    for (int c = 0; c < 3; ++c)
      if (std::abs(n0.dot(m.points.row(m.triangles(f, c)).transpose() - x0)) > 1e-12 * h) return false;
  }
  return true;
}

// A tet split into its exact pieces (cut_pieces.h), its new points numbered on their own: in
// `tets` and `wound` a reference r >= 0 is a mesh node, r < 0 the new point -1 - r of `points`, in
// the order in which the tet's pieces and then its wound first use them (the order split_mesh gives
// them their ids in). It depends on the tet and the cut only, so it is computed for all cut tets in
// parallel; split_mesh then numbers the new points tet after tet, in tet order.
struct ExactSplit {
  bool exact = false;  // false: a completely cut tet with the cut planar inside (split face by face)
  std::vector<Eigen::Vector3d> points;
  std::vector<int> point_side;
  std::vector<std::array<int, 4>> tets;
  std::vector<int> tet_side;
  std::vector<std::array<int, 3>> wound;
  std::vector<int> wound_side;
};

// An element the front passes through (`partial`), or one the cut separates but not in one plane (a
// fold inside it): its exact pieces, the wound being the cut triangles clipped to it. Their points
// are its own.
ExactSplit exact_split(const TetMesh& mesh, int t, bool partial, const std::vector<int>& side, const CutSurface& cut,
                       const std::vector<FrontSegment>& front) {
  ExactSplit out;
  const std::array<int, 4> v = {mesh.tets(t, 0), mesh.tets(t, 1), mesh.tets(t, 2), mesh.tets(t, 3)};
  TetCorners corners;
  for (int c = 0; c < 4; ++c) corners[c] = mesh.points.row(v[c]).transpose();
  const std::vector<int> meeting = cut.triangles_meeting(corners);
  if (!partial && planar_inside(cut, meeting, corners)) return out;
  out.exact = true;
  double parent_edge = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) parent_edge = std::max(parent_edge, (corners[i] - corners[j]).norm());
  const CutPieces pieces = partial ? split_at_front(corners, cut, meeting, front) : split_by_cut(corners, cut, meeting);
  // Per point of a partial element: is the field continuous there? Kept, as a point is met once
  // per piece and wound triangle it is a corner of, and the answer costs a search of the cut.
  std::map<std::tuple<double, double, double>, bool> continuous;
  auto id_of = [&](const Eigen::Vector3d& x, int sd) {
    // In an element the front passes through, only points on the cut behind the front have
    // a copy per side; elsewhere (the front, the cut's plane ahead of it, off the cut) the
    // field is continuous and the pieces share one point.
    if (partial && sd != 0) {
      const auto key = std::make_tuple(x.x(), x.y(), x.z());
      auto it = continuous.find(key);
      if (it == continuous.end()) {
        bool on_front = false;
        for (const FrontSegment& f : front)
          on_front = on_front || point_segment_distance(x, f.p0, f.p1) <= 1e-12 * parent_edge;
        it = continuous.emplace(key, on_front || cut.closest(x).distance > 1e-12 * parent_edge).first;
      }
      if (it->second) sd = 0;
    }
    for (int c = 0; c < 4; ++c)
      if ((side[v[c]] == sd || sd == 0) && corners[c] == x) return v[c];
    // A tet's few dozen points: a scan is quicker than a search tree.
    for (std::size_t k = 0; k < out.points.size(); ++k)
      if (out.point_side[k] == sd && out.points[k] == x) return -1 - static_cast<int>(k);
    out.points.push_back(x);
    out.point_side.push_back(sd);
    return -static_cast<int>(out.points.size());
  };
  for (std::size_t i = 0; i < pieces.tets.size(); ++i) {
    const TetCorners& q = pieces.tets[i];
    const int sd = pieces.side[i];
    std::array<int, 4> ids4;
    for (int c = 0; c < 4; ++c) ids4[c] = id_of(q[c], sd);
    out.tets.push_back(ids4);
    out.tet_side.push_back(sd);
  }
  // The wound: the cut's triangles clipped to the element, once per side, each oriented out
  // of its side's pieces (towards the other side).
  const TriangleMesh& cm = cut.mesh();
  for (const int f : meeting) {
    const std::vector<Eigen::Vector3d> polygon =
        clip_triangle(corners, cm.points.row(cm.triangles(f, 0)).transpose(),
                      cm.points.row(cm.triangles(f, 1)).transpose(), cm.points.row(cm.triangles(f, 2)).transpose());
    if (!(polygon_area(polygon) > kDegenerate * parent_edge * parent_edge)) continue;
    const Eigen::Vector3d n = cut.unit_normal(f);
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
      for (int sd : {1, -1}) {
        std::array<int, 3> w = {id_of(polygon[0], sd), id_of(polygon[i], sd), id_of(polygon[i + 1], sd)};
        const Eigen::Vector3d normal = (polygon[i] - polygon[0]).cross(polygon[i + 1] - polygon[0]);
        if (normal.norm() <= kDegenerate * parent_edge * parent_edge) continue;
        if (sd * normal.dot(n) > 0) std::swap(w[1], w[2]);
        out.wound.push_back(w);
        out.wound_side.push_back(sd);
      }
  }
  return out;
}

// split_mesh with the cut's CutSurface `given` by the caller, or built here from `cut` when an
// element is cut (null: none given).
SplitMesh split(const TetMesh& mesh, const std::vector<int>& side, const std::vector<int>& cut_class,
                const TriangleMesh& cut, const CutSurface* given, const std::vector<FrontSegment>& front) {
  const int np = static_cast<int>(mesh.points.rows()), nt = static_cast<int>(mesh.tets.rows());
  if (static_cast<int>(side.size()) != np)
    throw Error("split_mesh: " + std::to_string(side.size()) + " point sides for " + std::to_string(np) + " points");
  if (static_cast<int>(cut_class.size()) != nt)
    throw Error("split_mesh: " + std::to_string(cut_class.size()) + " cut classes for " + std::to_string(nt) + " tets");
  for (int k = 0; k < np; ++k)
    if (side[k] != 1 && side[k] != -1)
      throw Error("split_mesh: point " + std::to_string(k) + " has side " + std::to_string(side[k]) + ", expected +1 or -1");
  for (int t = 0; t < nt; ++t)
    if (cut_class[t] < 0 || cut_class[t] > 2)
      throw Error("split_mesh: tet " + std::to_string(t) + " has cut class " + std::to_string(cut_class[t]) +
                  ", expected 0, 1 or 2");

  Splitter s(mesh, side, cut, front);
  // The cut tets' exact pieces, each on its own and so in parallel (parallel_for.h): most of the
  // work on a curved cut. Small chunks, as the cost of a tet varies with the cut inside it.
  std::vector<int> cut_tets;
  for (int t = 0; t < nt; ++t)
    if (cut_class[t] > 0) cut_tets.push_back(t);
  std::unique_ptr<CutSurface> built;
  if (!given && !cut_tets.empty()) built = std::make_unique<CutSurface>(cut);
  const CutSurface* cut_surface = given ? given : built.get();
  std::vector<ExactSplit> exact(cut_tets.size());
  parallel_for(static_cast<long>(cut_tets.size()), [&](long begin, long end) {
    for (long i = begin; i < end; ++i)
      exact[i] = exact_split(mesh, cut_tets[i], cut_class[cut_tets[i]] == 1, side, *cut_surface, front);
  }, {}, 8);
  // The split points of the cut tets' edges between nodes of opposite sides, in parallel too.
  std::vector<std::pair<int, int>> edges;
  for (const int t : cut_tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const int a = mesh.tets(t, i), b = mesh.tets(t, j);
        if (side[a] != side[b]) edges.emplace_back(std::min(a, b), std::max(a, b));
      }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  s.add_edges(edges);
  // A completely cut element with an edge between nodes of opposite sides that the cut does not
  // meet: the front passes through one of its nodes or edges (a front through a mesh node, the
  // element classified completely cut by the round-off rule). Split face by face, its faces with
  // one split edge would have no front point; it is split exactly at the front instead, as an
  // element the front runs through (the cut catalogue's "front through a node").
  std::vector<char> front_touched(cut_tets.size(), 0);
  std::vector<long> touched;
  for (std::size_t i = 0; i < cut_tets.size(); ++i) {
    const int t = cut_tets[i];
    if (cut_class[t] != 2) continue;
    bool split = false, open = false;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (side[mesh.tets(t, a)] != side[mesh.tets(t, b)]) (s.edge_point(mesh.tets(t, a), mesh.tets(t, b)) >= 0 ? split : open) = true;
    if (split && open) {
      front_touched[i] = 1;
      touched.push_back(static_cast<long>(i));
    }
  }
  parallel_for(static_cast<long>(touched.size()), [&](long begin, long end) {
    for (long k = begin; k < end; ++k)
      exact[touched[k]] = exact_split(mesh, cut_tets[touched[k]], true, side, *cut_surface, front);
  }, {}, 8);
  // Uncut tets are kept whole, turned positive: their orientations too, in parallel.
  std::vector<char> inverted(nt, 0);
  parallel_for(nt, [&](long begin, long end) {
    for (long t = begin; t < end; ++t)
      if (cut_class[t] == 0)
        inverted[t] = signed_volume(s.node(mesh.tets(t, 0)), s.node(mesh.tets(t, 1)), s.node(mesh.tets(t, 2)),
                                    s.node(mesh.tets(t, 3))) < 0;
  });
  std::size_t next_exact = 0;  // exact[next_exact] is the next cut tet's, in tet order
  // Each node's field is evaluated in the first tet that holds it.
  std::vector<int> node_tet(np, -1);
  for (int t = nt - 1; t >= 0; --t)
    for (int c = 0; c < 4; ++c) node_tet[mesh.tets(t, c)] = t;

  SplitMesh out;
  std::vector<std::array<int, 4>> tets;
  std::vector<std::array<int, 3>> wound;
  // Room for about every tet and point, so that the arrays are seldom copied as they grow (a cut tet
  // split face by face makes a few cone tets per face).
  std::size_t room = nt, new_points = 0;
  for (const ExactSplit& e : exact) {
    room += e.exact ? e.tets.size() : 12;
    new_points += e.exact ? e.points.size() : 16;
  }
  tets.reserve(room);
  out.parent.reserve(room);
  out.tet_side.reserve(room);
  s.points_.reserve(new_points);
  s.point_side_.reserve(new_points);
  s.point_tet_.reserve(new_points);
  auto position = [&](int id) -> Eigen::Vector3d {
    return id < np ? s.node(id) : s.points_[id - np];
  };
  double parent_volume = 0.0, parent_edge = 0.0;  // of the element being split
  auto add_tet = [&](std::array<int, 4> v, int parent, int tet_side) {
    const double volume = signed_volume(position(v[0]), position(v[1]), position(v[2]), position(v[3]));
    if (tet_side != 0 && std::abs(volume) <= kDegenerate * parent_volume) return;
    if (volume < 0) std::swap(v[1], v[2]);
    tets.push_back(v);
    out.parent.push_back(parent);
    out.tet_side.push_back(tet_side);
  };

  static const int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  for (int t = 0; t < nt; ++t) {
    const std::array<int, 4> v = {mesh.tets(t, 0), mesh.tets(t, 1), mesh.tets(t, 2), mesh.tets(t, 3)};
    if (cut_class[t] == 0) {  // kept whole (as add_tet would)
      tets.push_back(inverted[t] ? std::array<int, 4>{v[0], v[2], v[1], v[3]} : v);
      out.parent.push_back(t);
      out.tet_side.push_back(0);
      continue;
    }
    bool any_split = false;
    bool closed = true;  // every edge between nodes of opposite sides is split
    Eigen::Vector3d edge_sum = Eigen::Vector3d::Zero();
    int edge_count = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        if (side[v[i]] == side[v[j]]) continue;
        const int e = s.edge_point(v[i], v[j]);
        if (e < 0) {
          closed = false;
          continue;
        }
        any_split = true;
        edge_sum += s.edge_points_[e];
        ++edge_count;
      }
    parent_volume = std::abs(signed_volume(s.node(v[0]), s.node(v[1]), s.node(v[2]), s.node(v[3])));
    parent_edge = 0.0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) parent_edge = std::max(parent_edge, (s.node(v[i]) - s.node(v[j])).norm());

    // An element the front passes through, or one the cut separates but not in one plane (a fold
    // inside it): its exact pieces, computed above (also, unused, for a completely cut element
    // whose edges are split only in part); here its new points get their ids.
    const bool partial = cut_class[t] == 1 || front_touched[next_exact];
    const ExactSplit* pieces = &exact[next_exact++];
    if (partial || ((closed || !any_split) && pieces->exact)) {
      const int first = np + static_cast<int>(s.points_.size());
      for (std::size_t k = 0; k < pieces->points.size(); ++k) s.add_point(pieces->points[k], pieces->point_side[k], t);
      auto id = [&](int r) { return r >= 0 ? r : first - 1 - r; };
      for (std::size_t i = 0; i < pieces->tets.size(); ++i) {
        const std::array<int, 4>& q = pieces->tets[i];
        add_tet({id(q[0]), id(q[1]), id(q[2]), id(q[3])}, t, pieces->tet_side[i]);
      }
      for (std::size_t i = 0; i < pieces->wound.size(); ++i) {
        const std::array<int, 3>& w = pieces->wound[i];
        wound.push_back({id(w[0]), id(w[1]), id(w[2])});
        out.wound_side.push_back(pieces->wound_side[i]);
      }
      ++(partial ? out.split_partial : out.split_complete);
      continue;
    }
    if (!any_split) {
      add_tet(v, t, 0);
      continue;
    }

    // 1. The faces, triangulated alike from both sides, and the cut's segments on them.
    std::vector<FaceTriangle> triangles;
    std::vector<std::array<Ref, 2>> crack;
    for (const auto& f : kFaces) s.split_face(v[f[0]], v[f[1]], v[f[2]], triangles, crack);

    // 2. The centre M: on the cut inside the element; on the front when the element is split only
    // behind it. Kept strictly inside the tet so that every cone tet has positive volume.
    Eigen::Vector3d centre = edge_sum / edge_count;
    if (!closed) {
      Eigen::Vector3d front_sum = Eigen::Vector3d::Zero();
      int front_count = 0;
      for (const auto& tri : triangles)
        for (const auto& r : tri.v)
          if (r.kind == FacePoint) {
            front_sum += s.face_points_[r.index];
            ++front_count;
          }
      // Every face point appears in four fan triangles of its face: the mean is unaffected.
      if (front_count > 0) centre = front_sum / front_count;
    }
    if (!closed) {  // a centre on the front; a crossed element's centre stays on the cut (exact volumes)
      Eigen::Matrix3d J;
      for (int c = 0; c < 3; ++c) J.col(c) = s.node(v[c + 1]) - s.node(v[0]);
      const Eigen::Vector3d l = J.partialPivLu().solve(centre - s.node(v[0]));
      const double l0 = 1.0 - l.sum();
      if (std::min({l0, l[0], l[1], l[2]}) < 1e-3) {
        const Eigen::Vector3d centroid = (s.node(v[0]) + s.node(v[1]) + s.node(v[2]) + s.node(v[3])) / 4;
        centre = 0.5 * (centre + centroid);
      }
    }
    std::array<int, 3> centre_ids{};  // per side -1, 0, +1
    if (closed) {
      centre_ids[0] = s.add_point(centre, -1, t);
      centre_ids[1] = centre_ids[2];  // unused: every face triangle of a crossed element has a side
      centre_ids[2] = s.add_point(centre, 1, t);
      ++out.split_complete;
    } else {
      centre_ids[0] = centre_ids[1] = centre_ids[2] = s.add_point(centre, 0, t);
      ++out.split_partial;
    }

    // 3. Cone every face triangle to M; each cone takes its face triangle's side.
    for (const auto& tri : triangles) {
      std::array<int, 4> ids;
      for (int c = 0; c < 3; ++c) ids[c] = s.output_id(tri.v[c], tri.side, t, centre_ids);
      ids[3] = centre_ids[tri.side + 1];
      add_tet(ids, t, tri.side);
    }

    // 4. The wound: the fan from M over the cut's segments, once per side, each oriented out of its
    // side's piece (towards the other side).
    Eigen::Vector3d above = Eigen::Vector3d::Zero(), below = Eigen::Vector3d::Zero();
    int n_above = 0;
    for (int c = 0; c < 4; ++c) {
      if (side[v[c]] > 0) {
        above += s.node(v[c]);
        ++n_above;
      } else {
        below += s.node(v[c]);
      }
    }
    const Eigen::Vector3d up = above / n_above - below / (4 - n_above);
    for (const auto& seg : crack)
      for (int sd : {1, -1}) {
        std::array<int, 3> w = {centre_ids[sd + 1], s.output_id(seg[0], sd, t, centre_ids),
                                s.output_id(seg[1], sd, t, centre_ids)};
        const Eigen::Vector3d n = (position(w[1]) - position(w[0])).cross(position(w[2]) - position(w[0]));
        if (n.norm() <= kDegenerate * parent_edge * parent_edge) continue;  // a cut through a node or an edge
        if (sd * n.dot(up) > 0) std::swap(w[1], w[2]);
        wound.push_back(w);
        out.wound_side.push_back(sd);
      }
  }

  const int total = np + static_cast<int>(s.points_.size());
  out.points.resize(total, 3);
  out.point_side.resize(total);
  out.point_tet.resize(total);
  for (int k = 0; k < np; ++k) {
    out.points.row(k) = mesh.points.row(k);
    out.point_side[k] = side[k];
    out.point_tet[k] = node_tet[k];
  }
  for (int k = np; k < total; ++k) {
    out.points.row(k) = s.points_[k - np].transpose();
    out.point_side[k] = s.point_side_[k - np];
    out.point_tet[k] = s.point_tet_[k - np];
  }
  out.tets.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (std::size_t i = 0; i < tets.size(); ++i)
    for (int c = 0; c < 4; ++c) out.tets(static_cast<Eigen::Index>(i), c) = tets[i][c];
  out.wound.resize(static_cast<Eigen::Index>(wound.size()), 3);
  for (std::size_t i = 0; i < wound.size(); ++i)
    for (int c = 0; c < 3; ++c) out.wound(static_cast<Eigen::Index>(i), c) = wound[i][c];
  out.degenerate_faces = static_cast<int>(s.degenerate_.size());
  return out;
}

}  // namespace

SplitMesh split_mesh(const TetMesh& mesh, const std::vector<int>& side, const std::vector<int>& cut_class,
                     const TriangleMesh& cut, const std::vector<FrontSegment>& front) {
  return split(mesh, side, cut_class, cut, nullptr, front);
}

SplitMesh split_mesh(const TetMesh& mesh, const std::vector<int>& side, const std::vector<int>& cut_class,
                     const CutSurface& cut, const std::vector<FrontSegment>& front) {
  return split(mesh, side, cut_class, cut.mesh(), &cut, front);
}

SplitMesh unsplit_mesh(const TetMesh& mesh, const std::vector<int>& side) {
  const int np = static_cast<int>(mesh.points.rows()), nt = static_cast<int>(mesh.tets.rows());
  if (static_cast<int>(side.size()) != np)
    throw Error("unsplit_mesh: " + std::to_string(side.size()) + " point sides for " + std::to_string(np) + " points");
  SplitMesh out;
  out.points = mesh.points;
  out.point_side = side;
  out.point_tet.assign(np, 0);
  // Each node's field is evaluated in the first tet that holds it (a doubled node's own tets).
  for (int t = nt - 1; t >= 0; --t)
    for (int c = 0; c < 4; ++c) out.point_tet[mesh.tets(t, c)] = t;
  out.tets = mesh.tets;
  out.parent.resize(nt);
  for (int t = 0; t < nt; ++t) out.parent[t] = t;
  out.tet_side.assign(nt, 0);
  out.wound.resize(0, 3);
  return out;
}

}  // namespace xfem
