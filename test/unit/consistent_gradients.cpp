// SPDX-License-Identifier: MIT
#include "xfem/integrate/consistent_gradients.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <memory>

#include "xfem/generate/box_mesh.h"
#include "xfem/integrate/conforming_quadrature.h"
#include "xfem/geometry/cut_pieces.h"
#include "xfem/enrich/enriched_basis.h"
#include "enriched_test_meshes.h"

using V = Eigen::Vector3d;
using xfem_test::front_inside_box;

TEST_CASE("consistent_gradients: the divergence theorem gives the integrals of the branch gradients",
          "[consistent_gradients]") {
  const xfem::EnrichedMesh em = front_inside_box();
  // Reference: the tet's exact pieces (split at the cut and the front), each by a front-singular
  // Gauss rule of order 10 (converged: orders 6 and 14 agree to 1e-10 here), with the piece's side.
  // The face integrals converge with their order (F ~ sqrt(r) where the front meets a face); the
  // default order (assembly's order + 1 = 4) is about as accurate as the volume rule it corrects.
  auto worst_error = [&](int order, double& largest) {
    double worst = 0;
    for (int t = 0; t < em.tets(); t += 3) {
      xfem::TetCorners p;
      for (int c = 0; c < 4; ++c) p[c] = em.mesh.points.row(em.mesh.tets(t, c)).transpose();
      const xfem::CutPieces pieces =
          xfem::split_at_front(p, *em.cut, em.cut->triangles_meeting(p), em.front.segments());
      xfem::PointRule rule;
      for (std::size_t i = 0; i < pieces.tets.size(); ++i)
        xfem::append_tet_rule(pieces.tets[i], em.front, 10, pieces.side[i], rule);
      Eigen::Matrix<double, Eigen::Dynamic, 3> reference = Eigen::Matrix<double, Eigen::Dynamic, 3>::Zero(em.size(t), 3);
      xfem::BasisAt b;
      for (int q = 0; q < rule.size(); ++q) {
        xfem::enriched_basis(em, t, rule.x[q], rule.side[q], b);
        reference += rule.weights[q] * b.dN;
      }
      const auto exact = xfem::branch_gradient_integrals(em, t, order);
      CHECK(exact.topRows(4).isZero(0.0));  // original DOFs: not corrected
      for (int c = 4; c < em.size(t); ++c) {  // the branch rows
        worst = std::max(worst, (exact.row(c) - reference.row(c)).norm());
        largest = std::max(largest, reference.row(c).norm());
      }
    }
    return worst;
  };
  double largest = 0;
  const double e4 = worst_error(4, largest), e8 = worst_error(8, largest);
  CAPTURE(e4, e8, largest);
  CHECK(largest > 1e-3);
  CHECK(e4 <= 1e-2 * largest);
  CHECK(e8 <= 0.25 * e4);
  CHECK(e8 <= 1e-3 * largest);
}

TEST_CASE("consistent_gradients: the face terms of neighbouring tets cancel to round-off",
          "[consistent_gradients]") {
  // For an interior node l, summing over its star: sum_T integral_T grad(N_l F_j) = the cut's term
  // only (N_l vanishes on the star's boundary), which is normal to the cut (z here). Its x and y
  // components vanish when the faces shared by two tets are integrated alike from both.
  const xfem::EnrichedMesh em = front_inside_box();
  Eigen::MatrixXd star = Eigen::MatrixXd::Zero(em.n, 3);
  double largest = 0;
  for (int t = 0; t < em.tets(); ++t) {
    const auto integrals = xfem::branch_gradient_integrals(em, t, 4);
    for (int c = 4; c < em.size(t); ++c) {
      star.row(em.dofs[em.offsets[t] + c]) += integrals.row(c);
      largest = std::max(largest, integrals.row(c).norm());
    }
  }
  int interior = 0;
  double worst = 0, normal = 0;
  for (long k = 0; k < em.np; ++k) {
    const V x = em.mesh.points.row(k).transpose();
    if (x.minCoeff() < 1e-9 || x.maxCoeff() > 1 - 1e-9) continue;
    ++interior;
    for (int j = 0; j < 4; ++j) {
      worst = std::max(worst, star.row(em.np + 4 * k + j).head<2>().norm());
      normal = std::max(normal, std::abs(star(em.np + 4 * k + j, 2)));
    }
  }
  CAPTURE(worst, normal, largest);
  CHECK(interior == 27);
  CHECK(normal > 1e-3 * largest);  // the cut's term is there (F_1 jumps across the cut)
  CHECK(worst <= 1e-13 * largest);
}
