// SPDX-License-Identifier: MIT
#include "xfem/integrate/consistent_gradients.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "xfem/enrich/branch_functions.h"
#include "xfem/integrate/conforming_quadrature.h"
#include "xfem/integrate/cut_face_quadrature.h"
#include "xfem/integrate/polygon_split.h"
#include "xfem/integrate/straight_front_rule.h"
#include "xfem/geometry/cut_pieces.h"
#include "xfem/core/mesh.h"
#include "xfem/geometry/tet_shape.h"

namespace xfem {
namespace {

// The integrals over face (A, B, C) (its points in increasing id order, `normal` its unit normal)
// of N_v F_j for v = A, B, C and the four branch functions, for a tet whose outward normal is
// +normal [0] and -normal [1]. Everything here depends on the face alone, so that the two tets
// sharing it get the same numbers (FaceIntegralCache): the face is split along the cut's trace (by
// every cut triangle crossing a part's inside, `meeting` holding at least those) and along a front
// lying in its plane, then fanned from the singular point of each part.
std::array<Eigen::Matrix<double, 3, 4>, 2> face_integrals(const CutSurface* cut, const CrackFront& front,
                                                          const std::vector<const FrontSegment*>& fronts,
                                                          const std::vector<int>& meeting, const Eigen::Vector3d& A,
                                                          const Eigen::Vector3d& B, const Eigen::Vector3d& C,
                                                          const Eigen::Vector3d& normal, int depth,
                                                          const std::vector<double>& nodes,
                                                          const std::vector<double>& weights) {
  // Split by the face alone (its own tolerances and fronts): both tets decide alike.
  const FaceParts face = split_face(cut, fronts, meeting, A, B, C, normal);
  const double face_tolerance = face.tolerance;
  const std::vector<const FrontSegment*>& face_fronts = face.fronts;
  const std::vector<Polygon>& parts = face.parts;
  // Barycentric coordinates on the face, for N_v.
  Eigen::Matrix<double, 3, 2> J;
  J << B - A, C - A;
  const Eigen::LDLT<Eigen::Matrix2d> JtJ = (J.transpose() * J).ldlt();  // factored once for all points
  std::array<Eigen::Matrix<double, 3, 4>, 2> integral;
  integral[0].setZero();
  integral[1].setZero();
  std::vector<Eigen::Vector3d> x;
  std::vector<double> w;
  std::vector<TipCoordinates> tips;
  for (const Polygon& part : parts) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& v : part) centre += v;
    centre /= static_cast<double>(part.size());
    polygon_gauss_rule(part, polygon_fan_apex(part, normal, face_fronts, face_tolerance), depth, face_fronts, nodes, weights, x, w);
    // The crack-tip coordinates of the part's points together (the same bits as one by one).
    tips.resize(x.size());
    front.coordinates(x.data(), static_cast<int>(x.size()), tips.data());
    // The side whose F the part shows each tet: its own, or for a part lying on the cut, the side
    // the tet is on (the one its outward normal points away from).
    std::array<int, 2> side = {0, 0};
    if (cut) {
      const CutSurface::Closest near = cut->closest(centre);
      if (near.distance <= face_tolerance) {
        const double along = cut->unit_normal(near.triangle).dot(normal);
        side = {-along > 0 ? 1 : -1, along > 0 ? 1 : -1};
      } else {
        // The side matters only behind the front (branch_functions clamps theta to +-pi on a point
        // of the other side there). A part crossing the cut's plane ahead of the front, where no
        // cut splits it, can reach behind the front on one side while its centre lies ahead on the
        // other: judge the side at the centroid of its points behind the front, inside that convex
        // region (a point there may lie on the cut, on the part's edge). (The unstructured box of
        // e2e.front had faces whose F was wrong on a whole region, their integrals off by 12 %,
        // found by straight_front_face_integrals.)
        Eigen::Vector3d behind = Eigen::Vector3d::Zero();
        int count = 0;
        for (std::size_t i = 0; i < x.size(); ++i)
          if (tips[i].xa < 0) behind += x[i], ++count;
        side[0] = side[1] = count > 0 ? cut->side(behind / count) : cut->side(centre, near);
      }
    }
    for (std::size_t i = 0; i < x.size(); ++i) {
      const Eigen::Vector2d bc = JtJ.solve(J.transpose() * (x[i] - A));
      const Eigen::Vector3d N(1.0 - bc[0] - bc[1], bc[0], bc[1]);
      const TipCoordinates& tc = tips[i];
      const BranchValues F0 = branch_functions(tc, side[0]);
      const BranchValues F1 = side[1] == side[0] ? F0 : branch_functions(tc, side[1]);
      for (int j = 0; j < 4; ++j) {
        integral[0].col(j) += (w[i] * F0.F[j]) * N;
        integral[1].col(j) += (w[i] * F1.F[j]) * N;
      }
    }
  }
  return integral;
}

}  // namespace

Eigen::Matrix<double, Eigen::Dynamic, 3> branch_gradient_integrals(const EnrichedMesh& em, int t, int order,
                                                                   FaceIntegralCache* cache, int near_order,
                                                                   int straight_angle_points) {
  const int n = em.size(t);
  const long begin = em.offsets[t];
  Eigen::Matrix<double, Eigen::Dynamic, 3> out = Eigen::Matrix<double, Eigen::Dynamic, 3>::Zero(n, 3);
  // The branch entries of C: (row, local node, function).
  struct Entry {
    int row, local, function;
  };
  std::vector<Entry> entries;
  for (int k = 0; k < n; ++k)
    if (em.dofs[begin + k] >= em.np + em.ns)
      entries.push_back({k, em.local[begin + k], static_cast<int>((em.dofs[begin + k] - em.np - em.ns) % 4)});
  if (entries.empty()) return out;
  // With several cuts: the cut whose branch DOFs the tet holds (enriched_mesh.h).
  const CutSurface* const cut = cut_of_tet(em, t);
  const CrackFront& front = front_of_tet(em, t);

  const GaussRule01& face_rule = gauss_legendre_rule_01(order);
  const std::vector<double>&nodes = face_rule.nodes, &weights = face_rule.weights;
  // Subdivision near the front pays only for accurate rules (as the volume rule's bisection).
  const int depth = std::max(0, order - 3);
  const GaussRule01& near_rule = near_order > order ? gauss_legendre_rule_01(near_order) : face_rule;
  const std::vector<double>&near_nodes = near_rule.nodes, &near_weights = near_rule.weights;
  const int near_depth = std::max(0, near_order - 3);
  std::array<Eigen::Vector3d, 4> corner;
  std::array<long, 4> id;
  for (int c = 0; c < 4; ++c) {
    id[c] = em.mesh.tets(t, c);
    corner[c] = em.mesh.points.row(id[c]).transpose();
  }
  double h = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) h = std::max(h, (corner[i] - corner[j]).norm());
  const double tolerance = 1e-12 * h;
  const std::vector<int> meeting = cut ? cut->triangles_meeting(corner) : std::vector<int>();
  const std::vector<const FrontSegment*> fronts = fronts_near(front, corner, tolerance);

  std::vector<Eigen::Vector3d> x;
  std::vector<double> w;
  // 1. The four faces. Face k is opposite corner k; its corners in global node order make its
  // points and splits the same from both tets that share it.
  for (int k = 0; k < 4; ++k) {
    std::array<int, 3> f;
    for (int c = 0, m = 0; c < 4; ++c)
      if (c != k) f[m++] = c;
    std::sort(f.begin(), f.end(), [&](int a, int b) { return id[a] < id[b]; });
    bool needed = false;  // N_l vanishes on the faces without node l
    for (const Entry& e : entries) needed = needed || e.local != k;
    if (!needed) continue;
    const Eigen::Vector3d &A = corner[f[0]], &B = corner[f[1]], &C = corner[f[2]];
    Eigen::Vector3d normal = (B - A).cross(C - A);
    const double area2 = normal.norm();
    if (area2 == 0.0) continue;
    normal /= area2;
    const bool reversed = normal.dot(A - corner[k]) <= 0;  // outward = -normal
    const Eigen::Vector3d outward = reversed ? Eigen::Vector3d(-normal) : normal;
    const FaceIntegralCache::Key key{{id[f[0]], id[f[1]], id[f[2]]}, &front};
    FaceIntegralCache::Value computed;
    FaceIntegralCache::Value* face = nullptr;
    if (cache) {
      const auto found = cache->faces.find(key);
      if (found != cache->faces.end()) face = &found->second;
    }
    if (!face) {
      // The face alone decides whether the front passes near it (both tets agree).
      bool near = false;
      if (near_order > order && !front.empty()) {
        const double longest = std::max({(B - A).norm(), (C - B).norm(), (A - C).norm()});
        near = front.distance((A + B + C) / 3.0) < longest;
      }
      Eigen::Matrix<double, 3, 4> straight;
      if (straight_angle_points > 0 && straight_front_face_integrals(front, cut, A, B, C, straight_angle_points, straight))
        computed.integral = {straight, straight};  // not in the cut's plane: both tets see the same F
      else
        computed.integral = near ? face_integrals(cut, front, fronts, meeting, A, B, C, normal, near_depth, near_nodes,
                                                  near_weights)
                                 : face_integrals(cut, front, fronts, meeting, A, B, C, normal, depth, nodes, weights);
      face = &computed;
      if (cache) face = &(cache->faces[key] = computed);
    }
    const Eigen::Matrix<double, 3, 4>& integral = face->integral[reversed ? 1 : 0];
    for (const Entry& e : entries) {
      if (e.local == k) continue;
      const long v = std::find(f.begin(), f.end(), e.local) - f.begin();
      out.row(e.row) += integral(v, e.function) * outward.transpose();
    }
    if (cache && ++face->uses == 2) cache->faces.erase(key);  // both tets of the face served
  }
  // 2. The cut inside the tet: the jump of F across it (a cut lying on a face was taken there).
  if (cut) {
    const TetShape shape = tet_shape(em.mesh, t);
    const TriangleMesh& cm = cut->mesh();
    std::vector<TipCoordinates> tips;
    for (const int tri : meeting) {
      const Polygon poly = clip_triangle(corner, cm.points.row(cm.triangles(tri, 0)).transpose(),
                                         cm.points.row(cm.triangles(tri, 1)).transpose(),
                                         cm.points.row(cm.triangles(tri, 2)).transpose());
      if (!(polygon_area(poly) > 1e-10 * h * h)) continue;
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (const auto& v : poly) centre += v;
      centre /= static_cast<double>(poly.size());
      bool on_face = false;
      for (int k = 0; k < 4; ++k) {
        const Eigen::Vector3d& a = corner[(k + 1) % 4];
        const Eigen::Vector3d nf = (corner[(k + 2) % 4] - a).cross(corner[(k + 3) % 4] - a).normalized();
        on_face = on_face || std::abs(nf.dot(centre - a)) <= tolerance;
      }
      if (on_face) continue;
      const Eigen::Vector3d cut_normal = cut->unit_normal(tri);
      polygon_gauss_rule(poly, polygon_fan_apex(poly, cut_normal, fronts, tolerance), depth, fronts, nodes, weights, x, w);
      tips.resize(x.size());
      front.coordinates(x.data(), static_cast<int>(x.size()), tips.data());
      for (std::size_t i = 0; i < x.size(); ++i) {
        const TipCoordinates& tc = tips[i];
        const BranchValues below = branch_functions(tc, -1), above = branch_functions(tc, 1);
        const Eigen::Vector4d N = shape.values(x[i]);
        for (const Entry& e : entries)
          out.row(e.row) += (w[i] * N[e.local] * (below.F[e.function] - above.F[e.function])) * cut_normal.transpose();
      }
    }
  }
  return out;
}

}  // namespace xfem
