// SPDX-License-Identifier: MIT
#include "xfem/geometry/crack_front.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

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

TEST_CASE("crack_front: coordinates and distances from the segments near a tet equal the whole front's, bit for bit",
          "[crack_front]") {
  // A wavy open chain of 300 short segments and a closed loop of 60 beside it (two chains).
  std::vector<xfem::FrontSegment> segments;
  const auto wave = [](int k) {
    const double s = 0.001 * k;
    return Eigen::Vector3d(s - 0.15, 0.02 * std::sin(40 * s), 0.01 * std::cos(25 * s));
  };
  for (int k = 0; k < 300; ++k) {
    const Eigen::Vector3d n = Eigen::Vector3d(0, -std::sin(0.02 * k), std::cos(0.02 * k));
    segments.push_back({wave(k), wave(k + 1), n});
  }
  const double pi = std::acos(-1.0);
  const auto loop = [&](int k) {
    const double a = 2 * pi * k / 60;
    return Eigen::Vector3d(0.05 * std::cos(a), 0.08, 0.05 * std::sin(a));
  };
  for (int k = 0; k < 60; ++k) segments.push_back({loop(k), loop(k + 1), Eigen::Vector3d(0, 1, 0)});
  const xfem::CrackFront front(segments);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  std::size_t listed = 0, tets = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // Tets of 2 to 40 mm near both chains, some across them.
    const double size = trial % 2 ? 0.002 : 0.04;
    const Eigen::Vector3d at = trial % 4 < 2 ? Eigen::Vector3d(0.15 * u(rng), 0.04 + 0.06 * u(rng), 0.03 * u(rng))
                                             : Eigen::Vector3d(wave(static_cast<int>(150 + 140 * u(rng))) + 0.003 * Eigen::Vector3d(u(rng), u(rng), u(rng)));
    Eigen::Vector3d corners[4];
    for (auto& c : corners) c = at + size * Eigen::Vector3d(u(rng), u(rng), u(rng));
    const xfem::CrackFront::Near near = front.near(corners, 4);
    if (size < 0.01 && front.distance(at) < 0.004) listed += near.chain_segments.size(), ++tets;
    std::vector<Eigen::Vector3d> points;
    for (int p = 0; p < 30; ++p) {
      double l[4], sum = 0;
      for (double& v : l) sum += (v = -std::log(unit(rng) + 1e-300));
      Eigen::Vector3d x = Eigen::Vector3d::Zero();
      for (int c = 0; c < 4; ++c) x += l[c] / sum * corners[c];
      if (p == 0) x = corners[trial % 4];  // a corner itself
      points.push_back(x);
      const xfem::TipCoordinates a = front.coordinates(x), b = front.coordinates(x, near);
      REQUIRE(a.xa == b.xa);
      REQUIRE(a.xb == b.xb);
      REQUIRE(a.grad == b.grad);
      // The distances the rules ask for, from the list and from the tree.
      REQUIRE(front.distance(x, near) == front.distance(x));
      REQUIRE(front.distance(x, corners[p % 4], near) == front.distance(x, corners[p % 4]));
    }
    // Many points at once (runs of consecutive points, each with its own list), the points of this
    // tet and one far away among them.
    points.insert(points.begin() + 12, at + Eigen::Vector3d(0.3, 0, 0));
    // More than two runs (of 64): the tet's points again, shifted by up to a tenth of its size.
    for (std::size_t p = 0; points.size() < 150; ++p)
      points.push_back(points[p % 31] + 0.1 * size * Eigen::Vector3d(u(rng), u(rng), u(rng)));
    std::vector<xfem::TipCoordinates> many(points.size());
    front.coordinates(points.data(), static_cast<int>(points.size()), many.data());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const xfem::TipCoordinates one = front.coordinates(points[i]);
      REQUIRE(many[i].xa == one.xa);
      REQUIRE(many[i].xb == one.xb);
      REQUIRE(many[i].grad == one.grad);
    }
    // Far outside the region the list is not used: the whole front's answer still.
    const Eigen::Vector3d away = at + Eigen::Vector3d(0.3, 0, 0);
    REQUIRE(front.coordinates(away, near).xa == front.coordinates(away).xa);
  }
  // The point of the lists: a few segments per small tet near the front (2 mm, segments of 1 mm),
  // not the front's 360.
  REQUIRE(tets > 5);
  CHECK(static_cast<double>(listed) / tets < 30);
  CHECK(xfem::CrackFront().near(nullptr, 0).chain_segments.empty());
}

TEST_CASE("crack_front: the coordinates' gradients match central differences on a curved front", "[crack_front]") {
  // A wavy open chain whose frame turns along each segment (tangent and normal interpolated
  // between the vertices): the gradients hold the frame's derivative along the front, in closed
  // form; a missing or wrong term of it shows at the 1e-3 level here, the differences' own error
  // is ~1e-10 (measured: 6e-11).
  std::vector<xfem::FrontSegment> segments;
  const auto wave = [](int k) {
    const double s = 0.004 * k;
    return Eigen::Vector3d(s - 0.1, 0.02 * std::sin(40 * s), 0.01 * std::cos(25 * s));
  };
  for (int k = 0; k < 50; ++k)
    segments.push_back({wave(k), wave(k + 1), Eigen::Vector3d(0, -std::sin(0.3 * k), std::cos(0.3 * k))});
  const xfem::CrackFront front(segments);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  const double h = 1e-7;
  int tested = 0, skipped = 0;
  double worst = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Vector3d x = wave(static_cast<int>(5 + 40 * (u(rng) + 1) / 2)) + 0.004 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    const xfem::TipCoordinates t = front.coordinates(x);
    const double r = std::hypot(t.xa, t.xb);
    if (r < 1e-4) continue;  // the differences lose digits at the front
    Eigen::Matrix<double, 2, 3> fd;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(k);
      const xfem::TipCoordinates p = front.coordinates(x + e), m = front.coordinates(x - e);
      fd(0, k) = (p.xa - m.xa) / (2 * h);
      fd(1, k) = (p.xb - m.xb) / (2 * h);
    }
    const double error = (fd - t.grad).cwiseAbs().maxCoeff();
    // A foot moving across a vertex changes segment (the coordinates are only C0 there): a few
    // points, not most as a wrong derivative would make it.
    if (error > 1e-3) {
      ++skipped;
      continue;
    }
    worst = std::max(worst, error);
    ++tested;
  }
  REQUIRE(tested > 200);
  CHECK(skipped < 10);
  CHECK(worst < 2e-7);
}
