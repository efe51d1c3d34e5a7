// SPDX-License-Identifier: MIT
// What xfem-visualize shows of a large deformation: each model's strain and Cauchy stress per
// cell (post/cell_stress.h) and the deformed volume per side (post/deformed_volume.h).
#include "xfem/post/cell_stress.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "xfem/generate/box_mesh.h"
#include "xfem/post/deformed_mesh.h"
#include "xfem/post/deformed_volume.h"

namespace {

const double kE = 3e3, kNu = 0.3;
xfem::MaterialLaw law(xfem::MaterialModel model) { return {model, xfem::lame(kE, kNu)}; }

Eigen::Matrix3d rotation_z(double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

// A box mesh as a SplitMesh of whole cells: piece_side +1 above z = 0.5, -1 below (as if cut
// there), every point evaluated in a tet that holds it.
xfem::SplitMesh whole_cells() {
  const xfem::TetMesh m = xfem::box_mesh({2, 2, 2}, {0, 0, 0}, {1, 1, 1});
  xfem::SplitMesh s;
  s.points = m.points;
  s.tets = m.tets;
  s.point_side.assign(m.points.rows(), 0);
  s.point_tet.assign(m.points.rows(), 0);
  for (Eigen::Index t = 0; t < m.tets.rows(); ++t) {
    double z = 0;
    for (int c = 0; c < 4; ++c) {
      s.point_tet[m.tets(t, c)] = static_cast<int>(t);
      z += m.points(m.tets(t, c), 2) / 4;
    }
    s.parent.push_back(static_cast<int>(t));
    s.tet_side.push_back(z > 0.5 ? 1 : -1);
  }
  return s;
}

// The affine field u = (F - I) x.
xfem::DisplacementField affine(const Eigen::Matrix3d& F) {
  xfem::DisplacementField u;
  u.value = [F](int, const Eigen::Vector3d& x, int) -> Eigen::Vector3d { return (F - Eigen::Matrix3d::Identity()) * x; };
  u.gradient = [F](int, const Eigen::Vector3d&, int) -> Eigen::Matrix3d { return F - Eigen::Matrix3d::Identity(); };
  return u;
}

}  // namespace

TEST_CASE("cell_stress: the linear model is Hooke's small-strain stress, bit for bit", "[cell_stress]") {
  Eigen::Matrix3d G;
  G << 1e-3, 2e-3, 0, -4e-4, 3e-3, 1e-3, 5e-4, 0, -2e-3;
  const xfem::Lame lm = xfem::lame(kE, kNu);
  const Eigen::Matrix3d eps = 0.5 * (G + G.transpose());
  const Eigen::Matrix3d sigma = lm.lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2 * lm.mu * eps;
  const xfem::CellStress c = xfem::cell_stress(law(xfem::MaterialModel::Linear), G);
  CHECK(c.strain == eps);
  CHECK(c.stress == sigma);
  CHECK(c.det_F == Approx((Eigen::Matrix3d::Identity() + G).determinant()).epsilon(1e-15));
}

TEST_CASE("cell_stress: a 90 degree rotation is stress-free for the large-deformation models only",
          "[cell_stress]") {
  const Eigen::Matrix3d G = rotation_z(M_PI / 2) - Eigen::Matrix3d::Identity();
  for (auto model : {xfem::MaterialModel::Corotational, xfem::MaterialModel::NeoHookean}) {
    const xfem::CellStress c = xfem::cell_stress(law(model), G);
    CHECK(c.stress.norm() < 1e-12 * kE);
    CHECK(c.strain.norm() < 1e-15);
    CHECK(c.det_F == Approx(1).epsilon(1e-15));
  }
  // Hooke's stress of the same motion: eps = diag(cos - 1, cos - 1, 0), sigma_xx = 2 (lambda + mu)(cos - 1).
  const xfem::Lame lm = xfem::lame(kE, kNu);
  const xfem::CellStress linear = xfem::cell_stress(law(xfem::MaterialModel::Linear), G);
  CHECK(linear.stress(0, 0) == Approx(2 * (lm.lambda + lm.mu) * (std::cos(M_PI / 2) - 1)).epsilon(1e-14));
}

TEST_CASE("cell_stress: simple shear gives the neo-Hookean Cauchy stress mu gamma", "[cell_stress]") {
  const double gamma = 0.7, mu = xfem::lame(kE, kNu).mu;
  Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
  G(0, 1) = gamma;
  const xfem::CellStress c = xfem::cell_stress(law(xfem::MaterialModel::NeoHookean), G);
  // J = 1: sigma = mu (b - I), b = F F^T: sigma_12 = mu gamma, sigma_11 = mu gamma^2, the rest 0.
  CHECK(c.stress(0, 1) == Approx(mu * gamma).epsilon(1e-13));
  CHECK(c.stress(1, 0) == c.stress(0, 1));
  CHECK(c.stress(0, 0) == Approx(mu * gamma * gamma).epsilon(1e-13));
  CHECK(std::abs(c.stress(1, 1)) + std::abs(c.stress(2, 2)) + std::abs(c.stress(0, 2)) < 1e-12 * mu);
  // Green-Lagrange: E_12 = gamma / 2, E_22 = gamma^2 / 2.
  CHECK(c.strain(0, 1) == Approx(gamma / 2).epsilon(1e-15));
  CHECK(c.strain(1, 1) == Approx(gamma * gamma / 2).epsilon(1e-15));
}

TEST_CASE("cell_stress: an inverted cell has a defined, zero stress for the large-deformation models",
          "[cell_stress]") {
  Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
  G(0, 0) = -2;  // F = diag(-1, 1, 1)
  for (auto model : {xfem::MaterialModel::Corotational, xfem::MaterialModel::NeoHookean}) {
    const xfem::CellStress c = xfem::cell_stress(law(model), G);
    CHECK(c.inverted());
    CHECK(c.det_F == -1);
    CHECK(c.stress == Eigen::Matrix3d::Zero());
  }
  const xfem::CellStress linear = xfem::cell_stress(law(xfem::MaterialModel::Linear), G);
  CHECK(linear.inverted());
  CHECK(linear.stress(0, 0) != 0);  // Hooke's stress stays what it always was
}

TEST_CASE("deformed_volume: the volume per side before and after, and the inverted cells", "[cell_stress]") {
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  F(0, 0) = 1.5;
  F(1, 1) = 0.9;
  F(0, 2) = 0.3;  // det F = 1.35
  const xfem::DeformedBody body =
      xfem::deformed_body(whole_cells(), std::vector<int>(48, 0), affine(F), kE, kNu, {}, 1e-4,
                          xfem::MaterialModel::NeoHookean);
  xfem::DeformedVolume v = xfem::deformed_volume(body.volume, body.det_F);
  CHECK(v.body.cells == 48);
  CHECK(v.body.before == Approx(1).epsilon(1e-14));
  CHECK(v.body.after == Approx(1.35).epsilon(1e-14));
  REQUIRE(v.sides.size() == 2);
  CHECK(v.sides[0].side == 1);
  CHECK(v.sides[0].before == Approx(0.5).epsilon(1e-14));
  CHECK(v.sides[0].after == Approx(0.675).epsilon(1e-14));
  CHECK(v.sides[1].side == -1);
  CHECK(v.sides[1].after == Approx(0.675).epsilon(1e-14));
  CHECK(v.inverted == 0);
  CHECK(xfem::inverted_warning(v, xfem::MaterialModel::NeoHookean).empty());
  CHECK(xfem::describe(v).find("volume 1 m^3 -> 1.35 m^3 (relative change +0.35); above the cut (piece_side +1) "
                               "0.5 m^3 -> 0.675 m^3") == 0);
  for (double j : body.det_F) CHECK(j == Approx(1.35).epsilon(1e-14));

  // A mirror turns every cell inside out: counted by det F and by the deformed volume.
  F = Eigen::Matrix3d::Identity();
  F(2, 2) = -1;
  const xfem::DeformedBody mirrored =
      xfem::deformed_body(whole_cells(), std::vector<int>(48, 0), affine(F), kE, kNu, {}, 1e-4,
                          xfem::MaterialModel::Corotational);
  v = xfem::deformed_volume(mirrored.volume, mirrored.det_F);
  CHECK(v.inverted == 48);
  CHECK(v.undefined_stress == 48);
  CHECK(v.body.after == Approx(-1).epsilon(1e-14));
  CHECK(xfem::inverted_warning(v, xfem::MaterialModel::Corotational).find("48 of 48 cells are inverted (det F <= 0 at the centroid)") == 0);
  for (double s : mirrored.volume.cell_data.at("von_mises").values) CHECK(s == 0);
  // Flipped by the corners only (det F > 0 at the centroid, as a sliver can be): counted, no warning.
  const xfem::DeformedVolume corners = xfem::deformed_volume(mirrored.volume, std::vector<double>(48, 0.5));
  CHECK(corners.inverted == 48);
  CHECK(corners.undefined_stress == 0);
  CHECK(xfem::inverted_warning(corners, xfem::MaterialModel::Linear).empty());
  CHECK(xfem::describe(corners).find("48 inverted cells (0 with det F <= 0 at the centroid, 48 slivers") != std::string::npos);
  // Without a cut (every piece_side 0) the report has the body only.
  xfem::TetMesh whole = mirrored.volume;
  for (double& s : whole.cell_data.at("piece_side").values) s = 0;
  CHECK(xfem::deformed_volume(whole, mirrored.det_F).sides.empty());
}
