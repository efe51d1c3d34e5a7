// SPDX-License-Identifier: MIT
#include "xfem/geometry/cut_surface.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Intersections_3/Tetrahedron_3_Triangle_3.h>

#include <algorithm>
#include <iterator>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "xfem/core/error.h"

namespace xfem {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Triangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point to_cgal(const Eigen::Vector3d& x) { return Point(x.x(), x.y(), x.z()); }

/// Where on a triangle its closest point to x lies: the face, an edge (i: from vertex i to i+1),
/// or a vertex.
struct Feature {
  enum Kind { Face, Edge, Vertex } kind = Face;
  int index = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

/// Closest point of the triangle (a, b, c) to p and its Voronoi region (Ericson, "Real-Time
/// Collision Detection", 5.1.5). The region, not only the point, decides which pseudo-normal
/// judges the side of p.
Feature closest_feature(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                        const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {Feature::Vertex, 0, a};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {Feature::Vertex, 1, b};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return {Feature::Edge, 0, a + d1 / (d1 - d3) * ab};
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {Feature::Vertex, 2, c};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return {Feature::Edge, 2, a + d2 / (d2 - d6) * ac};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return {Feature::Edge, 1, b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b)};
  const double denom = 1.0 / (va + vb + vc);
  return {Feature::Face, 0, a + ab * (vb * denom) + ac * (vc * denom)};
}

std::pair<int, int> edge_key(int a, int b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); }

}  // namespace

struct CutSurface::Impl {
  TriangleMesh mesh;
  std::vector<Triangle> triangles;
  Tree tree;
  std::vector<Eigen::Vector3d> normals;         // unit normal per triangle
  std::vector<Eigen::Vector3d> vertex_normals;  // angle-weighted pseudo-normal per point
  // Per undirected edge, by edge: the sum of the adjacent unit normals. A sorted vector, not a map:
  // every tool reading a cut of thousands of triangles builds it, and the map's nodes cost more.
  std::vector<std::pair<std::pair<int, int>, Eigen::Vector3d>> edge_normals;
  const Eigen::Vector3d& edge_normal(std::pair<int, int> key) const {
    const auto it = std::lower_bound(edge_normals.begin(), edge_normals.end(), key,
                                     [](const auto& e, const std::pair<int, int>& k) { return e.first < k; });
    if (it == edge_normals.end() || it->first != key) throw std::out_of_range("cut surface: no such edge");
    return it->second;
  }
  std::vector<BoundaryEdge> boundary;

  Eigen::Vector3d point(int i) const { return mesh.points.row(i).transpose(); }
  /// H(x) judged at the closest point of triangle f (f must hold a closest point of the cut).
  int side(const Eigen::Vector3d& x, int f) const;
  /// side() of the points at(0) .. at(count - 1) into out[0 .. count - 1], each closest-point search
  /// started from the previous point's answer (CGAL's hint): for points that lie close together.
  template <class PointAt>
  void hinted_sides(long count, PointAt&& at, int* out) const {
    Tree::Point_and_primitive_id hint;
    for (long i = 0; i < count; ++i) {
      const Eigen::Vector3d x = at(i);
      const Point q = to_cgal(x);
      hint = i == 0 ? tree.closest_point_and_primitive(q) : tree.closest_point_and_primitive(q, hint);
      out[i] = side(x, static_cast<int>(hint.second - triangles.cbegin()));
    }
  }
};

CutSurface::CutSurface(TriangleMesh cut) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.mesh = std::move(cut);
  const int F = static_cast<int>(m.mesh.triangles.rows());
  if (F == 0) throw Error("cut surface: no triangles");
  m.triangles.reserve(F);
  m.normals.resize(F);
  m.vertex_normals.assign(m.mesh.points.rows(), Eigen::Vector3d::Zero());
  struct EdgeUse {
    std::pair<int, int> key;  // the undirected edge
    int f, i;                 // triangle f's edge i (from vertex i to i + 1)
    bool operator<(const EdgeUse& o) const { return std::tie(key, f, i) < std::tie(o.key, o.f, o.i); }
  };
  std::vector<EdgeUse> edges;  // sorted below: by edge, then by triangle as they were added
  edges.reserve(3 * static_cast<std::size_t>(F));
  for (int f = 0; f < F; ++f) {
    const int v[3] = {m.mesh.triangles(f, 0), m.mesh.triangles(f, 1), m.mesh.triangles(f, 2)};
    const Eigen::Vector3d p[3] = {m.point(v[0]), m.point(v[1]), m.point(v[2])};
    m.triangles.emplace_back(to_cgal(p[0]), to_cgal(p[1]), to_cgal(p[2]));
    const Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]);
    if (!(n.norm() > 0)) throw Error("cut surface: triangle " + std::to_string(f) + " has zero area");
    m.normals[f] = n.normalized();
    // Angle-weighted pseudo-normal (Baerentzen & Aanaes 2005): the sign of (x - c) . n at the
    // closest point c is then right wherever c lies on the surface, edges and vertices included.
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d e1 = (p[(i + 1) % 3] - p[i]).normalized(), e2 = (p[(i + 2) % 3] - p[i]).normalized();
      const double angle = std::acos(std::clamp(e1.dot(e2), -1.0, 1.0));
      m.vertex_normals[v[i]] += angle * m.normals[f];
      edges.push_back({edge_key(v[i], v[(i + 1) % 3]), f, i});
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t b = 0; b < edges.size();) {
    std::size_t e = b;
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (; e < edges.size() && edges[e].key == edges[b].key; ++e) n += m.normals[edges[e].f];
    m.edge_normals.emplace_back(edges[b].key, n);
    if (e - b == 1) {
      const int f = edges[b].f, i = edges[b].i;
      m.boundary.push_back({m.mesh.triangles(f, i), m.mesh.triangles(f, (i + 1) % 3), f});
    }
    b = e;
  }
  // Deterministic order independent of the edges' order: by triangle, then by its own edge order.
  std::sort(m.boundary.begin(), m.boundary.end(), [&](const BoundaryEdge& x, const BoundaryEdge& y) {
    if (x.triangle != y.triangle) return x.triangle < y.triangle;
    auto local = [&](const BoundaryEdge& e) {
      for (int i = 0; i < 3; ++i)
        if (m.mesh.triangles(e.triangle, i) == e.p0) return i;
      return 3;
    };
    return local(x) < local(y);
  });
  m.tree.insert(m.triangles.cbegin(), m.triangles.cend());
  m.tree.build();
  m.tree.accelerate_distance_queries();
}

CutSurface::~CutSurface() = default;
CutSurface::CutSurface(CutSurface&&) noexcept = default;
CutSurface& CutSurface::operator=(CutSurface&&) noexcept = default;

const TriangleMesh& CutSurface::mesh() const { return impl_->mesh; }

CutSurface::Closest CutSurface::closest(const Eigen::Vector3d& x) const {
  const Impl& m = *impl_;
  const auto hit = m.tree.closest_point_and_primitive(to_cgal(x));
  Closest out;
  out.triangle = static_cast<int>(hit.second - m.triangles.cbegin());
  out.point = Eigen::Vector3d(hit.first.x(), hit.first.y(), hit.first.z());
  out.distance = (out.point - x).norm();
  return out;
}

int CutSurface::side(const Eigen::Vector3d& x) const { return impl_->side(x, closest(x).triangle); }

int CutSurface::side(const Eigen::Vector3d& x, const Closest& closest) const {
  if (closest.triangle < 0 || closest.triangle >= static_cast<int>(impl_->normals.size()))
    throw Error("cut surface: side judged at triangle " + std::to_string(closest.triangle) + ", out of range");
  return impl_->side(x, closest.triangle);
}

std::vector<int> CutSurface::sides(const Points& points, long begin, long end) const {
  std::vector<int> out(static_cast<std::size_t>(std::max(0L, end - begin)));
  impl_->hinted_sides(static_cast<long>(out.size()), [&](long i) { return points.row(begin + i).transpose().eval(); },
                      out.data());
  return out;
}

void CutSurface::sides(const Eigen::Vector3d* points, int count, int* out) const {
  impl_->hinted_sides(count, [&](long i) { return points[i]; }, out);
}

int CutSurface::Impl::side(const Eigen::Vector3d& x, int f) const {
  const Impl& m = *this;
  const int v[3] = {m.mesh.triangles(f, 0), m.mesh.triangles(f, 1), m.mesh.triangles(f, 2)};
  // Recompute the closest point on that triangle ourselves to learn its feature (face, edge,
  // vertex); CGAL only returns the point.
  const Feature feature = closest_feature(x, m.point(v[0]), m.point(v[1]), m.point(v[2]));
  Eigen::Vector3d n;
  switch (feature.kind) {
    case Feature::Face: n = m.normals[f]; break;
    case Feature::Edge: n = m.edge_normal(edge_key(v[feature.index], v[(feature.index + 1) % 3])); break;
    default: n = m.vertex_normals[v[feature.index]]; break;
  }
  // A point on the cut (or exactly in the plane of the pseudo-normal) counts as above: +1.
  return (x - feature.point).dot(n) >= 0 ? +1 : -1;
}

bool CutSurface::meets_segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  const Point pa = to_cgal(a), pb = to_cgal(b);
  // A degenerate segment is a point: ask the tree whether that point lies on a triangle.
  if (pa == pb) return impl_->tree.do_intersect(pa);
  return impl_->tree.do_intersect(Segment(pa, pb));
}

const std::vector<CutSurface::BoundaryEdge>& CutSurface::boundary_edges() const { return impl_->boundary; }

namespace {
Kernel::Tetrahedron_3 to_cgal(const std::array<Eigen::Vector3d, 4>& p) {
  return {to_cgal(p[0]), to_cgal(p[1]), to_cgal(p[2]), to_cgal(p[3])};
}
}  // namespace

std::vector<int> CutSurface::triangles_meeting(const std::array<Eigen::Vector3d, 4>& p) const {
  const Impl& m = *impl_;
  CGAL::Bbox_3 box;
  for (const auto& x : p) box += to_cgal(x).bbox();
  std::vector<Tree::Primitive_id> hits;
  m.tree.all_intersected_primitives(box, std::back_inserter(hits));
  const Kernel::Tetrahedron_3 tet = to_cgal(p);
  const bool solid = !tet.is_degenerate();
  std::vector<int> out;
  for (const auto& h : hits) {
    if (solid ? CGAL::do_intersect(*h, tet) : true) out.push_back(static_cast<int>(h - m.triangles.cbegin()));
  }
  std::sort(out.begin(), out.end());
  return out;
}

Eigen::Vector3d CutSurface::unit_normal(int t) const {
  if (t < 0 || t >= static_cast<int>(impl_->normals.size()))
    throw Error("cut surface: triangle index " + std::to_string(t) + " out of range");
  return impl_->normals[t];
}

}  // namespace xfem
