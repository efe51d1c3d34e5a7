// SPDX-License-Identifier: MIT
#include "xfem/enrich/classification.h"

#include "xfem/enrich/growing_classification.h"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <unordered_map>

#include "xfem/geometry/cut_pieces.h"
#include "xfem/geometry/point_location.h"
#include "xfem/core/error.h"
#include "xfem/core/parallel_for.h"

namespace xfem {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Segment = Kernel::Segment_3;
using SegmentIterator = std::vector<Segment>::const_iterator;
using SegmentTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_segment_primitive<Kernel, SegmentIterator>>>;

// Local edges of a tet (i < j) and, for the face opposite vertex k, its three local edges.
constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
constexpr int kFaceEdges[4][3] = {{3, 4, 5}, {1, 2, 5}, {0, 2, 4}, {0, 1, 3}};

Kernel::Point_3 to_cgal(const Eigen::Vector3d& x) { return {x.x(), x.y(), x.z()}; }

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

std::array<int, 3> face_key(const TetMesh& m, int t, int opposite) {
  std::array<int, 3> f;
  int n = 0;
  for (int k = 0; k < 4; ++k)
    if (k != opposite) f[n++] = m.tets(t, k);
  std::sort(f.begin(), f.end());
  return f;
}

struct FaceHash {
  std::size_t operator()(const std::array<int, 3>& f) const {
    return std::hash<std::uint64_t>()((static_cast<std::uint64_t>(f[0]) * 73856093u) ^
                                      (static_cast<std::uint64_t>(f[1]) * 19349663u) ^
                                      (static_cast<std::uint64_t>(f[2]) * 83492791u));
  }
};

/// A tet's corners, bounding box and barycentric coordinates, for clipping segments to it.
struct TetGeometry {
  Eigen::Vector3d P[4];
  CGAL::Bbox_3 box;
  Eigen::Matrix3d Jinv;
  TetGeometry(const TetMesh& mesh, long t) {
    for (int k = 0; k < 4; ++k) {
      P[k] = mesh.points.row(mesh.tets(t, k)).transpose();
      box += to_cgal(P[k]).bbox();
    }
    Eigen::Matrix3d J;
    J << P[1] - P[0], P[2] - P[0], P[3] - P[0];
    Jinv = J.inverse();
  }
  Eigen::Vector4d barycentric(const Eigen::Vector3d& x) const {
    const Eigen::Vector3d l = Jinv * (x - P[0]);
    return Eigen::Vector4d(1 - l.sum(), l[0], l[1], l[2]);
  }
};

/// The front (rule D4 and the orientation of crack_front.h): each boundary edge of the cut is
/// clipped to the candidate tets (cut tets and their node neighbours: a front inside the body
/// runs through them), the pieces of one edge merged, and pieces lying on the body's surface
/// dropped.
CrackFront extract_front(const TetMesh& mesh, const CutSurface& cut, const std::vector<char>& candidate) {
  const auto& edges = cut.boundary_edges();
  if (edges.empty()) return {};
  const TriangleMesh& cm = cut.mesh();
  std::vector<Segment> segments;
  for (const auto& e : edges)
    segments.emplace_back(to_cgal(cm.points.row(e.p0).transpose()), to_cgal(cm.points.row(e.p1).transpose()));
  SegmentTree tree(segments.cbegin(), segments.cend());

  struct Piece {
    int edge;
    double t0, t1;
    std::array<int, 3> face;  // a face the piece lies on ({-1,..} if inside the tet)
  };
  std::vector<Piece> pieces;
  std::vector<SegmentTree::Primitive_id> hits;
  constexpr double eps = 1e-10;  // barycentric tolerance: a piece this close to a face lies on it
  for (int t = 0; t < mesh.tets.rows(); ++t) {
    if (!candidate[t]) continue;
    const TetGeometry tg(mesh, t);
    hits.clear();
    tree.all_intersected_primitives(tg.box, std::back_inserter(hits));
    if (hits.empty()) continue;
    auto bary = [&](const Eigen::Vector3d& x) { return tg.barycentric(x); };
    std::sort(hits.begin(), hits.end());
    for (const auto& h : hits) {
      const int e = static_cast<int>(h - segments.cbegin());
      const Eigen::Vector3d a = cm.points.row(edges[e].p0).transpose(), b = cm.points.row(edges[e].p1).transpose();
      const Eigen::Vector4d la = bary(a), lb = bary(b);
      // Liang-Barsky on the 4 half-spaces lambda_k >= 0 along a + s (b - a), s in [0, 1]. An edge
      // running along a face plane (lambda_k constant) is kept if it lies on it within eps: a
      // front exactly on a face belongs to the tets on both sides.
      double s0 = 0, s1 = 1;
      for (int k = 0; k < 4 && s0 <= s1; ++k) {
        const double d = lb[k] - la[k];
        if (std::abs(d) <= eps) {
          if (std::max(la[k], lb[k]) < -eps) s0 = 2;
        } else if (d > 0) {
          s0 = std::max(s0, -la[k] / d);
        } else {
          s1 = std::min(s1, -la[k] / d);
        }
      }
      if (!(s1 - s0 > 1e-9)) continue;  // a point contact or nothing: no piece of front
      const Eigen::Vector4d lm = bary(a + 0.5 * (s0 + s1) * (b - a));
      Piece p{e, s0, s1, {-1, -1, -1}};
      for (int k = 0; k < 4; ++k)
        if (std::abs(lm[k]) <= eps) p.face = face_key(mesh, t, k);
      pieces.push_back(p);
    }
  }
  // D4: pieces on a face of the body's surface (a face of one tet only) are dropped.
  std::unordered_map<std::array<int, 3>, int, FaceHash> face_use;
  for (const Piece& p : pieces)
    if (p.face[0] >= 0) face_use[p.face] = 0;
  if (!face_use.empty())
    for (int t = 0; t < mesh.tets.rows(); ++t)
      for (int k = 0; k < 4; ++k) {
        const auto it = face_use.find(face_key(mesh, t, k));
        if (it != face_use.end()) ++it->second;
      }
  std::vector<Piece> kept;
  for (const Piece& p : pieces)
    if (p.face[0] < 0 || face_use[p.face] >= 2) kept.push_back(p);
  std::sort(kept.begin(), kept.end(), [](const Piece& x, const Piece& y) {
    return x.edge != y.edge ? x.edge < y.edge : x.t0 < y.t0;
  });
  std::vector<FrontSegment> front;
  for (std::size_t i = 0; i < kept.size();) {
    const int e = kept[i].edge;
    double s0 = kept[i].t0, s1 = kept[i].t1;
    std::size_t j = i + 1;
    for (; j < kept.size() && kept[j].edge == e && kept[j].t0 <= s1 + 1e-9; ++j) s1 = std::max(s1, kept[j].t1);
    const Eigen::Vector3d a = cm.points.row(edges[e].p0).transpose(), b = cm.points.row(edges[e].p1).transpose();
    // The owning triangle traverses its edge counter-clockwise about n: the triangle lies to the
    // left, n x (b - a) points into the cut. Reversing the edge makes a = b x c point away.
    FrontSegment seg;
    seg.p0 = a + s1 * (b - a);
    seg.p1 = a + s0 * (b - a);
    seg.b = cut.unit_normal(edges[e].triangle);
    front.push_back(seg);
    i = j;
  }
  return CrackFront(std::move(front));
}

/// How each candidate tet meets the front: 0 not at all, 1 on its boundary only (along a face or an
/// edge, or at a point), 2 through its inside. `corners` (4 bits per tet) marks the corners whose
/// star (the tets around the node) holds the contact in its inside: every corner for a front
/// through the tet, the corners of the face, edge or vertex the front lies on otherwise.
std::vector<char> front_contact(const TetMesh& mesh, const CrackFront& front, const std::vector<char>& candidate,
                                std::vector<unsigned char>& corners) {
  std::vector<char> contact(mesh.tets.rows(), 0);
  corners.assign(mesh.tets.rows(), 0);
  const auto& segs = front.segments();
  if (segs.empty()) return contact;
  std::vector<Segment> segments;
  for (const auto& s : segs) segments.emplace_back(to_cgal(s.p0), to_cgal(s.p1));
  SegmentTree tree(segments.cbegin(), segments.cend());
  parallel_for(mesh.tets.rows(), [&](long b, long e) {
    std::vector<SegmentTree::Primitive_id> hits;
    for (long t = b; t < e; ++t) {
      if (!candidate[t]) continue;
      const TetGeometry tg(mesh, t);
      hits.clear();
      tree.all_intersected_primitives(tg.box, std::back_inserter(hits));
      if (hits.empty()) continue;
      auto bary = [&](const Eigen::Vector3d& x) { return tg.barycentric(x); };
      constexpr double eps = 1e-10;  // barycentric: a front this close to a face lies on it
      for (const auto& h : hits) {
        const FrontSegment& fs = segs[h - segments.cbegin()];
        const Eigen::Vector4d la = bary(fs.p0), lb = bary(fs.p1);
        const double length = (fs.p1 - fs.p0).norm();
        double s0 = 0, s1 = 1;
        for (int k = 0; k < 4 && s0 <= s1 + eps; ++k) {
          const double d = lb[k] - la[k];
          if (std::abs(d) <= eps) {
            if (std::max(la[k], lb[k]) < -eps) s0 = 2;
          } else if (d > 0) {
            s0 = std::max(s0, (-eps - la[k]) / d);
          } else {
            s1 = std::min(s1, (-eps - la[k]) / d);
          }
        }
        if (s0 > s1) continue;
        // Positive length: longer than the tolerance band the clipping added at each end.
        const double tolerance = 4 * eps / std::max(1e-300, (lb - la).cwiseAbs().maxCoeff());
        // Through the inside (2), or only along a face, an edge or a point of the tet (1): a front
        // lying on a face ends a cut that separates the tet behind it.
        const Eigen::Vector4d mid = bary(fs.p0 + 0.5 * (s0 + s1) * (fs.p1 - fs.p0));
        const bool inside = mid.minCoeff() > 1e-9;
        const char kind = (s1 - s0) * length > 1e-9 * length + tolerance * length && inside ? 2 : 1;
        contact[t] = std::max(contact[t], kind);
        for (int k = 0; k < 4; ++k)
          if (kind == 2 || mid[k] > 1e-9) corners[t] |= static_cast<unsigned char>(1u << k);
        if (contact[t] == 2) break;
      }
    }
  });
  return contact;
}

// The mesh's unique edges and each tet's edges into `memory`.
void find_edges(const TetMesh& mesh, ClassificationMemory& memory) {
  const long T = mesh.tets.rows();
  std::vector<std::uint64_t> keys;
  keys.reserve(6 * T);
  for (long t = 0; t < T; ++t)
    for (const auto& e : kEdge) keys.push_back(edge_key(mesh.tets(t, e[0]), mesh.tets(t, e[1])));
  std::vector<std::uint64_t> unique = keys;
  std::sort(unique.begin(), unique.end());
  unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
  memory.tet_edges.assign(6 * T, 0);
  parallel_for(T, [&](long b, long e) {
    for (long i = 6 * b; i < 6 * e; ++i)
      memory.tet_edges[i] = static_cast<int>(std::lower_bound(unique.begin(), unique.end(), keys[i]) - unique.begin());
  });
  memory.unique = std::move(unique);
}

}  // namespace

// classify(), with the mesh's edges from `memory` and, when `growth` is given (the cut is the
// previous one of `memory` plus the triangles of `growth`), the previous cut's answers away from the
// new triangles. Leaves this cut's answers in `memory`.
Classification classify_with(const TetMesh& mesh, const CutSurface& cut, const ClassifyOptions& options,
                             ClassificationMemory& memory, const CutGrowth* growth,
                             ClassifyWork& stats) {
  const long V = mesh.points.rows(), T = mesh.tets.rows();
  Classification c;
  std::atomic<long> tested_points{0}, tested_edges{0}, tested_tets{0};
  auto report = [&](double lo, double hi) {
    return options.progress ? std::function<void(double)>([&, lo, hi](double f) { options.progress(lo + (hi - lo) * f); })
                            : std::function<void(double)>();
  };

  // 1. Points: on the cut (exactly, D1) and side H. A point's side is judged at its closest cut
  //    point; when every new triangle's box lies farther from the point than the previous cut did,
  //    that closest point stays where it was, on an old triangle whose feature (face, edge or
  //    vertex) gained no neighbour (a new triangle sharing it would hold that very point), so the
  //    pseudo-normal and the side stay too: only points some new triangle comes as close to are
  //    judged anew (GrowingCutClassifier, which keeps the distances).
  c.side.assign(V, 1);
  c.on_cut.assign(V, 0);
  const bool keep_distances = memory.keep_distances;
  const bool reuse_sides = growth && keep_distances && static_cast<long>(memory.distance.size()) == V &&
                           static_cast<long>(memory.side.size()) == V;
  if (keep_distances && !reuse_sides) memory.distance.assign(V, 0.0);
  //    The distance to the grown cut is the smaller of the distance to the old one and to the new
  //    triangles (computed for the points some new triangle's box comes that close to).
  std::vector<char> judge(reuse_sides ? V : 0, 0);
  std::atomic<long> judged{0};
  parallel_for(V, [&](long b, long e) {
    long sided = 0;
    if (reuse_sides) {
      for (long i = b; i < e; ++i) {
        const Eigen::Vector3d x = mesh.points.row(i).transpose();
        const double d = memory.distance[i];
        if (growth->near(x, x, d * (1 + 1e-9) + 1e-300)) {
          judge[i] = 1;
          memory.distance[i] = growth->distance(x, d);
        } else {
          c.side[i] = memory.side[i];
        }
      }
    } else {
      const std::vector<int> s = cut.sides(mesh.points, b, e);
      std::copy(s.begin(), s.end(), c.side.begin() + b);
      if (keep_distances)
        for (long i = b; i < e; ++i) memory.distance[i] = cut.closest(mesh.points.row(i).transpose()).distance;
      sided = e - b;
    }
    judged += sided;
    long tested = 0;
    for (long i = b; i < e; ++i) {
      const Eigen::Vector3d x = mesh.points.row(i).transpose();
      if (growth && (memory.on_cut[i] || !growth->near(x, x))) {
        c.on_cut[i] = memory.on_cut[i];  // met the old cut, or cannot meet a new triangle
      } else {
        c.on_cut[i] = cut.meets_segment(x, x);
        ++tested;
      }
    }
    tested_points += tested;
  }, report(0.0, 0.3));
  if (reuse_sides) {  // the sides judged anew, in the points' order (sides() is fastest on neighbours)
    std::vector<long> which;
    for (long i = 0; i < V; ++i)
      if (judge[i]) which.push_back(i);
    Points rows(static_cast<long>(which.size()), 3);
    for (std::size_t j = 0; j < which.size(); ++j) rows.row(static_cast<long>(j)) = mesh.points.row(which[j]);
    parallel_for(rows.rows(), [&](long b, long e) {
      const std::vector<int> s = cut.sides(rows, b, e);
      for (long j = b; j < e; ++j) c.side[which[j]] = s[j - b];
    }, {}, 1024);
    judged = static_cast<long>(which.size());
  }
  memory.on_cut = c.on_cut;
  if (keep_distances) memory.side = c.side;

  // 2. Unique edges, each tested once (D2 for edges with an end point on the cut). An edge whose
  //    end points are off the grown cut were off the old one: its old answer is known.
  if (memory.unique.empty()) find_edges(mesh, memory);
  const std::vector<std::uint64_t>& unique = memory.unique;
  std::vector<char> edge_cut(unique.size(), 0);
  if (!growth) memory.meets.assign(unique.size(), -1);
  parallel_for(static_cast<long>(unique.size()), [&](long b, long e) {
    long tested = 0;
    for (long i = b; i < e; ++i) {
      const int p = static_cast<int>(unique[i] >> 32), q = static_cast<int>(unique[i] & 0xffffffffu);
      if (c.on_cut[p] || c.on_cut[q]) {
        edge_cut[i] = c.side[p] != c.side[q];
        memory.meets[i] = -1;
        continue;
      }
      const Eigen::Vector3d a = mesh.points.row(p).transpose(), z = mesh.points.row(q).transpose();
      if (growth && memory.meets[i] >= 0 && (memory.meets[i] || !growth->near(a.cwiseMin(z), a.cwiseMax(z)))) {
        edge_cut[i] = memory.meets[i];
      } else {
        edge_cut[i] = cut.meets_segment(a, z);
        ++tested;
      }
      memory.meets[i] = edge_cut[i];
    }
    tested_edges += tested;
  }, report(0.3, 0.9), 256);  // small chunks: a small mesh's edges in threads too (each edge's answer is its own)

  // 2b. D1 with a round-off tolerance: a node closer to the cut than 1e-10 of the mesh's size
  //     (e.g. z = 0.10000000000000003 for a cut at z = 0.1, a mesher's midpoint) is on the cut.
  //     Left off the cut, it would give its neighbours a support of ~1e-17 relative volume on
  //     its side: K near-singular, and zero when no integration point lands there. Only end
  //     points of cut edges can matter, so only they are measured.
  const double on_cut_tolerance =
      1e-10 * (mesh.points.colwise().maxCoeff() - mesh.points.colwise().minCoeff()).norm();
  std::vector<char> snapped(V, 0);
  for (std::size_t i = 0; i < unique.size(); ++i) {
    if (!edge_cut[i]) continue;
    for (const int p : {static_cast<int>(unique[i] >> 32), static_cast<int>(unique[i] & 0xffffffffu)}) {
      if (c.on_cut[p] || snapped[p]) continue;
      // The kept distance is the true one to round-off: only points it puts near the tolerance are
      // measured again, as classify() measures them.
      if (keep_distances && memory.distance[p] > 2 * on_cut_tolerance) continue;
      if (cut.closest(mesh.points.row(p).transpose()).distance <= on_cut_tolerance) snapped[p] = 1;
    }
  }
  if (std::find(snapped.begin(), snapped.end(), 1) != snapped.end()) {
    for (long p = 0; p < V; ++p)
      if (snapped[p]) c.on_cut[p] = 1, c.side[p] = 1;
    for (std::size_t i = 0; i < unique.size(); ++i) {
      const int p = static_cast<int>(unique[i] >> 32), q = static_cast<int>(unique[i] & 0xffffffffu);
      if (snapped[p] || snapped[q]) edge_cut[i] = c.side[p] != c.side[q];
    }
  }

  // 3. Cut edges and completely cut faces per tet (reported; the paper's rule of 3.3 classified by
  //    them). A tet meets the cut when one of its edges does or one of its nodes lies on it.
  c.cut_edges.assign(T, 0);
  c.cut_faces.assign(T, 0);
  c.cut_class.assign(T, CutClass::Uncut);
  std::vector<char> meets(T, 0);
  parallel_for(T, [&](long b, long e) {
    for (long t = b; t < e; ++t) {
      bool cut_edge[6];
      int n = 0;
      for (int k = 0; k < 6; ++k) {
        cut_edge[k] = edge_cut[memory.tet_edges[6 * t + k]];
        n += cut_edge[k];
      }
      int faces = 0;
      for (const auto& f : kFaceEdges) faces += cut_edge[f[0]] + cut_edge[f[1]] + cut_edge[f[2]] >= 2;
      c.cut_edges[t] = n;
      c.cut_faces[t] = faces;
      bool touches = n > 0;
      for (int k = 0; k < 4; ++k) touches = touches || c.on_cut[mesh.tets(t, k)];
      meets[t] = touches;
    }
  });

  // 4. The front (the cut's boundary inside the body), from the tets near the cut, and how each
  //    tet meets it: the front passing through a tet makes it partially cut (by geometry, not by
  //    counting faces: a fold or a cut ending on a face is no front).
  std::vector<char> near_node(V, 0), candidate(T, 0);
  for (long t = 0; t < T; ++t)
    if (meets[t])
      for (int k = 0; k < 4; ++k) near_node[mesh.tets(t, k)] = 1;
  for (long t = 0; t < T; ++t)
    for (int k = 0; k < 4; ++k) candidate[t] |= near_node[mesh.tets(t, k)];
  c.front = extract_front(mesh, cut, candidate);
  std::vector<unsigned char> corners;
  const std::vector<char> contact = front_contact(mesh, c.front, candidate, corners);
  if (options.progress) options.progress(0.92);

  // 5. The tets the cut separates: split along the cut (cut_pieces.h), exact volumes per side.
  //    Completely cut = not partially cut, meets the cut, and separated (below).
  //    A tet's volumes are the old cut's when no new triangle comes within its longest edge h of it:
  //    the triangles meeting it are the same, and so is the closest cut point of each piece's
  //    centroid (at most h from a triangle meeting the tet), which gives the piece its side.
  if (!growth) memory.split.assign(T, 0);
  memory.above.resize(T, 0.0);
  memory.below.resize(T, 0.0);
  std::vector<double>& above = memory.above;
  std::vector<double>& below = memory.below;
  //    Which tets are split is decided first, then those are split each on its own with a small
  //    chunk (a few hundred cut tets of a mesh's thousands would otherwise fall into one or two of
  //    the tet loop's chunks, i.e. one thread): each tet's volumes depend on that tet alone, so the
  //    result does not depend on the thread count.
  std::vector<char> to_split(T, 0);
  parallel_for(T, [&](long b, long e) {
    for (long t = b; t < e; ++t) {
      if (contact[t] == 2 || !meets[t]) {
        memory.split[t] = 0;
        above[t] = below[t] = 0;
        if (contact[t] == 2) c.cut_class[t] = CutClass::Partial;
        continue;
      }
      bool known = growth && memory.split[t];
      if (known) {
        TetCorners p;
        for (int k = 0; k < 4; ++k) p[k] = mesh.points.row(mesh.tets(t, k)).transpose();
        Eigen::Vector3d lo = p[0], hi = p[0];
        double h = 0;
        for (int k = 0; k < 4; ++k) {
          lo = lo.cwiseMin(p[k]);
          hi = hi.cwiseMax(p[k]);
          for (int l = k + 1; l < 4; ++l) h = std::max(h, (p[k] - p[l]).norm());
        }
        known = !growth->near(lo, hi, h * (1 + 1e-9) + on_cut_tolerance);  // D1's snapping moves the cut that far
      }
      to_split[t] = !known;
    }
  });
  std::vector<long> split_list;
  for (long t = 0; t < T; ++t)
    if (to_split[t]) split_list.push_back(t);
  parallel_for(static_cast<long>(split_list.size()), [&](long b, long e) {
    for (long i = b; i < e; ++i) {
      const long t = split_list[i];
      TetCorners p;
      for (int k = 0; k < 4; ++k) p[k] = mesh.points.row(mesh.tets(t, k)).transpose();
      const CutPieces pieces = split_by_cut(p, cut);
      above[t] = pieces.volume_above;
      below[t] = pieces.volume_below;
      memory.split[t] = 1;
    }
  }, {}, 4);
  tested_tets += static_cast<long>(split_list.size());
  parallel_for(T, [&](long b, long e) {
    for (long t = b; t < e; ++t) {
      if (contact[t] == 2 || !meets[t]) continue;
      // Separated: some node's sign function lives in the tet (volume on the side opposite to the
      // node's own: across the cut, or below a node lying on it, which has side +1). A tet the
      // front only touches (all its nodes branch enriched) counts as separated only with volume
      // on both sides: ahead of a front lying on its face, H jumps across the cut's extension,
      // which is no cut.
      // But a node lying on the cut behind the front (on the cut, not one of the corners the front
      // touches) has its sign function below it in this tet too: a crack lying in a node layer
      // whose front runs along the tet's edge or vertex. Left uncut, the tet would not carry that
      // node's sign DOF, and its sign function would jump across the tet's faces inside the body.
      bool opposite = false, opposite_behind_front = false;
      for (int k = 0; k < 4; ++k) {
        const long m = mesh.tets(t, k);
        const bool o = (c.side[m] > 0 ? below[t] : above[t]) > 0;
        opposite = opposite || o;
        opposite_behind_front = opposite_behind_front || (o && c.on_cut[m] && !(corners[t] & (1u << k)));
      }
      const bool both = above[t] > 0 && below[t] > 0;
      if (contact[t] == 1 ? both || opposite_behind_front : opposite) c.cut_class[t] = CutClass::Complete;
    }
  });

  // 6. Enrichment. Branch: every node whose star (the tets around it) holds the front in its inside:
  //    the nodes of a tet the front passes through, and of a face, edge or vertex it lies on.
  //    Sign: the other nodes of completely cut tets whose support has volume on the side opposite
  //    the node's own, at least options.tiny_support of the support's volume; below that the sign
  //    function is nearly zero and makes K near-singular, and it is removed (counted, sign_tiny).
  c.enrichment.assign(V, Enrichment::None);
  if (static_cast<long>(memory.support.size()) != V) {  // the mesh alone: once per classifier
    memory.support.assign(V, 0.0);
    for (long t = 0; t < T; ++t) {
      const double v = std::abs(signed_volume(mesh, static_cast<int>(t)));
      for (int k = 0; k < 4; ++k) memory.support[mesh.tets(t, k)] += v;
    }
  }
  const std::vector<double>& support = memory.support;
  std::vector<double> opposite(V, 0.0);
  for (long t = 0; t < T; ++t) {
    for (int k = 0; k < 4; ++k)
      if (corners[t] & (1u << k)) c.enrichment[mesh.tets(t, k)] = Enrichment::Branch;
    if (c.cut_class[t] != CutClass::Complete) continue;
    for (int k = 0; k < 4; ++k) {
      const int m = mesh.tets(t, k);
      opposite[m] += c.side[m] > 0 ? below[t] : above[t];
    }
  }
  for (long m = 0; m < V; ++m) {
    const double fraction = support[m] > 0 ? opposite[m] / support[m] : 0.0;
    if (c.enrichment[m] != Enrichment::None || !(fraction > 1e-12)) continue;
    if (fraction >= options.tiny_support) c.enrichment[m] = Enrichment::Sign;
    else ++c.counts.sign_tiny;
  }
  const long partial = std::count(c.cut_class.begin(), c.cut_class.end(), CutClass::Partial);

  // 6. Optional radius enrichment around the front.
  if (options.tip_radius > 0 && !c.front.empty()) {
    for (long m = 0; m < V; ++m) {
      if (c.enrichment[m] == Enrichment::Branch) continue;
      const Eigen::Vector3d x = mesh.points.row(m).transpose();
      const FrontSegment& s = c.front.segments()[c.front.closest_segment(x)];
      if (point_segment_distance(x, s.p0, s.p1) <= options.tip_radius) {
        ++c.counts.radius_branch;
        c.enrichment[m] = Enrichment::Branch;
      }
    }
  }

  // 7. Counts.
  auto& n = c.counts;
  n.points = V;
  n.tets = T;
  n.edges = static_cast<long>(unique.size());
  n.cut_edges = std::count(edge_cut.begin(), edge_cut.end(), 1);
  n.points_on_cut = std::count(c.on_cut.begin(), c.on_cut.end(), 1);
  n.uncut = std::count(c.cut_class.begin(), c.cut_class.end(), CutClass::Uncut);
  n.partial = partial;
  n.complete = T - n.uncut - partial;
  n.sign = std::count(c.enrichment.begin(), c.enrichment.end(), Enrichment::Sign);
  n.branch = std::count(c.enrichment.begin(), c.enrichment.end(), Enrichment::Branch);
  n.none = V - n.sign - n.branch;
  n.front_segments = static_cast<long>(c.front.segments().size());
  if (options.progress) options.progress(1.0);
  memory.classified = true;
  stats.incremental = growth != nullptr;
  stats.points = tested_points;
  stats.edges = tested_edges;
  stats.tets = tested_tets;
  stats.sides = judged;
  return c;
}

Classification classify(const TetMesh& mesh, const CutSurface& cut, const ClassifyOptions& options) {
  ClassificationMemory memory;
  ClassifyWork stats;
  return classify_with(mesh, cut, options, memory, nullptr, stats);
}

Classification classify_without_cut(const TetMesh& mesh) {
  const long V = mesh.points.rows(), T = mesh.tets.rows();
  Classification c;
  c.side.assign(V, 1);
  c.on_cut.assign(V, 0);
  c.enrichment.assign(V, Enrichment::None);
  c.cut_class.assign(T, CutClass::Uncut);
  c.cut_edges.assign(T, 0);
  c.cut_faces.assign(T, 0);
  std::vector<std::uint64_t> keys;
  keys.reserve(6 * T);
  for (long t = 0; t < T; ++t)
    for (const auto& e : kEdge) keys.push_back(edge_key(mesh.tets(t, e[0]), mesh.tets(t, e[1])));
  std::sort(keys.begin(), keys.end());
  c.counts.edges = std::unique(keys.begin(), keys.end()) - keys.begin();
  c.counts.points = c.counts.none = V;
  c.counts.tets = c.counts.uncut = T;
  return c;
}

std::vector<std::string> count_names() {
  return {"points", "tets", "edges", "cut_edges", "points_on_cut", "uncut", "partial", "complete",
          "none", "sign", "branch", "sign_tiny", "radius_branch", "front_segments"};
}

std::vector<long> count_values(const Classification::Counts& n) {
  return {n.points, n.tets,   n.edges, n.cut_edges, n.points_on_cut, n.uncut,         n.partial,
          n.complete, n.none, n.sign,  n.branch,    n.sign_tiny,  n.radius_branch, n.front_segments};
}

void store_classification(const Classification& c, TetMesh& mesh) {
  const std::size_t V = mesh.points.rows(), T = mesh.tets.rows();
  if (c.side.size() != V || c.cut_class.size() != T)
    throw Error("store_classification: classification does not match the mesh");
  DataArray side = make_array(DataArray::Type::Int32, 1, V), enr = make_array(DataArray::Type::Int32, 1, V);
  for (std::size_t i = 0; i < V; ++i) {
    side.values[i] = c.side[i];
    enr.values[i] = static_cast<int>(c.enrichment[i]);
  }
  DataArray cls = make_array(DataArray::Type::Int32, 1, T), edges = make_array(DataArray::Type::Int32, 1, T);
  for (std::size_t t = 0; t < T; ++t) {
    cls.values[t] = static_cast<int>(c.cut_class[t]);
    edges.values[t] = c.cut_edges[t];
  }
  mesh.point_data["side"] = std::move(side);
  mesh.point_data["enrichment"] = std::move(enr);
  mesh.cell_data["cut_class"] = std::move(cls);
  mesh.cell_data["cut_edges"] = std::move(edges);
  store_front(c.front, mesh);
  const auto values = count_values(c.counts);
  DataArray counts = make_array(DataArray::Type::Int64, 1, values.size());
  for (std::size_t i = 0; i < values.size(); ++i) counts.values[i] = static_cast<double>(values[i]);
  mesh.field_data["classification_counts"] = std::move(counts);
}

}  // namespace xfem
