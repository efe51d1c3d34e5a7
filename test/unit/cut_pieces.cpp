// SPDX-License-Identifier: MIT
#include "xfem/geometry/cut_pieces.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <functional>

#include "xfem/core/mesh.h"

namespace {

using xfem::TetCorners;
using V3 = Eigen::Vector3d;

const TetCorners kUnit = {V3(0, 0, 0), V3(1, 0, 0), V3(0, 1, 0), V3(0, 0, 1)};

double volume(const std::vector<TetCorners>& tets) {
  double v = 0;
  for (const auto& t : tets) v += std::abs(xfem::signed_volume(t[0], t[1], t[2], t[3]));
  return v;
}

/// Every corner of every piece on the given side of the plane (within round-off).
bool all_on_side(const std::vector<TetCorners>& tets, const V3& point, const V3& normal, int side) {
  for (const auto& t : tets)
    for (const auto& x : t)
      if (side * normal.dot(x - point) < -1e-14) return false;
  return true;
}

void check_plane(const V3& point, const V3& normal, double expected_above) {
  std::vector<TetCorners> above, below;
  xfem::split_by_plane(kUnit, point, normal.normalized(), 1e-12, above, below);
  CHECK(volume(above) == Approx(expected_above).margin(1e-15));
  CHECK(volume(below) == Approx(1.0 / 6 - expected_above).margin(1e-15));
  CHECK(all_on_side(above, point, normal, 1));
  CHECK(all_on_side(below, point, normal, -1));
}

/// A sheet z = g(x) (piecewise linear in x with kinks at `folds`) over x, y in [-1, 2], normal +z,
/// two triangles per linear strip.
xfem::TriangleMesh sheet(const std::vector<double>& xs, const std::function<double(double)>& g) {
  xfem::TriangleMesh m;
  const int n = static_cast<int>(xs.size());
  m.points.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    m.points.row(2 * i) << xs[i], -1, g(xs[i]);
    m.points.row(2 * i + 1) << xs[i], 2, g(xs[i]);
  }
  m.triangles.resize(2 * (n - 1), 3);
  for (int i = 0; i + 1 < n; ++i) {
    m.triangles.row(2 * i) << 2 * i, 2 * i + 2, 2 * i + 3;
    m.triangles.row(2 * i + 1) << 2 * i, 2 * i + 3, 2 * i + 1;
  }
  return m;
}

/// Volume of the unit tet below z = g(x): the integral over x of the area of {y, z >= 0,
/// y + z <= h, z < g} with h = 1 - x, i.e. h^2/2 where g >= h, else g h - g^2/2 (g >= 0). The
/// integrand is piecewise quadratic between the breakpoints: 3-point Gauss on each piece is exact.
double volume_below(const std::function<double(double)>& g, std::vector<double> breaks) {
  breaks.push_back(0);
  breaks.push_back(1);
  std::sort(breaks.begin(), breaks.end());
  auto f = [&](double x) {
    const double h = 1 - x, z = std::max(0.0, g(x));
    return z >= h ? h * h / 2 : z * h - z * z / 2;
  };
  const double a = std::sqrt(3.0 / 5.0);
  double total = 0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double lo = std::max(0.0, breaks[i]), hi = std::min(1.0, breaks[i + 1]);
    if (hi <= lo) continue;
    const double m = (lo + hi) / 2, r = (hi - lo) / 2;
    total += r * (5.0 / 9 * f(m - a * r) + 8.0 / 9 * f(m) + 5.0 / 9 * f(m + a * r));
  }
  return total;
}

}  // namespace

TEST_CASE("cut pieces: a plane splits the unit tet into pieces of the exact volumes", "[cut_pieces]") {
  SECTION("one corner alone: a tet and a prism") { check_plane(V3(0, 0, 0.25), V3(0, 0, 1), std::pow(0.75, 3) / 6); }
  SECTION("two and two: two prisms") {
    // x + y < c within the unit tet has volume c^2/2 - c^3/3.
    const double c = 0.4;
    check_plane(V3(c, 0, 0), V3(1, 1, 0), 1.0 / 6 - (c * c / 2 - c * c * c / 3));
  }
  SECTION("two corners on the plane: two tets") { check_plane(V3(0, 0, 0), V3(1, -1, 0), 1.0 / 12); }
  SECTION("one corner on the plane: a tet and a pyramid") {
    // x + y < z within the unit tet has volume 1/24.
    check_plane(V3(0, 0, 0), V3(1, 1, -1), 1.0 / 6 - 1.0 / 24);
  }
  SECTION("a plane through a face or a corner only touches: no split") {
    check_plane(V3(0, 0, 0), V3(0, 0, 1), 1.0 / 6);
    check_plane(V3(0, 0, 1), V3(0, 0, 1), 0.0);
    check_plane(V3(1, 0, 0), V3(1, 1, 1), 0.0);
  }
}

TEST_CASE("cut pieces: a folded cut inside one tet gives the exact volume on each side", "[cut_pieces]") {
  struct Case {
    const char* name;
    std::vector<double> xs;
    std::function<double(double)> g;
    std::vector<double> breaks;
  };
  const auto valley = [](double x) { return 0.15 + 0.6 * std::abs(x - 0.3); };
  const auto ridge = [](double x) { return 0.45 - 0.6 * std::abs(x - 0.3); };
  const auto zigzag = [](double x) { return x < 0.2 ? 0.3 - (x - 0.2) : x < 0.5 ? 0.3 + (x - 0.2) : 0.6 - 1.5 * (x - 0.5); };
  for (const Case& c : {Case{"valley", {-1, 0.3, 2}, valley, {0.3}}, Case{"ridge", {-1, 0.3, 2}, ridge, {0.3}},
                        Case{"two folds", {-1, 0.2, 0.5, 2}, zigzag, {0.2, 0.5}}}) {
    SECTION(c.name) {
      const xfem::TriangleMesh m = sheet(c.xs, c.g);
      const xfem::CutSurface cut(m);
      const xfem::CutPieces pieces = xfem::split_by_cut(kUnit, cut);
      // Breakpoints where z = g(x) meets the tet's top y + z = 1 - x at y = 0, and where it leaves
      // the tet's bottom z = 0: the integrand of volume_below has kinks there.
      std::vector<double> breaks = c.breaks;
      for (const auto& level : {std::function<double(double)>([](double x) { return 1 - x; }),
                                std::function<double(double)>([](double) { return 0.0; })}) {
        auto f = [&](double x) { return c.g(x) - level(x); };
        for (double x = 0; x < 1; x += 1e-4)
          if (f(x) * f(x + 1e-4) < 0) {
            double lo = x, hi = x + 1e-4;
            for (int i = 0; i < 100; ++i) {
              const double mid = (lo + hi) / 2;
              (f(lo) * f(mid) <= 0 ? hi : lo) = mid;
            }
            breaks.push_back((lo + hi) / 2);
          }
      }
      const double below = volume_below(c.g, breaks);
      CHECK(pieces.volume_below == Approx(below).epsilon(1e-12));
      CHECK(pieces.volume_above == Approx(1.0 / 6 - below).epsilon(1e-12));
      // Each piece lies on one side: its centroid's side, and every corner on that side or on the cut.
      for (std::size_t i = 0; i < pieces.tets.size(); ++i)
        for (const auto& x : pieces.tets[i]) CHECK(pieces.side[i] * (x.z() - c.g(x.x())) >= -1e-12);
    }
  }
}

TEST_CASE("cut pieces: a cut through a corner or along a face leaves the tet whole", "[cut_pieces]") {
  const xfem::CutSurface face(sheet({-1, 2}, [](double) { return 0.0; }));
  const xfem::CutPieces on_face = xfem::split_by_cut(kUnit, face);
  REQUIRE(on_face.tets.size() == 1);
  CHECK(on_face.side[0] == 1);
  CHECK(on_face.volume_above == Approx(1.0 / 6));
  const xfem::CutSurface corner(sheet({-1, 2}, [](double) { return 1.0; }));
  const xfem::CutPieces at_corner = xfem::split_by_cut(kUnit, corner);
  REQUIRE(at_corner.tets.size() == 1);
  CHECK(at_corner.side[0] == -1);
}

TEST_CASE("cut pieces: a front with a kink inside the tet ends the pieces' faces on the cut exactly", "[cut_pieces]") {
  // The plane z = 0 cut for x <= f(y) = 0.2 + 0.5 |y| (a reflex corner of the cut at (0.2, 0, 0),
  // inside the tet): three triangles, the front two segments through the kink.
  const auto f = [](double y) { return 0.2 + 0.5 * std::abs(y); };
  xfem::TriangleMesh m;
  m.points.resize(5, 3);
  m.points << -5, -5, 0, f(-5), -5, 0, 0.2, 0, 0, f(5), 5, 0, -5, 5, 0;
  m.triangles.resize(3, 3);
  m.triangles << 0, 1, 2, 0, 2, 4, 4, 2, 3;
  const xfem::CutSurface cut(m);
  const std::vector<xfem::FrontSegment> front = {{V3(f(-5), -5, 0), V3(0.2, 0, 0), V3(0, 0, 1)},
                                                 {V3(0.2, 0, 0), V3(f(5), 5, 0), V3(0, 0, 1)}};
  const TetCorners tet = {V3(-1, -1, -1), V3(2, -1, -0.8), V3(-0.7, 2, -1), V3(0.1, 0.2, 1.5)};
  const xfem::CutPieces pieces = xfem::split_at_front(tet, cut, cut.triangles_meeting(tet), front);
  CHECK(volume(pieces.tets) == Approx(std::abs(xfem::signed_volume(tet[0], tet[1], tet[2], tet[3]))).epsilon(1e-12));
  // Each piece lies on one side of z = 0; a face on the plane is behind the front or ahead of it,
  // and the faces behind it, seen from above, make up the cut inside the tet.
  double behind_area = 0, cut_area = 0;
  bool kink_is_corner = false;
  for (std::size_t i = 0; i < pieces.tets.size(); ++i) {
    const TetCorners& q = pieces.tets[i];
    std::vector<V3> on;
    double zlo = 0, zhi = 0;
    for (const V3& x : q) {
      zlo = std::min(zlo, x.z());
      zhi = std::max(zhi, x.z());
      if (std::abs(x.z()) <= 1e-14) on.push_back(x);
      kink_is_corner = kink_is_corner || (x - V3(0.2, 0, 0)).norm() <= 1e-14;
    }
    CHECK((zlo >= -1e-14 || zhi <= 1e-14));
    CHECK(pieces.side[i] == (zhi > 1e-14 ? 1 : -1));
    if (on.size() != 3) continue;
    double behind = 0, ahead = 0;
    for (const V3& x : on) {
      behind = std::max(behind, f(x.y()) - x.x());
      ahead = std::max(ahead, x.x() - f(x.y()));
    }
    CHECK(std::min(behind, ahead) <= 1e-14);
    const V3 centre = (on[0] + on[1] + on[2]) / 3;  // strictly inside the face: behind or ahead
    if (pieces.side[i] > 0 && centre.x() < f(centre.y()))
      behind_area += 0.5 * (on[1] - on[0]).cross(on[2] - on[0]).norm();
  }
  for (int t = 0; t < 3; ++t)
    cut_area += xfem::polygon_area(xfem::clip_triangle(tet, m.points.row(m.triangles(t, 0)).transpose(),
                                                       m.points.row(m.triangles(t, 1)).transpose(),
                                                       m.points.row(m.triangles(t, 2)).transpose()));
  CHECK(cut_area > 0.1);
  CHECK(behind_area == Approx(cut_area).epsilon(1e-12));
  CHECK(kink_is_corner);
}
