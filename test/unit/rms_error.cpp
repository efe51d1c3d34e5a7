// SPDX-License-Identifier: MIT
#include "xfem/post/rms_error.h"

#include <catch2/catch.hpp>

#include "xfem/generate/box_mesh.h"
#include "xfem/geometry/point_location.h"

namespace {
using Field = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

template <class F>
Field sample(const xfem::Points& p, F f) {
  Field u(p.rows(), 3);
  for (Eigen::Index i = 0; i < p.rows(); ++i) u.row(i) = f(Eigen::Vector3d(p.row(i))).transpose();
  return u;
}

Eigen::Vector3d linear(const Eigen::Vector3d& x) {
  return Eigen::Vector3d(0.1 + 2 * x[0] - x[2], 3 * x[1], -0.5 * x[0] + x[1] + 4 * x[2]);
}
Eigen::Vector3d quadratic(const Eigen::Vector3d& x) { return Eigen::Vector3d(x[0] * x[0], x[1] * x[2], x[2] * x[2]); }

xfem::ReferenceSamples reference_of(const xfem::TetMesh& m, const Field& u) {
  return {m.points, u, std::vector<int>(m.points.rows(), 0)};
}
}  // namespace

TEST_CASE("point_location: every tet's centroid is found in exactly that tet", "[point_location]") {
  const auto m = xfem::box_mesh({3, 4, 5}, {0, 0, 0}, {0.03, 0.06, 0.2});
  const xfem::PointLocator locator(m);
  for (int t = 0; t < m.tets.rows(); ++t) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) c += m.points.row(m.tets(t, k)).transpose() / 4;
    const auto found = locator.containing(c);
    REQUIRE(found.size() == 1);
    CHECK(found[0] == t);
  }
  // A point outside: found by nearest within a radius, not without.
  CHECK(locator.containing({-0.001, 0.01, 0.01}).empty());
  double d = -1;
  CHECK(locator.nearest({-0.001, 0.01, 0.01}, 0.01, &d) >= 0);
  CHECK_THAT(d, Catch::WithinAbs(0.001, 1e-12));
  CHECK(locator.nearest({-0.1, 0.01, 0.01}, 0.01) == -1);
}

TEST_CASE("rms_error: a solution against itself has zero error", "[rms_error]") {
  const auto m = xfem::box_mesh({2, 2, 3}, {0, 0, 0}, {1, 1, 1});
  const Field u = sample(m.points, quadratic);
  const auto r = xfem::rms_error(reference_of(m, u), xfem::plain_field(m, u, 1e-9));
  CHECK(r.compared == m.points.rows());
  CHECK(r.rms == 0.0);
  CHECK(r.max == 0.0);
}

TEST_CASE("rms_error: a constant shift gives its length over sqrt(3)", "[rms_error]") {
  const auto m = xfem::box_mesh({2, 2, 2}, {0, 0, 0}, {1, 1, 1});
  const Field u = sample(m.points, linear);
  Field shifted = u;
  shifted.rowwise() += Eigen::RowVector3d(0.3, 0.0, 0.4);
  const auto r = xfem::rms_error(reference_of(m, u), xfem::plain_field(m, shifted, 1e-9));
  CHECK_THAT(r.rms, Catch::WithinRel(0.5 / std::sqrt(3.0), 1e-12));
  CHECK_THAT(r.max, Catch::WithinRel(0.5, 1e-12));
}

TEST_CASE("rms_error: a coarser copy of the reference's mesh family converges at second order",
          "[rms_error]") {
  // Linear interpolation of a smooth field: exact for a linear field, O(h^2) for a quadratic one.
  const auto fine = xfem::box_mesh({16, 16, 16}, {0, 0, 0}, {1, 1, 1});
  const auto lin_ref = reference_of(fine, sample(fine.points, linear));
  const auto quad_ref = reference_of(fine, sample(fine.points, quadratic));
  std::vector<double> errors;
  for (int n : {2, 4, 8}) {
    const auto coarse = xfem::box_mesh({n, n, n}, {0, 0, 0}, {1, 1, 1});
    const Field lin = sample(coarse.points, linear), quad = sample(coarse.points, quadratic);
    CHECK(xfem::rms_error(lin_ref, xfem::plain_field(coarse, lin, 1e-9)).rms < 1e-13);
    errors.push_back(xfem::rms_error(quad_ref, xfem::plain_field(coarse, quad, 1e-9)).rms);
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    CAPTURE(errors);
    CHECK(errors[i - 1] / errors[i] > 3.5);  // h halves: ratio ~4
  }
}

TEST_CASE("rms_error: nodes outside the mesh are snapped or left out and counted", "[rms_error]") {
  const auto m = xfem::box_mesh({2, 2, 2}, {0, 0, 0}, {1, 1, 1});
  const Field u = sample(m.points, linear);
  xfem::ReferenceSamples ref;
  ref.points.resize(3, 3);
  ref.points << 0.5, 0.5, 0.5, 1.0 + 1e-6, 0.5, 0.5, 3.0, 0.5, 0.5;
  ref.displacement = sample(ref.points, linear);
  ref.side = {0, 0, 0};
  const auto r = xfem::rms_error(ref, xfem::plain_field(m, u, 1e-3));
  CHECK(r.compared == 2);
  CHECK(r.snapped == 1);
  CHECK(r.outside == 1);
}
