// SPDX-License-Identifier: MIT
#include "xfem/exact_error.h"

#include <cmath>
#include <string>

#include "xfem/enriched_basis.h"
#include "xfem/error.h"
#include "xfem/oversampling_quadrature.h"
#include "xfem/tet_shape.h"

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

  // 2. Volume integrals by oversampling. A sample's side: that of the tet's nodes when the tet is
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
