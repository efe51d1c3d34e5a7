// SPDX-License-Identifier: MIT
#include "xfem/geometry/crack_front.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "xfem/core/error.h"

namespace {

/// The beam cut's front x = 0.015, z = 0.1, as two segments along y, oriented so that
/// a = b x c = +x points away from the cut (which lies at x < 0.015): b = +z, c = -y.
xfem::CrackFront beam_front() {
  return xfem::CrackFront({{{0.015, 0.06, 0.1}, {0.015, 0.03, 0.1}, {0, 0, 1}},
                           {{0.015, 0.03, 0.1}, {0.015, 0.0, 0.1}, {0, 0, 1}}});
}

}  // namespace

TEST_CASE("crack_front: closest segment, ties to the lowest index", "[crack_front]") {
  const xfem::CrackFront f = beam_front();
  CHECK(f.closest_segment({0.02, 0.05, 0.1}) == 0);
  CHECK(f.closest_segment({0.02, 0.01, 0.3}) == 1);
  CHECK(f.closest_segment({0.02, 0.03, 0.1}) == 0);  // equidistant: the shared end point
  CHECK_THROWS_WITH(xfem::CrackFront().closest_segment({0, 0, 0}), Catch::Contains("no segments"));
}

TEST_CASE("crack_front: the frame is a rotation with a pointing into intact material", "[crack_front]") {
  const xfem::CrackFront f = beam_front();
  const xfem::CrackTipFrame fr = f.frame({0.02, 0.05, 0.1});
  CHECK((fr.R.transpose() * fr.R).isApprox(Eigen::Matrix3d::Identity(), 1e-14));
  CHECK_THAT(fr.R.determinant(), Catch::WithinAbs(1.0, 1e-14));
  CHECK(fr.R.col(0).isApprox(Eigen::Vector3d(1, 0, 0)));   // a: away from the cut
  CHECK(fr.R.col(1).isApprox(Eigen::Vector3d(0, 0, 1)));   // b: the cut's normal
  CHECK(fr.R.col(2).isApprox(Eigen::Vector3d(0, -1, 0)));  // c: along the front
  CHECK(fr.origin.isApprox(Eigen::Vector3d(0.015, 0.06, 0.1)));
  // A point on the upper face of the cut is at theta = +pi, on the lower face at -pi.
  auto theta = [&](const Eigen::Vector3d& x) {
    const Eigen::Vector3d l = fr.R.transpose() * (x - fr.origin);
    return std::atan2(l.y(), l.x());
  };
  CHECK_THAT(theta({0.005, 0.05, 0.1 + 1e-12}), Catch::WithinAbs(M_PI, 1e-9));
  CHECK_THAT(theta({0.005, 0.05, 0.1 - 1e-12}), Catch::WithinAbs(-M_PI, 1e-9));
  CHECK_THAT(theta({0.025, 0.05, 0.1}), Catch::WithinAbs(0.0, 1e-15));
}

TEST_CASE("crack_front: store and read round trip", "[crack_front]") {
  xfem::TetMesh m;
  xfem::store_front(beam_front(), m);
  CHECK(m.field_data.at("front_segments").components == 6);
  CHECK(m.field_data.at("front_normals").components == 3);
  const xfem::CrackFront back = xfem::read_front(m, "m.vtu");
  REQUIRE(back.segments().size() == 2);
  CHECK(back.segments()[1].p1.isApprox(Eigen::Vector3d(0.015, 0.0, 0.1)));
  CHECK(back.segments()[1].b.isApprox(Eigen::Vector3d(0, 0, 1)));
  // An empty front stores and reads back as empty.
  xfem::TetMesh e;
  xfem::store_front(xfem::CrackFront(), e);
  CHECK(xfem::read_front(e, "e.vtu").empty());
}

TEST_CASE("crack_front: bad input is named", "[crack_front]") {
  xfem::TetMesh m;
  CHECK_THROWS_WITH(xfem::read_front(m, "m.vtu"),
                    "m.vtu: field array 'front_segments' missing (is this xfem-classify output?)");
  CHECK_THROWS_WITH(xfem::CrackFront({{{0, 0, 0}, {0, 0, 0}, {0, 0, 1}}}), Catch::Contains("segment 0 is degenerate"));
}

TEST_CASE("crack_front: segments join into chains, open and closed, whatever their order", "[crack_front]") {
  // An open chain of three segments given out of order, and a closed square loop.
  const Eigen::Vector3d z(0, 0, 1);
  std::vector<xfem::FrontSegment> s = {{{2, 0, 0}, {3, 0, 0}, z}, {{0, 0, 0}, {1, 0, 0}, z}, {{1, 0, 0}, {2, 0, 0}, z},
                                       {{10, 0, 0}, {11, 0, 0}, z}, {{11, 1, 0}, {10, 1, 0}, z},
                                       {{11, 0, 0}, {11, 1, 0}, z}, {{10, 1, 0}, {10, 0, 0}, z}};
  const auto chains = xfem::front_polylines(xfem::CrackFront(s));
  REQUIRE(chains.size() == 2);
  CHECK(!chains[0].closed);
  REQUIRE(chains[0].points.size() == 4);
  CHECK(chains[0].points[0].isApprox(Eigen::Vector3d(0, 0, 0)));
  CHECK(chains[0].points[3].isApprox(Eigen::Vector3d(3, 0, 0)));
  CHECK_THAT(chains[0].length, Catch::WithinAbs(3.0, 1e-14));
  CHECK(chains[1].closed);
  CHECK(chains[1].points.size() == 4);
  CHECK_THAT(chains[1].length, Catch::WithinAbs(4.0, 1e-14));
  // Positions, frames and closest points along the loop; arc offsets the short way round.
  CHECK(chains[1].position(4.5).isApprox(Eigen::Vector3d(10.5, 0, 0)));
  Eigen::Vector3d c, b;
  chains[1].frame(0.5, c, b);
  CHECK(c.isApprox(Eigen::Vector3d(1, 0, 0)));
  CHECK(b.isApprox(z));
  chains[1].frame(1.0, c, b);  // a corner: the mean of the two segments' directions
  CHECK(c.isApprox(Eigen::Vector3d(1, 1, 0).normalized()));
  double s_at, d;
  chains[1].closest({10.5, -2, 0}, s_at, d);
  CHECK_THAT(s_at, Catch::WithinAbs(0.5, 1e-14));
  CHECK_THAT(d, Catch::WithinAbs(2.0, 1e-14));
  CHECK_THAT(chains[1].arc_offset(3.5, 0.5), Catch::WithinAbs(1.0, 1e-14));
  CHECK_THAT(chains[0].arc_offset(2.5, 0.5), Catch::WithinAbs(-2.0, 1e-14));
  CHECK_THROWS_WITH(xfem::front_polylines(xfem::CrackFront()), Catch::Contains("no segments"));
}
