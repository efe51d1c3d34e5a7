// SPDX-License-Identifier: MIT
#include "xfem/post/exact_error.h"

#include <cmath>
#include <string>

#include "xfem/enrich/enriched_basis.h"
#include "xfem/core/error.h"
#include "xfem/integrate/oversampling_quadrature.h"
#include "xfem/geometry/tet_shape.h"

namespace xfem {

ExactErrorReport exact_error(const EnrichedMesh& em, const Eigen::VectorXd& u, const ExactField& exact, int points) {
  if (u.size() != 3 * em.n)
    throw Error("solution: " + std::to_string(u.size()) + " values, expected 3N = " + std::to_string(3 * em.n));
  ExactErrorReport r;
  const TetMesh& mesh = em.mesh;
  const long np = mesh.points.rows();
  const auto side_of_node = [&](long k) { return em.side.empty() ? 1 : em.side[k]; };

  // 1. Nodes: one tet using each node evaluates u_h there (the field is continuous on each side).
  std::vector<int> tet_of(np, -1);
  for (int t = 0; t < em.tets(); ++t)
    for (int c = 0; c < 4; ++c)
      if (tet_of[mesh.tets(t, c)] < 0) tet_of[mesh.tets(t, c)] = t;
  double sum = 0.0, ref_sum = 0.0;
  for (long k = 0; k < np; ++k) {
    if (tet_of[k] < 0) continue;  // a point no tet uses has no displacement
    const Eigen::Vector3d x = mesh.points.row(k).transpose();
    const int side = side_of_node(k);
    const Eigen::Vector3d ue = exact.displacement(x, side);
    const double e2 = (displacement_at(em, tet_of[k], x, side, u) - ue).squaredNorm();
    sum += e2;
    ref_sum += ue.squaredNorm();
    ++r.nodes.compared;
    if (std::sqrt(e2) > r.nodes.max || r.nodes.max_node < 0) {
      r.nodes.max = std::sqrt(e2);
      r.nodes.max_node = k;
    }
  }
  if (r.nodes.compared > 0) {
    r.nodes.rms = std::sqrt(sum / (3.0 * r.nodes.compared));
    r.nodes.reference_rms = std::sqrt(ref_sum / (3.0 * r.nodes.compared));
  }

  // 2. The gap, at the points where the edges of cut tets cross the cut (found by bisection on
  //    H(x)): both sides of such a tet have volume, and a rigid motion extends to every x. Only
  //    tets whose 4 nodes are all enriched (|C| >= 8) carry both sides' fields; one with a node
  //    left unenriched (rule D3, docs/CLASSIFICATION.md) has no volume on that node's other side.
  if (exact.kind == ExactField::Kind::Rigid && em.cut && !em.cut_class.empty()) {
    r.max_gap_error = 0.0;
    for (int t = 0; t < em.tets(); ++t) {
      if (em.cut_class[t] == 0 || em.size(t) < 8) continue;
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) {
          Eigen::Vector3d p = mesh.points.row(mesh.tets(t, i)).transpose(), q = mesh.points.row(mesh.tets(t, j)).transpose();
          const int hp = em.cut->side(p);
          if (hp == em.cut->side(q)) continue;
          for (int k = 0; k < 60; ++k) {
            const Eigen::Vector3d m = 0.5 * (p + q);
            (em.cut->side(m) == hp ? p : q) = m;
          }
          const Eigen::Vector3d x = 0.5 * (p + q);
          const Eigen::Vector3d gap = displacement_at(em, t, x, +1, u) - displacement_at(em, t, x, -1, u);
          const Eigen::Vector3d gap_exact = exact.displacement(x, +1) - exact.displacement(x, -1);
          r.max_gap_error = std::max(r.max_gap_error, (gap - gap_exact).norm());
        }
    }
  }

  // 3. Volume integrals by oversampling. A sample's side: that of the tet's nodes when the tet is
  //    uncut and they agree (no cut query), else H(x) from the cut surface.
  const Quadrature rule = oversampling_quadrature(points);
  double l2 = 0, l2e = 0, h1 = 0, h1e = 0;
  for (int t = 0; t < em.tets(); ++t) {
    const TetShape shape = tet_shape(mesh, t);
    const double v = std::abs(shape.volume);
    r.volume += v;
    int tet_side = side_of_node(mesh.tets(t, 0));
    for (int c = 1; c < 4; ++c)
      if (side_of_node(mesh.tets(t, c)) != tet_side) tet_side = 0;
    if (!em.cut_class.empty() && em.cut_class[t] != 0) tet_side = 0;
    Eigen::Matrix<double, 4, 3> P;
    for (int c = 0; c < 4; ++c) P.row(c) = mesh.points.row(mesh.tets(t, c));
    for (int q = 0; q < rule.size(); ++q) {
      const Eigen::Vector3d x = P.transpose() * rule.lambda[q];
      int side = tet_side;
      if (side == 0) {
        if (!em.cut) throw Error("tet " + std::to_string(t) + ": a sample near the cut needs the cut surface");
        side = em.cut->side(x);
      }
      const Eigen::Vector3d du = displacement_at(em, t, x, side, u) - exact.displacement(x, side);
      const Eigen::Matrix3d Ge = exact.gradient(x, side);
      const Eigen::Matrix3d dG = displacement_gradient_at(em, t, x, side, u) - Ge;
      const double w = v * rule.weights[q];
      l2 += w * du.squaredNorm();
      l2e += w * exact.displacement(x, side).squaredNorm();
      h1 += w * dG.squaredNorm();
      h1e += w * Ge.squaredNorm();
      r.max_strain = std::max(r.max_strain, (0.5 * (dG + dG.transpose())).norm());
      ++r.samples;
    }
  }
  r.l2 = std::sqrt(l2);
  r.l2_exact = std::sqrt(l2e);
  r.h1 = std::sqrt(h1);
  r.h1_exact = std::sqrt(h1e);
  return r;
}

}  // namespace xfem
