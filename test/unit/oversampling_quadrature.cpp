// SPDX-License-Identifier: MIT
#include "xfem/integrate/oversampling_quadrature.h"

#include <catch2/catch.hpp>

#include "xfem/core/error.h"
#include "xfem/core/mesh.h"

TEST_CASE("oversampling_quadrature: m is the smallest integer with m^3 above the request", "[oversampling_quadrature]") {
  CHECK(xfem::oversampling_quadrature(1).size() == 8);
  CHECK(xfem::oversampling_quadrature(7).size() == 8);
  CHECK(xfem::oversampling_quadrature(8).size() == 27);
  CHECK(xfem::oversampling_quadrature(30).size() == 64);  // the paper's beam
  CHECK(xfem::oversampling_quadrature(100).size() == 125);  // the paper's liver
  CHECK_THROWS_AS(xfem::oversampling_quadrature(0), xfem::Error);
}

TEST_CASE("oversampling_quadrature: the sub-tets tile the tet with equal volumes", "[oversampling_quadrature]") {
  const int m = GENERATE(1, 2, 3, 5);
  const auto subtets = xfem::uniform_subtets(m);
  REQUIRE(subtets.size() == static_cast<std::size_t>(m * m * m));
  // In a unit reference tet (P0..P3 = e0, e1, e2, origin) each sub-tet has volume 1/(6 m^3),
  // all corners lie in the tet, and the volumes add up to 1/6; equal volumes and a covering sum
  // mean a tiling up to overlaps, which the centroids being distinct rules out for these sizes.
  const Eigen::Matrix<double, 3, 4> P = (Eigen::Matrix<double, 3, 4>() << 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0).finished();
  double total = 0;
  std::vector<Eigen::Vector3d> centroids;
  for (const Eigen::Matrix4d& c : subtets) {
    CHECK(c.minCoeff() >= -1e-15);
    CHECK((c.colwise().sum().array() - 1.0).abs().maxCoeff() < 1e-14);
    const Eigen::Matrix<double, 3, 4> x = P * c;
    const double v = xfem::signed_volume(x.col(0), x.col(1), x.col(2), x.col(3));
    CHECK_THAT(std::abs(v), Catch::WithinRel(1.0 / (6.0 * m * m * m), 1e-12));
    total += std::abs(v);
    centroids.push_back(x.rowwise().mean());
  }
  CHECK_THAT(total, Catch::WithinRel(1.0 / 6.0, 1e-12));
  for (std::size_t i = 0; i < centroids.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) CHECK((centroids[i] - centroids[j]).norm() > 1e-9);
}

TEST_CASE("oversampling_quadrature: linear functions integrate exactly, quadratics converge", "[oversampling_quadrature]") {
  // Over the unit reference tet: integral of x = 1/24, of x^2 = 1/60 (= 2! / 5!).
  double previous = 1.0;
  for (int request : {1, 30, 300, 3000}) {
    const xfem::Quadrature q = xfem::oversampling_quadrature(request);
    double w = 0, lin = 0, quad = 0;
    for (int k = 0; k < q.size(); ++k) {
      w += q.weights[k];
      lin += q.weights[k] * q.lambda[k][0] / 6.0;
      quad += q.weights[k] * q.lambda[k][0] * q.lambda[k][0] / 6.0;
    }
    CHECK_THAT(w, Catch::WithinAbs(1.0, 1e-12));  // sum of up to 3375 rounded weights
    CHECK_THAT(lin, Catch::WithinAbs(1.0 / 24.0, 1e-15));
    const double error = std::abs(quad - 1.0 / 60.0);
    CAPTURE(request, error);
    CHECK(error < previous);  // centroid rule: O(1/m^2) for smooth integrands
    previous = error;
  }
}
