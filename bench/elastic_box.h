// SPDX-License-Identifier: MIT
// A plain linear-tet elasticity system on a box mesh with the beam benchmark's boundary
// conditions (DESIGN.md, "The benchmark"), for xfem-solve's tests and benchmarks while no
// xfem-assemble output is at hand. Header-only: included by bench/ programs and unit tests.
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "xfem/generate/box_mesh.h"
#include "xfem/system/linear_system.h"

namespace xfem::bench {

/// K (3NP x 3NP, both triangles) of linear tets, closed form: constant gradients G (4 x 3),
/// k[3a+i][3b+j] = V (lambda G_ai G_bj + mu G_aj G_bi + mu delta_ij G_a . G_b) (DESIGN.md formula 5).
inline SparseMatrix linear_tet_stiffness(const TetMesh& mesh, double E, double nu) {
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(mesh.tets.rows()) * 144);
  for (Eigen::Index e = 0; e < mesh.tets.rows(); ++e) {
    Eigen::Matrix3d J;
    for (int c = 0; c < 3; ++c) J.col(c) = (mesh.points.row(mesh.tets(e, c + 1)) - mesh.points.row(mesh.tets(e, 0))).transpose();
    const double V = J.determinant() / 6;
    const Eigen::Matrix3d Jinv = J.inverse();  // rows: gradients of the barycentric coords 1..3
    Eigen::Matrix<double, 4, 3> G;
    G.bottomRows<3>() = Jinv;
    G.row(0) = -Jinv.colwise().sum();
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            double k = lambda * G(a, i) * G(b, j) + mu * G(a, j) * G(b, i);
            if (i == j) k += mu * G.row(a).dot(G.row(b));
            t.emplace_back(3 * mesh.tets(e, a) + i, 3 * mesh.tets(e, b) + j, V * k);
          }
  }
  const int n = static_cast<int>(3 * mesh.points.rows());
  SparseMatrix K(n, n);
  K.setFromTriplets(t.begin(), t.end());
  return K;
}

/// The uncut beam of the paper on a cells(0) x cells(1) x cells(2) box mesh of
/// [0,0.03]x[0,0.06]x[0,0.2]: E = 300 kPa, nu = 0.35, z <= 0.001 fixed, the edge z >= 0.199,
/// x <= 0.001 pulled by (0, 0, 0.02) m, no load. NP = N, coordinates filled.
inline LinearSystem beam_system(const Eigen::Vector3i& cells) {
  const TetMesh mesh = box_mesh(cells, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.03, 0.06, 0.2));
  LinearSystem s;
  s.np = s.n = mesh.points.rows();
  s.K = linear_tet_stiffness(mesh, 300e3, 0.35);
  s.f = Eigen::VectorXd::Zero(3 * s.n);
  s.coordinates = mesh.points;
  for (long k = 0; k < s.np; ++k) {
    const Eigen::RowVector3d p = mesh.points.row(k);
    const bool fixed = p.z() <= 0.001, pulled = p.z() >= 0.199 && p.x() <= 0.001;
    if (!fixed && !pulled) continue;
    for (int i = 0; i < 3; ++i) {
      s.fixed.push_back(3 * k + i);
      s.fixed_values.push_back(pulled && i == 2 ? 0.02 : 0.0);
    }
  }
  s.pieces = {Piece{static_cast<long>(mesh.tets.rows()), true}};
  return s;
}

}  // namespace xfem::bench
