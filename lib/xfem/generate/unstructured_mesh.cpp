// SPDX-License-Identifier: MIT
// GCC 12 flags Boost.Graph's edge descriptors (used by CGAL's feature detection) as maybe
// uninitialized inside std::allocator once inlined here: a false positive in library code. The
// pragma must precede every include, since the warning is attributed to <new_allocator.h>.
#if defined(__GNUC__) && !defined(__clang__)  // clang has no such warning (and would warn about the pragma)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "xfem/generate/unstructured_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <cmath>
#include <map>
#include <vector>

#include "xfem/core/error.h"
#include "xfem/generate/mesh_ordering.h"
#include "xfem/io/vtk_io.h"

namespace xfem {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface = CGAL::Surface_mesh<K::Point_3>;
namespace params = CGAL::parameters;

// Radius bounds from the target edge length H. An equilateral triangle of edge H has
// circumradius 0.58 H, a regular tet 0.61 H, but refinement stops below the bound: 0.72 H was
// measured to give a mean edge length of H on the beam (0.6 H gave 0.83 H, 0.8 H gave 1.09 H).
constexpr double radius_per_edge = 0.72;

// Sliver exudation stops by default after as long as the refinement took: a wall-clock limit
// that makes the result vary from run to run. time_limit = 0 means none: run to completion.
auto exude_without_time_limit() { return params::exude(params::time_limit = 0); }

void check_size(double size) {
  if (!(std::isfinite(size) && size > 0))
    throw Error("mesh size must be positive and finite (got " + short_number(size) + ")");
}

// Tets of the complex (cells in the domain) and the vertices they use, validated (positive
// orientation, no zero volumes), then renumbered along a Hilbert curve: the complex lists them
// in no spatial order, which made every later stage miss the cache (docs/PERFORMANCE.md,
// "Mesh ordering").
template <class C3t3>
TetMesh extract(const C3t3& c3t3, const std::string& name) {
  using Vertex = typename C3t3::Vertex_handle;
  std::map<Vertex, int> ids;
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector4i> tets;
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    Eigen::Vector4i t;
    for (int k = 0; k < 4; ++k) {
      const Vertex v = c->vertex(k);
      auto [it, added] = ids.emplace(v, static_cast<int>(points.size()));
      if (added) {
        const auto& p = v->point();  // a weighted point in Mesh_3's regular triangulation
        points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      }
      t[k] = it->second;
    }
    tets.push_back(t);
  }
  if (tets.empty()) throw Error(name + ": the mesher produced no tetrahedra (is the size too large for the body?)");
  TetMesh mesh;
  mesh.points.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i) mesh.points.row(i) = points[i].transpose();
  mesh.tets.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (std::size_t i = 0; i < tets.size(); ++i) mesh.tets.row(i) = tets[i].transpose();
  std::vector<std::string> warnings;
  validate_tet_mesh(mesh, name, &warnings);
  return spatially_ordered(mesh);
}

// Surface_mesh of a validated triangle mesh; throws when it is not closed or not manifold.
Surface to_surface(const TriangleMesh& in, const std::string& name) {
  std::map<std::pair<int, int>, int> edge_count;
  for (Eigen::Index f = 0; f < in.triangles.rows(); ++f)
    for (int e = 0; e < 3; ++e) {
      int a = in.triangles(f, e), b = in.triangles(f, (e + 1) % 3);
      if (a > b) std::swap(a, b);
      ++edge_count[{a, b}];
    }
  long open = 0;
  std::pair<int, int> first{-1, -1};
  for (const auto& [e, n] : edge_count)
    if (n == 1 && open++ == 0) first = e;
  if (open > 0)
    throw Error(name + ": surface is not closed: " + std::to_string(open) + " boundary edges (the first joins points " +
                std::to_string(first.first) + " and " + std::to_string(first.second) +
                "); a volume mesh needs a closed surface");
  Surface s;
  std::vector<Surface::Vertex_index> v(in.points.rows());
  for (Eigen::Index i = 0; i < in.points.rows(); ++i)
    v[i] = s.add_vertex(K::Point_3(in.points(i, 0), in.points(i, 1), in.points(i, 2)));
  for (Eigen::Index f = 0; f < in.triangles.rows(); ++f)
    if (s.add_face(v[in.triangles(f, 0)], v[in.triangles(f, 1)], v[in.triangles(f, 2)]) == Surface::null_face())
      throw Error(name + ": surface is not manifold at triangle " + std::to_string(f) +
                  " (a point where separate sheets touch); cannot mesh its volume");
  return s;
}

TetMesh mesh_polyhedral(const Surface& surface, double size, const std::string& name) {
  using Domain = CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface>;
  using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
  using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index>;
  using Criteria = CGAL::Mesh_criteria_3<Tr>;
  Domain domain(surface);
  domain.detect_features();  // dihedral angles sharper than 60 degrees (CGAL's default)
  const Criteria criteria(params::edge_size = size, params::facet_angle = 25,
                          params::facet_size = radius_per_edge * size, params::facet_distance = 0.05 * size,
                          params::cell_radius_edge_ratio = 3, params::cell_size = radius_per_edge * size);
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), exude_without_time_limit());
  return extract(c3t3, name);
}

}  // namespace

TetMesh unstructured_box_mesh(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double size) {
  check_size(size);
  if (!((hi.array() > lo.array()).all())) throw Error("unstructured box: empty box (hi must exceed lo in x, y and z)");
  if (!lo.allFinite() || !hi.allFinite() || !std::isfinite((hi - lo).prod()))
    throw Error("unstructured box: corners too large (the volume overflows)");
  // The box as 12 outward triangles; corner c has coordinates lo or hi by the bits of c.
  Surface s;
  Surface::Vertex_index v[8];
  for (int c = 0; c < 8; ++c)
    v[c] = s.add_vertex(K::Point_3(c & 1 ? hi.x() : lo.x(), c & 2 ? hi.y() : lo.y(), c & 4 ? hi.z() : lo.z()));
  static const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    s.add_face(v[q[0]], v[q[1]], v[q[2]]);
    s.add_face(v[q[0]], v[q[2]], v[q[3]]);
  }
  TetMesh mesh = mesh_polyhedral(s, size, "unstructured box");
  // Boundary vertices come from intersections computed in floating point: put them exactly on
  // the faces they lie on (moves of a few ulps, far below any tet's size).
  const double tol = 1e-9 * (hi - lo).maxCoeff();
  for (Eigen::Index i = 0; i < mesh.points.rows(); ++i)
    for (int a = 0; a < 3; ++a) {
      double& x = mesh.points(i, a);
      if (std::abs(x - lo[a]) <= tol) x = lo[a];
      if (std::abs(x - hi[a]) <= tol) x = hi[a];
    }
  return mesh;
}

TetMesh implicit_mesh(const std::function<double(const Eigen::Vector3d&)>& f, double bounding_radius, double size) {
  check_size(size);
  if (!(bounding_radius > 0)) throw Error("implicit body: bounding radius must be positive");
  if (!(f(Eigen::Vector3d::Zero()) < 0))
    throw Error("implicit body: the origin must lie inside the body (f(0) < 0), the mesher starts from there");
  using Domain = CGAL::Labeled_mesh_domain_3<K>;
  using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
  using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
  using Criteria = CGAL::Mesh_criteria_3<Tr>;
  const auto function = [&f](const K::Point_3& p) { return f(Eigen::Vector3d(p.x(), p.y(), p.z())); };
  // Surface points are located by bisection to 1e-6 of the bounding sphere (CGAL: 1e-3).
  const Domain domain = Domain::create_implicit_mesh_domain(
      function, K::Sphere_3(CGAL::ORIGIN, bounding_radius * bounding_radius), params::relative_error_bound = 1e-6);
  const Criteria criteria(params::facet_angle = 25, params::facet_size = radius_per_edge * size,
                          params::facet_distance = 0.05 * size, params::cell_radius_edge_ratio = 3,
                          params::cell_size = radius_per_edge * size);
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), exude_without_time_limit());
  return extract(c3t3, "implicit body");
}

TetMesh surface_mesh(const TriangleMesh& surface, double size, const std::string& name) {
  check_size(size);
  return mesh_polyhedral(to_surface(surface, name), size, name);
}

}  // namespace xfem
