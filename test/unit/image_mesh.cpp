// SPDX-License-Identifier: MIT
// Meshes of label maps: each region's volume against its voxels' and the analytic one, the
// interfaces conforming, and the image's geometry (spacing, origin, direction) honoured.
#include "xfem/generate/image_mesh.h"

#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <map>

#include "mesh_checks.h"
#include "xfem/core/error.h"
#include "xfem/generate/image_smoothing.h"
#include "xfem/generate/phantom_image.h"

namespace {

using xfem::LabelImage;

// A ball of label 1 (radius 26 voxels) holding a ball of label 2 (radius 20 voxels, off centre),
// in millimetre voxels. Centred on a voxel corner; at 20 voxels the inner ball's voxels hold
// 33,552 mm^3 against the sphere's 33,510 (+0.13 %; at 10 voxels the lattice count strays by ~1 %,
// too much to test the mesh against the sphere to 1 %).
constexpr int n = 58;
constexpr double outer_radius = 26, inner_radius = 20;
const Eigen::Vector3d ball_centre(28.5, 28.5, 28.5), inner_offset(2, 0, 0);

LabelImage nested_balls() {
  LabelImage im;
  im.dims = {n, n, n};
  for (std::int64_t k = 0; k < n; ++k)
    for (std::int64_t j = 0; j < n; ++j)
      for (std::int64_t i = 0; i < n; ++i) {
        const Eigen::Vector3d p = Eigen::Vector3d(double(i), double(j), double(k)) - ball_centre;
        im.labels.push_back((p - inner_offset).norm() < inner_radius ? 2 : p.norm() < outer_radius ? 1 : 0);
      }
  return im;
}

std::map<int, double> region_volumes(const xfem::TetMesh& m) {
  std::map<int, double> v;
  const auto& region = m.cell_data.at("region");
  for (int t = 0; t < m.tets.rows(); ++t) v[static_cast<int>(region(t))] += xfem::signed_volume(m, t);
  return v;
}

std::map<int, double> voxel_volumes(const LabelImage& im, double scale) {
  std::map<int, double> v;
  for (std::int32_t l : im.labels)
    if (l) v[l] += im.spacing.prod() * scale * scale * scale;
  return v;
}

Eigen::Vector3d region_centroid(const xfem::TetMesh& m, int label) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double volume = 0;
  const auto& region = m.cell_data.at("region");
  for (int t = 0; t < m.tets.rows(); ++t) {
    if (region(t) != label) continue;
    const double v = xfem::signed_volume(m, t);
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) c += m.points.row(m.tets(t, k)).transpose() / 4;
    sum += v * c;
    volume += v;
  }
  return sum / volume;
}

}  // namespace

TEST_CASE("a label map's regions: volumes to 1 %, labels at the centroids, conforming interfaces", "[image_mesh]") {
  const LabelImage im = nested_balls();
  xfem::ImageMeshOptions o;
  o.scale = 0.001;  // millimetre voxels
  o.size = 0.005;
  o.facet_distance = 0.0003;  // 0.3 voxel: measured -0.39 % against the voxels, -0.27 % against the sphere
  const xfem::TetMesh m = xfem::image_mesh(im, o, "balls");
  REQUIRE(m.cell_data.count("region"));
  xfem_test::total_volume(m);  // every tet positive
  const auto mesh_v = region_volumes(m), voxel_v = voxel_volumes(im, o.scale);
  REQUIRE(mesh_v.size() == 2);
  for (int label : {1, 2}) {
    INFO("region " << label << ": mesh " << mesh_v.at(label) << " m^3, voxels " << voxel_v.at(label) << " m^3");
    CHECK(std::abs(mesh_v.at(label) / voxel_v.at(label) - 1) < 0.01);
  }
  const double sphere = 4.0 / 3.0 * M_PI * std::pow(inner_radius * o.scale, 3);
  INFO("inclusion: mesh " << mesh_v.at(2) << " m^3, sphere " << sphere << " m^3");
  CHECK(std::abs(mesh_v.at(2) / sphere - 1) < 0.01);

  // Each tet whose centroid lies in a voxel surrounded by voxels of one label carries that label.
  const auto& region = m.cell_data.at("region");
  long checked = 0;
  for (int t = 0; t < m.tets.rows(); ++t) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) c += m.points.row(m.tets(t, k)).transpose() / 4;
    const Eigen::Vector3d ijk = c / o.scale;
    const std::int64_t i = std::llround(ijk[0]), j = std::llround(ijk[1]), k = std::llround(ijk[2]);
    const std::int32_t label = im.at(i, j, k);
    bool uniform = true;
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b)
        for (int d = -1; d <= 1; ++d) uniform = uniform && im.at(i + a, j + b, k + d) == label;
    if (!uniform) continue;
    ++checked;
    REQUIRE(region(t) == label);
  }
  CHECK(checked > m.tets.rows() / 3);  // measured: 7,287 of 15,504 (the shell is 4 to 8 voxels thick)

  // Conforming: no face has more than two tets; every face of the inner ball (inside the outer
  // one) has two, and the faces between the regions exist on both sides.
  const auto faces = xfem_test::face_counts(m.tets);
  std::map<std::array<int, 3>, std::vector<int>> face_regions;
  for (int t = 0; t < m.tets.rows(); ++t)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f;
      int n = 0;
      for (int k = 0; k < 4; ++k)
        if (k != skip) f[n++] = m.tets(t, k);
      std::sort(f.begin(), f.end());
      face_regions[f].push_back(static_cast<int>(region(t)));
    }
  long interface = 0;
  for (const auto& [f, regions] : face_regions) {
    REQUIRE(regions.size() <= 2);
    if (std::count(regions.begin(), regions.end(), 2) > 0) REQUIRE(regions.size() == 2);
    interface += regions.size() == 2 && regions[0] != regions[1];
  }
  CHECK(interface > 100);
  CHECK(faces.size() == face_regions.size());
}

TEST_CASE("image meshes keep the labels asked for and refuse unknown or negative ones", "[image_mesh]") {
  const LabelImage im = nested_balls();
  xfem::ImageMeshOptions o;
  o.scale = 0.001;
  o.size = 0.004;
  o.labels = {2};
  const xfem::TetMesh m = xfem::image_mesh(im, o, "balls");
  const auto v = region_volumes(m);
  REQUIRE(v.size() == 1);
  CHECK(v.count(2));
  o.labels = {-1};
  CHECK_THROWS_WITH(xfem::image_mesh(im, o, "balls"), "balls: label -1: regions are numbered from 1");
  o.labels = {7};
  CHECK_THROWS_WITH(xfem::image_mesh(im, o, "balls"), "balls: label 7 is not in the image (its labels: 1, 2)");
  CHECK_THROWS_WITH(xfem::kept_voxel_volume(im, o, "balls"), "balls: label 7 is not in the image (its labels: 1, 2)");
}

TEST_CASE("a phantom with anisotropic spacing, an origin and a rotation or reflection lands where it should",
          "[image_mesh]") {
  xfem::PhantomImageSpec spec;
  spec.spacing = Eigen::Vector3d(0.004, 0.003, 0.005);
  spec.origin = Eigen::Vector3d(0.1, -0.2, 0.3);
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  Eigen::Matrix3d reflection = rotation;
  reflection.col(2) *= -1;  // a left-handed frame, as NIfTI's qfac = -1
  for (const Eigen::Matrix3d& direction : {rotation, reflection}) {
    spec.direction = direction;
    const LabelImage written = xfem::phantom_image(spec);
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("xfem_unit_image_mesh_" + std::to_string(::getpid()) + ".nrrd")).string();
    xfem::write_label_image_nrrd(written, path);
    const LabelImage im = xfem::read_label_image(path);  // through the file: its header carries the geometry
    std::filesystem::remove(path);
    xfem::ImageMeshOptions o;
    o.size = 0.008;
    const xfem::TetMesh m = xfem::image_mesh(im, o, "phantom");
    xfem_test::total_volume(m);
    CHECK(m.region_names == std::map<int, std::string>{{1, "body"}, {2, "inclusion"}});  // from the NRRD header
    const Eigen::Vector3d body = xfem::phantom_body_centre(spec);
    const Eigen::Vector3d expected = spec.origin + direction * (body + spec.inclusion_centre);
    const double voxel = spec.spacing.maxCoeff();
    INFO("inclusion centroid " << region_centroid(m, 2).transpose() << ", expected " << expected.transpose());
    CHECK((region_centroid(m, 2) - expected).norm() < voxel);
    // The body's extent along the image's axes: x in [-0.075, 0.075], y in [-0.05, 0.05] around its centre.
    const Eigen::Vector3d centre_world = spec.origin + direction * body;
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
    for (int p = 0; p < m.points.rows(); ++p) {
      const Eigen::Vector3d local = direction.transpose() * (m.points.row(p).transpose() - centre_world);
      lo = lo.cwiseMin(local);
      hi = hi.cwiseMax(local);
    }
    INFO("extent along the image axes: " << lo.transpose() << " .. " << hi.transpose());
    CHECK(std::abs(lo[0] + 0.075) < voxel);
    CHECK(std::abs(hi[0] - 0.075) < voxel);
    CHECK(std::abs(lo[1] + 0.05) < voxel);
    CHECK(std::abs(hi[1] - 0.05) < voxel);
  }
}

TEST_CASE("label weights: 255 inside a label, the blurred indicator's maximum at a boundary", "[image_mesh]") {
  // Two labels split at i = 5 across a 10 x 3 x 3 block.
  std::vector<std::int32_t> labels;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 10; ++i) labels.push_back(i < 5 ? 1 : 2);
  const auto w = xfem::label_weights(labels, {10, 3, 3}, {1.0, 1.0, 1.0});
  CHECK(w[0] == 255);  // 5 voxels from the boundary: erf(4.5 / sqrt(2)) rounds to 1
  CHECK(w[9] == 255);
  // Voxels 4 and 5 face each other across the boundary: each its own label's blurred indicator,
  // 255 (g0 + g1 + g2 + g3) / (g0 + 2 (g1 + g2 + g3)) with g_j = exp(-j^2 / 2) (the kernel of
  // radius 3 sigma, normalised) = 255 x 0.69952 = 178.4.
  CHECK(int(w[4]) == 178);
  CHECK(w[4] == w[5]);
  CHECK_THROWS_AS(xfem::label_weights(labels, {10, 3, 3}, {0.0, 1.0, 1.0}), xfem::Error);
}

// Smoothing moves the boundary of a convex region inwards (a curvature effect, like a Gaussian
// blur of a disc): measured -2.4 % on the inner ball (20 voxels) with a Gaussian of one voxel,
// -0.9 % on the shell around it.
TEST_CASE("smoothed label boundaries keep each region's volume to 3 %", "[image_mesh]") {
  const LabelImage im = nested_balls();
  xfem::ImageMeshOptions o;
  o.scale = 0.001;
  o.size = 0.005;
  o.facet_distance = 0.0003;
  o.smooth = 0.001;  // one voxel
  const xfem::TetMesh m = xfem::image_mesh(im, o, "balls");
  const auto mesh_v = region_volumes(m), voxel_v = voxel_volumes(im, o.scale);
  for (int label : {1, 2}) {
    INFO("region " << label << ": mesh " << mesh_v.at(label) << " m^3, voxels " << voxel_v.at(label) << " m^3");
    CHECK(std::abs(mesh_v.at(label) / voxel_v.at(label) - 1) < 0.03);
  }
  CHECK(mesh_v.at(2) < voxel_v.at(2));  // shrunk, as a blurred convex body is
}
