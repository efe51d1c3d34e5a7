// SPDX-License-Identifier: MIT
#include "xfem/io/snapshot.h"

#include <catch2/catch.hpp>

#include "xfem/core/error.h"

namespace {

using Catch::Matchers::WithinAbs;

// A wound as deformed_body writes it: triangles of the upper sheet (side +1, normal pointing down
// to the lower side) and of the lower sheet (side -1, normal up); front points shared by both.
xfem::TriangleMesh wound(const Eigen::MatrixXd& points, const std::vector<std::array<int, 3>>& upper,
                         const std::vector<std::array<int, 3>>& lower) {
  xfem::TriangleMesh w;
  w.points = points;
  w.triangles.resize(static_cast<Eigen::Index>(upper.size() + lower.size()), 3);
  xfem::DataArray side = xfem::make_array(xfem::DataArray::Type::Int32, 1, upper.size() + lower.size());
  Eigen::Index f = 0;
  for (const auto& t : upper) {
    w.triangles.row(f) << t[0], t[1], t[2];
    side.values[f++] = 1;
  }
  for (const auto& t : lower) {
    w.triangles.row(f) << t[0], t[1], t[2];
    side.values[f++] = -1;
  }
  w.cell_data["side"] = side;
  return w;
}

}  // namespace

TEST_CASE("snapshot: the camera looks into the opening of a cut that reaches the surface", "[snapshot]") {
  // The beam's cut: z = 0.1, x in [0, 0.015] (mouth at x = 0), front x = 0.015 (points 1, 2 shared).
  Eigen::MatrixXd p(6, 3);
  p << 0, 0, 0.1, 0.015, 0, 0.1, 0.015, 0.06, 0.1, 0, 0.06, 0.1,  // 0..3: upper sheet (1, 2 front)
      0, 0, 0.1, 0, 0.06, 0.1;                                    // 4, 5: lower copies of 0, 3
  const xfem::CutView v = cut_view(wound(p, {{0, 2, 1}, {0, 3, 2}}, {{4, 1, 2}, {4, 2, 5}}));
  CHECK(v.has_cut);
  CHECK_FALSE(v.interior);
  CHECK_THAT((v.normal - Eigen::Vector3d(0, 0, 1)).norm(), WithinAbs(0, 1e-12));
  CHECK_THAT((v.opening - Eigen::Vector3d(-1, 0, 0)).norm(), WithinAbs(0, 1e-12));
  CHECK_THAT((v.centre - Eigen::Vector3d(0.0075, 0.03, 0.1)).norm(), WithinAbs(0, 1e-12));
  // normalize(opening + 0.8 normal + 0.35 normal x opening), normal x opening = -y.
  CHECK_THAT((v.eye - Eigen::Vector3d(-1, -0.35, 0.8).normalized()).norm(), WithinAbs(0, 1e-12));
}

TEST_CASE("snapshot: a cut whose border is all front is interior and gets a section", "[snapshot]") {
  // A square cut at z = 0 whose 4 corners are front points (shared), its centre doubled.
  Eigen::MatrixXd p(6, 3);
  p << -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0, 0, 0, 0, 0, 0, 0;  // 4: upper centre, 5: lower centre
  const xfem::CutView v = cut_view(wound(p, {{4, 1, 0}, {4, 2, 1}, {4, 3, 2}, {4, 0, 3}},
                                         {{5, 0, 1}, {5, 1, 2}, {5, 2, 3}, {5, 3, 0}}));
  CHECK(v.has_cut);
  CHECK(v.interior);
  CHECK_THAT((v.normal - Eigen::Vector3d(0, 0, 1)).norm(), WithinAbs(0, 1e-12));
  CHECK_THAT(v.opening.dot(v.normal), WithinAbs(0, 1e-12));        // the section plane contains the normal
  CHECK_THAT((v.eye - (v.normal + v.opening).normalized()).norm(), WithinAbs(0, 1e-12));  // 45 degrees
}

TEST_CASE("snapshot: no wound, the isometric view; a wound without its side array is an error", "[snapshot]") {
  const xfem::CutView v = cut_view(xfem::TriangleMesh{});
  CHECK_FALSE(v.has_cut);
  CHECK_THAT((v.eye - Eigen::Vector3d(-1, -1, 1).normalized()).norm(), WithinAbs(0, 1e-15));
  xfem::TriangleMesh w = wound(Eigen::MatrixXd::Identity(3, 3), {{0, 1, 2}}, {});
  w.cell_data.clear();
  CHECK_THROWS_AS(cut_view(w), xfem::Error);
}
