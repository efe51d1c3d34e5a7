// SPDX-License-Identifier: MIT
#include "xfem/generate/mesh_ordering.h"

#include <catch2/catch.hpp>
#include <algorithm>
#include <array>
#include <cstdlib>
#include <numeric>
#include <random>
#include <set>

#include "xfem/generate/box_mesh.h"
#include "xfem/core/error.h"

namespace {

// The mesh with its points and tets numbered in a random (seeded) order.
xfem::TetMesh shuffled(const xfem::TetMesh& m, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<int> p(m.points.rows()), t(m.tets.rows());
  std::iota(p.begin(), p.end(), 0);
  std::iota(t.begin(), t.end(), 0);
  std::shuffle(p.begin(), p.end(), rng);  // p[old] = new
  std::shuffle(t.begin(), t.end(), rng);
  xfem::TetMesh s = m;
  for (std::size_t i = 0; i < p.size(); ++i) s.points.row(p[i]) = m.points.row(i);
  for (std::size_t i = 0; i < t.size(); ++i)
    for (int k = 0; k < 4; ++k) s.tets(t[i], k) = p[m.tets(i, k)];
  return s;
}

// Each tet as its 4 corner coordinates in local order: the mesh as a set, numbering aside.
std::set<std::array<double, 12>> tet_set(const xfem::TetMesh& m) {
  std::set<std::array<double, 12>> s;
  for (int t = 0; t < m.tets.rows(); ++t) {
    std::array<double, 12> a;
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) a[3 * k + c] = m.points(m.tets(t, k), c);
    s.insert(a);
  }
  return s;
}

// Median |i - j| over the edges of the tets: how far apart neighbouring points are numbered.
int median_edge_id_gap(const xfem::TetMesh& m) {
  std::vector<int> gaps;
  for (int t = 0; t < m.tets.rows(); ++t)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) gaps.push_back(std::abs(m.tets(t, a) - m.tets(t, b)));
  std::nth_element(gaps.begin(), gaps.begin() + gaps.size() / 2, gaps.end());
  return gaps[gaps.size() / 2];
}

bool is_permutation_of_ids(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i] != static_cast<int>(i)) return false;
  return true;
}

}  // namespace

TEST_CASE("mesh_ordering: the Hilbert index walks every cell once, from face to face", "[mesh_ordering]") {
  for (int bits : {1, 2, 3, 4}) {
    const std::uint32_t n = 1u << bits;
    std::vector<std::array<int, 3>> cell_at(std::size_t(n) * n * n, {-1, -1, -1});
    for (std::uint32_t x = 0; x < n; ++x)
      for (std::uint32_t y = 0; y < n; ++y)
        for (std::uint32_t z = 0; z < n; ++z) {
          const std::uint64_t h = xfem::hilbert_index({x, y, z}, bits);
          REQUIRE(h < cell_at.size());
          REQUIRE(cell_at[h][0] == -1);  // injective, so a bijection onto [0, n^3)
          cell_at[h] = {int(x), int(y), int(z)};
        }
    CHECK(cell_at.front() == std::array<int, 3>{0, 0, 0});
    const auto& last = cell_at.back();  // ends at a corner next to the start (one side away)
    CHECK(last[0] + last[1] + last[2] == int(n) - 1);
    CHECK(std::count(last.begin(), last.end(), 0) == 2);
    for (std::size_t h = 1; h < cell_at.size(); ++h) {
      int d = 0;
      for (int a = 0; a < 3; ++a) d += std::abs(cell_at[h][a] - cell_at[h - 1][a]);
      INFO("bits " << bits << ", index " << h);
      CHECK(d == 1);  // consecutive cells share a face (a Morton curve jumps)
    }
  }
  CHECK(xfem::hilbert_index({0, 0, 0}, 21) == 0);
  const std::uint32_t top = (1u << 21) - 1;
  CHECK(xfem::hilbert_index({top, top, top}, 21) < (std::uint64_t(1) << 63));  // 63 bits
}

TEST_CASE("mesh_ordering: bad Hilbert arguments are refused", "[mesh_ordering]") {
  CHECK_THROWS_WITH(xfem::hilbert_index({0, 0, 0}, 0), Catch::Contains("bits must be in 1..21 (got 0)"));
  CHECK_THROWS_WITH(xfem::hilbert_index({0, 0, 0}, 22), Catch::Contains("bits must be in 1..21 (got 22)"));
  CHECK_THROWS_WITH(xfem::hilbert_index({0, 8, 0}, 3), Catch::Contains("coordinate 8 does not fit in 3 bits"));
}

TEST_CASE("mesh_ordering: renumbering is a permutation keeping the tets, orientation and volume, "
          "and makes neighbouring ids close",
          "[mesh_ordering]") {
  const xfem::TetMesh grid = xfem::box_mesh({6, 8, 20}, {0, 0, 0}, {0.03, 0.06, 0.2});
  const xfem::TetMesh in = shuffled(grid, 7);
  const xfem::MeshOrdering o = xfem::spatial_ordering(in);
  CHECK(o.point_order.size() == std::size_t(in.points.rows()));
  CHECK(o.tet_order.size() == std::size_t(in.tets.rows()));
  CHECK(is_permutation_of_ids(o.point_order));
  CHECK(is_permutation_of_ids(o.tet_order));

  const xfem::TetMesh out = xfem::spatially_ordered(in);
  CHECK(tet_set(out) == tet_set(in));
  double v_in = 0, v_out = 0;
  for (int t = 0; t < in.tets.rows(); ++t) {
    v_in += xfem::signed_volume(in, t);
    v_out += xfem::signed_volume(out, t);
    CHECK(xfem::signed_volume(out, t) > 0);
  }
  CHECK(v_out == Approx(v_in).epsilon(1e-12));
  // Medians measured: 391 shuffled (~ #points / 4, 1,701 points), 9 along the curve, 63 in the
  // grid's own lexicographic numbering (its z neighbours are 7 x 9 apart).
  const int gap_in = median_edge_id_gap(in), gap_out = median_edge_id_gap(out), gap_grid = median_edge_id_gap(grid);
  CAPTURE(gap_in, gap_out, gap_grid);
  CHECK(gap_out < gap_in / 10);
  CHECK(gap_out < gap_grid);
  // Consecutive tets lie near each other: centroids within a few cells (5 mm) on average.
  double step = 0;
  for (int t = 1; t < out.tets.rows(); ++t) {
    Eigen::RowVector3d a = Eigen::RowVector3d::Zero(), b = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 4; ++k) a += out.points.row(out.tets(t - 1, k)) / 4, b += out.points.row(out.tets(t, k)) / 4;
    step += (b - a).norm();
  }
  CHECK(step / (out.tets.rows() - 1) < 0.01);
}

TEST_CASE("mesh_ordering: the order depends on the geometry only, and is kept by a second pass", "[mesh_ordering]") {
  const xfem::TetMesh grid = xfem::box_mesh({4, 5, 6}, {-1, 0, 2}, {1, 3, 5});
  const xfem::TetMesh a = xfem::spatially_ordered(shuffled(grid, 1));
  const xfem::TetMesh b = xfem::spatially_ordered(shuffled(grid, 2));
  CHECK(a.points == b.points);  // no ties at 2^21 cells per side: the input numbering is gone
  CHECK(a.tets == b.tets);
  const xfem::TetMesh again = xfem::spatially_ordered(a);
  CHECK(again.points == a.points);
  CHECK(again.tets == a.tets);
}

TEST_CASE("mesh_ordering: point and cell arrays follow their points and tets", "[mesh_ordering]") {
  xfem::TetMesh in = shuffled(xfem::box_mesh({3, 3, 3}, {0, 0, 0}, {1, 1, 1}), 3);
  xfem::DataArray x = xfem::make_array(xfem::DataArray::Type::Float64, 3, in.points.rows());
  for (int i = 0; i < in.points.rows(); ++i)
    for (int c = 0; c < 3; ++c) x.values[3 * i + c] = in.points(i, c);
  xfem::DataArray first = xfem::make_array(xfem::DataArray::Type::Int32, 1, in.tets.rows());
  for (int t = 0; t < in.tets.rows(); ++t) first.values[t] = in.tets(t, 0);  // old id of its first point
  in.point_data["x"] = x;
  in.cell_data["first"] = first;
  in.field_data["n"] = xfem::make_array(xfem::DataArray::Type::Int32, 1, 1, 42);
  const xfem::MeshOrdering o = xfem::spatial_ordering(in);
  const xfem::TetMesh out = xfem::spatially_ordered(in);
  for (int i = 0; i < out.points.rows(); ++i)
    for (int c = 0; c < 3; ++c) CHECK(out.point_data.at("x")(i, c) == out.points(i, c));
  for (int t = 0; t < out.tets.rows(); ++t) CHECK(o.point_order[out.tets(t, 0)] == out.cell_data.at("first")(t));
  CHECK(out.field_data.at("n").values == std::vector<double>{42});
}

TEST_CASE("mesh_ordering: broken meshes are refused with what is wrong", "[mesh_ordering]") {
  xfem::TetMesh m = xfem::box_mesh({1, 1, 1}, {0, 0, 0}, {1, 1, 1});
  xfem::TetMesh bad_id = m;
  bad_id.tets(2, 1) = 8;
  CHECK_THROWS_WITH(xfem::spatial_ordering(bad_id), Catch::Contains("tet 2 names point 8 of 8"));
  xfem::TetMesh nan = m;
  nan.points(3, 2) = NAN;
  CHECK_THROWS_WITH(xfem::spatial_ordering(nan), Catch::Contains("not finite"));
  xfem::TetMesh short_array = m;
  short_array.cell_data["id"] = xfem::make_array(xfem::DataArray::Type::Int32, 1, 5);
  CHECK_THROWS_WITH(xfem::spatially_ordered(short_array),
                    Catch::Contains("cell array 'id' has 5 values, not 6 tuples of 1"));
}
