// SPDX-License-Identifier: MIT
#include "xfem/post/wound_pressure.h"

#include "xfem/geometry/tet_shape.h"

namespace xfem {

std::vector<double> wound_contact_pressure(const SplitMesh& split, const EnrichedMesh& em, const SparseMatrix& nodal) {
  const Eigen::MatrixXd P = Eigen::MatrixXd(nodal);  // NP x C
  // Which nodes have a condition (an entry, zeros included): a node merged into its neighbours
  // (a sliver node, contact_operator.h) has none, and its tets' points belong to the others.
  Eigen::MatrixXd has = Eigen::MatrixXd::Zero(P.rows(), P.cols());
  for (int k = 0; k < nodal.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(nodal, k); it; ++it) has(it.row(), k) = 1.0;
  const auto cut_of = [&](const Eigen::Vector3d& x) {
    int best = 0;
    double nearest = 0;
    for (std::size_t k = 0; k < em.cuts.size() && static_cast<Eigen::Index>(k) < P.cols(); ++k) {
      const double d = em.cuts[k].cut->closest(x).distance;
      if (k == 0 || d < nearest) best = static_cast<int>(k), nearest = d;
    }
    return best;
  };
  std::vector<double> out(static_cast<std::size_t>(split.wound.rows()), 0.0);
  for (Eigen::Index f = 0; f < split.wound.rows(); ++f) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int c = 0; c < 3; ++c) centroid += split.points.row(split.wound(f, c)).transpose() / 3.0;
    const int k = cut_of(centroid);
    double sum = 0;
    for (int c = 0; c < 3; ++c) {
      const int v = split.wound(f, c);
      const int t = split.point_tet[static_cast<std::size_t>(v)];
      const Eigen::Vector4d N = tet_shape(em.mesh, t).values(split.points.row(v).transpose()).cwiseMax(0.0);
      double value = 0, share = 0;
      for (int a = 0; a < 4; ++a) {
        value += N[a] * has(em.mesh.tets(t, a), k) * P(em.mesh.tets(t, a), k);
        share += N[a] * has(em.mesh.tets(t, a), k);
      }
      if (share > 0) sum += value / share / 3.0;
    }
    out[static_cast<std::size_t>(f)] = sum;
  }
  return out;
}

}  // namespace xfem
