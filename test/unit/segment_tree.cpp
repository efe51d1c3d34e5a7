// SPDX-License-Identifier: MIT
#include "xfem/geometry/segment_tree.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "xfem/geometry/crack_front.h"
#include "xfem/core/mesh.h"

namespace {

// A wavy open polyline of 300 segments (what a front looks like) followed by 40 scattered ones.
void test_segments(std::vector<Eigen::Vector3d>& p0, std::vector<Eigen::Vector3d>& p1) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  for (int i = 0; i < 300; ++i) {
    const auto at = [](int k) {
      const double s = 0.001 * k;
      return Eigen::Vector3d(s - 0.15, 0.02 * std::sin(40 * s), 0.01 * std::cos(25 * s));
    };
    p0.push_back(at(i));
    p1.push_back(at(i + 1));
  }
  for (int i = 0; i < 40; ++i) {
    p0.emplace_back(u(rng), u(rng), u(rng));
    p1.push_back(p0.back() + 0.1 * Eigen::Vector3d(u(rng), u(rng), u(rng)));
  }
}

}  // namespace

TEST_CASE("segment_tree: the nearest segment and the segments within a distance, as a linear scan finds them",
          "[segment_tree]") {
  std::vector<Eigen::Vector3d> p0, p1;
  test_segments(p0, p1);
  const xfem::SegmentTree tree(p0, p1);
  const int n = static_cast<int>(p0.size());
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  int skipped = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Eigen::Vector3d x(u(rng), 0.2 * u(rng), 0.2 * u(rng));
    // Nearest: the first segment at the least distance, as a scan with a strict '<'.
    int scan = -1, found = -1, last = -1;
    double scan_d = std::numeric_limits<double>::infinity(), best2 = scan_d, bound2 = tree.nearest_bound2(x);
    for (int k = 0; k < n; ++k) {
      const double d = xfem::point_segment_distance(x, p0[k], p1[k]);
      if (d < scan_d) scan_d = d, scan = k;
    }
    int visits = 0;
    tree.visit_near(x, bound2, [&](int k) {
      REQUIRE(k > last);  // increasing index
      last = k;
      ++visits;
      const double d = xfem::point_segment_distance(x, p0[k], p1[k]);
      if (d * d < best2) best2 = d * d, found = k, bound2 = std::min(bound2, best2);
    });
    REQUIRE(found == scan);
    REQUIRE(best2 == scan_d * scan_d);
    skipped += n - visits;
    // Range: every segment within r of x is visited.
    const double r = 0.02;
    double r2 = r * r;
    std::vector<char> seen(n, 0);
    tree.visit_near(x, r2, [&](int k) { seen[k] = 1; });
    for (int k = 0; k < n; ++k)
      if (xfem::point_segment_distance(x, p0[k], p1[k]) <= r) REQUIRE(seen[k]);
    // The same for a segment as the query.
    const Eigen::Vector3d q = x + Eigen::Vector3d(0.03, -0.01, 0.02);
    std::fill(seen.begin(), seen.end(), 0);
    r2 = r * r;
    tree.visit_near(x, q, r2, [&](int k) { seen[k] = 1; });
    for (int k = 0; k < n; ++k)
      if (xfem::segment_segment_distance(x, q, p0[k], p1[k]) <= r) REQUIRE(seen[k]);
  }
  // The point of the tree: most segments are never looked at.
  CHECK(skipped > 2000 * n / 2);
}

TEST_CASE("segment_tree: an empty tree visits nothing; mismatched ends are refused", "[segment_tree]") {
  const xfem::SegmentTree empty;
  double bound2 = std::numeric_limits<double>::infinity();
  int visits = 0;
  empty.visit_near(Eigen::Vector3d::Zero(), bound2, [&](int) { ++visits; });
  CHECK(visits == 0);
  CHECK(std::isinf(empty.nearest_bound2(Eigen::Vector3d::Zero())));
  CHECK_THROWS(xfem::SegmentTree({Eigen::Vector3d::Zero()}, {}));
}

TEST_CASE("segment_tree: the front's distances equal a scan over its segments", "[segment_tree][crack_front]") {
  std::vector<Eigen::Vector3d> p0, p1;
  test_segments(p0, p1);
  std::vector<xfem::FrontSegment> segments;
  for (int k = 0; k < 300; ++k) segments.push_back({p0[k], p1[k], Eigen::Vector3d(0, 0, 1)});
  const xfem::CrackFront front(segments);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (int trial = 0; trial < 500; ++trial) {
    const Eigen::Vector3d x(u(rng), 0.2 * u(rng), 0.2 * u(rng)), q = x + 0.05 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    double point = std::numeric_limits<double>::infinity(), edge = point, best2 = point;
    int closest = 0;
    for (int k = 0; k < 300; ++k) {
      point = std::min(point, xfem::point_segment_distance(x, p0[k], p1[k]));
      edge = std::min(edge, xfem::segment_segment_distance(x, q, p0[k], p1[k]));
      // CrackFront's own squared distance, for ties at a vertex shared by two segments.
      const Eigen::Vector3d d = p1[k] - p0[k];
      const double t = std::clamp((x - p0[k]).dot(d) / d.squaredNorm(), 0.0, 1.0);
      const double d2 = (p0[k] + t * d - x).squaredNorm();
      if (d2 < best2) best2 = d2, closest = k;
    }
    REQUIRE(front.distance(x) == point);
    REQUIRE(front.distance(x, q) == edge);
    REQUIRE(front.closest_segment(x) == closest);
  }
  CHECK(std::isinf(xfem::CrackFront().distance(Eigen::Vector3d::Zero())));
}
