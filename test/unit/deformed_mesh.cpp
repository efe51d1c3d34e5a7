// SPDX-License-Identifier: MIT
#include "xfem/post/deformed_mesh.h"

#include <catch2/catch.hpp>
#include <map>
#include <memory>

#include "xfem/generate/box_mesh.h"
#include "xfem/geometry/cut_surface.h"
#include "xfem/core/error.h"

namespace {

constexpr double kZc = 0.43;  // the cut plane z = kZc, through the whole unit box, no node on it

xfem::TriangleMesh plane_cut() {
  xfem::TriangleMesh m;
  m.points.resize(4, 3);
  m.points << -1, -1, kZc, 2, -1, kZc, 2, 2, kZc, -1, 2, kZc;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 2, 0, 2, 3;
  return m;
}

// The unit box cut through completely, enriched as xfem-classify and xfem-enrich would (by hand):
// every node of a cut element sign-enriched, numbered in node order after the originals.
xfem::EnrichedMesh cut_box() {
  xfem::EnrichedMesh em;
  em.mesh = xfem::box_mesh({3, 3, 4}, {0, 0, 0}, {1, 1, 1});
  const int np = static_cast<int>(em.mesh.points.rows()), nt = em.tets();
  em.side.resize(np);
  for (int k = 0; k < np; ++k) em.side[k] = em.mesh.points(k, 2) > kZc ? 1 : -1;
  em.cut_class.assign(nt, 0);
  std::map<int, long> sign_dof;
  for (int t = 0; t < nt; ++t) {
    int above = 0;
    for (int c = 0; c < 4; ++c) above += em.side[em.mesh.tets(t, c)] > 0;
    if (above == 0 || above == 4) continue;
    em.cut_class[t] = 2;  // a plane through the whole tet crosses 3 or 4 edges: completely cut
    for (int c = 0; c < 4; ++c) sign_dof[em.mesh.tets(t, c)] = 0;
  }
  em.np = np;
  em.ns = static_cast<long>(sign_dof.size());
  em.nb = 0;
  em.n = em.np + em.ns;
  long next = np;
  for (auto& [node, dof] : sign_dof) dof = next++;
  em.offsets.push_back(0);
  for (int t = 0; t < nt; ++t) {
    for (int c = 0; c < 4; ++c) {
      em.dofs.push_back(em.mesh.tets(t, c));
      em.local.push_back(c);
    }
    if (em.cut_class[t] > 0)
      for (int c = 0; c < 4; ++c) {
        em.dofs.push_back(sign_dof.at(em.mesh.tets(t, c)));
        em.local.push_back(c);
      }
    em.offsets.push_back(static_cast<long>(em.dofs.size()));
  }
  em.cut = std::make_shared<xfem::CutSurface>(plane_cut());
  return em;
}

xfem::SplitMesh split_of(const xfem::EnrichedMesh& em) {
  return xfem::split_mesh(em.mesh, em.side, em.cut_class, em.cut->mesh(), em.front.segments());
}

Eigen::Vector3d row3(const xfem::DataArray& a, Eigen::Index i) { return Eigen::Vector3d(a(i, 0), a(i, 1), a(i, 2)); }

}  // namespace

TEST_CASE("deformed_mesh: the two faces of the cut move apart by the solution's jump", "[deformed_mesh]") {
  const xfem::EnrichedMesh em = cut_box();
  // Originals: a linear field A x. Sign DOFs: the constant g, so that u jumps by exactly g across
  // the cut (the 4 nodes of a cut element are all sign-enriched: sum N_l (psi+ - psi-) g = g).
  Eigen::Matrix3d A;
  A << 1e-3, 2e-3, 0, 0, -1e-3, 0, 5e-4, 0, 3e-3;
  const Eigen::Vector3d g(1e-4, -2e-4, 0.01);
  Eigen::VectorXd u(3 * em.n);
  for (long k = 0; k < em.np; ++k) u.segment<3>(3 * k) = A * em.mesh.points.row(k).transpose();
  for (long k = em.np; k < em.n; ++k) u.segment<3>(3 * k) = g;
  const auto split = split_of(em);
  const auto body = xfem::deformed_body(split, em.cut_class, xfem::xfem_displacement(em, u), 300e3, 0.35);
  const auto& d = body.volume.point_data.at("displacement");

  // Displacements at the original nodes are the solution's nodal values: the shifted Heaviside
  // vanishes at its own node (1e-15: sums of a few products of size 1e-3).
  for (long k = 0; k < em.np; ++k) {
    CAPTURE(k);
    CHECK((row3(d, k) - u.segment<3>(3 * k)).norm() < 1e-15);
  }
  // Every point copied onto the cut: the upper copy minus the lower one is the jump g.
  std::map<std::array<double, 3>, std::map<int, Eigen::Vector3d>> copies;
  for (Eigen::Index k = em.np; k < split.points.rows(); ++k)
    copies[{split.points(k, 0), split.points(k, 1), split.points(k, 2)}][split.point_side[k]] = row3(d, k);
  int pairs = 0;
  for (const auto& [x, by_side] : copies) {
    REQUIRE(by_side.size() == 2);
    const Eigen::Vector3d gap = by_side.at(1) - by_side.at(-1);
    CHECK((gap - g).norm() < 1e-15);
    CHECK(gap[2] > 0);  // the cut opens
    ++pairs;
  }
  CHECK(pairs > 0);
  const auto o = xfem::cut_opening(split, d, [](const Eigen::Vector3d&) { return Eigen::Vector3d(0, 0, 1); });
  CHECK(o.pairs == pairs);
  CHECK_THAT(o.min_normal, Catch::WithinAbs(g[2], 1e-15));
  CHECK_THAT(o.max_normal, Catch::WithinAbs(g[2], 1e-15));
  CHECK_THAT(o.max_jump, Catch::WithinAbs(g.norm(), 1e-15));
  // The wound carries the same displacements: per side, its mean z-displacement differs by g_z.
  const auto& wd = body.wound.point_data.at("displacement");
  const auto& ws = body.wound.cell_data.at("side");
  // Its points lie off the cut plane by 1e-4 x the box's diagonal, along the face's outward normal
  // (the upper face's points below the plane), so it does not z-fight with deformed.vtu's faces.
  const double offset = 1e-4 * std::sqrt(3.0);
  std::map<int, double> sum, count;
  for (Eigen::Index f = 0; f < body.wound.triangles.rows(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int s = static_cast<int>(ws(f));
      Eigen::Vector3d x = body.wound.points.row(body.wound.triangles(f, c)).transpose();
      CHECK_THAT(x[2] - kZc, Catch::WithinAbs(-s * offset, 1e-12));
      x[2] = kZc;
      sum[s] += wd(body.wound.triangles(f, c), 2) - A.row(2).dot(x);
      count[s] += 1;
    }
  CHECK_THAT(sum[1] / count[1] - sum[-1] / count[-1], Catch::WithinAbs(g[2], 1e-15));
  // The undeformed split mesh fills the body: volume 1 to rounding.
  double volume = 0;
  for (int t = 0; t < body.volume.tets.rows(); ++t) volume += xfem::signed_volume(body.volume, t);
  CHECK_THAT(volume, Catch::WithinRel(1.0, 1e-12));
}

TEST_CASE("deformed_mesh: strain, stress and von Mises of a linear field are Hooke's", "[deformed_mesh]") {
  const xfem::EnrichedMesh em = cut_box();
  const auto split = split_of(em);
  // A uniaxial strain eps_xx = 1e-3 and a shear eps_xy = 2e-3 in an analytic field with a jump.
  Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
  G(0, 0) = 1e-3;
  G(0, 1) = 4e-3;
  xfem::DisplacementField f;
  f.value = [&](int, const Eigen::Vector3d& x, int side) {
    return Eigen::Vector3d(G * x + (side >= 0 ? 1.0 : -1.0) * Eigen::Vector3d(0, 0, 1e-3));
  };
  f.gradient = [&](int, const Eigen::Vector3d&, int) { return G; };
  const double E = 1000.0;
  // nu = 1/4: lambda = mu = 0.4 E, so sigma = E (1.2e-3, 0.4e-3, 0.4e-3, 1.6e-3, 0, 0), and
  // von Mises = sqrt(0.5 (0.8^2 + 0 + 0.8^2) + 3 * 1.6^2) 1e-3 E = sqrt(8.32) E 1e-3.
  const auto body = xfem::deformed_body(split, em.cut_class, f, E, 0.25);
  const auto& strain = body.volume.cell_data.at("strain");
  const auto& stress = body.volume.cell_data.at("stress");
  const auto& vm = body.volume.cell_data.at("von_mises");
  const double expected_strain[6] = {1e-3, 0, 0, 2e-3, 0, 0};
  const double expected_stress[6] = {1.2, 0.4, 0.4, 1.6, 0, 0};
  for (int t = 0; t < body.volume.tets.rows(); t += 7) {
    for (int c = 0; c < 6; ++c) {
      CHECK_THAT(strain(t, c), Catch::WithinAbs(expected_strain[c], 1e-18));
      CHECK_THAT(stress(t, c), Catch::WithinAbs(expected_stress[c], 1e-12));
    }
    CHECK_THAT(vm(t), Catch::WithinRel(std::sqrt(8.32), 1e-12));
  }
  // Known values of von Mises: uniaxial stress s gives s, pure shear tau gives sqrt(3) tau.
  CHECK_THAT(xfem::von_mises(Eigen::Vector3d(5, 0, 0).asDiagonal()), Catch::WithinRel(5.0, 1e-15));
  Eigen::Matrix3d shear = Eigen::Matrix3d::Zero();
  shear(1, 2) = shear(2, 1) = 2;
  CHECK_THAT(xfem::von_mises(shear), Catch::WithinRel(2 * std::sqrt(3.0), 1e-15));
  // Cell arrays: the parent's cut class and the piece's side.
  const auto& cls = body.volume.cell_data.at("cut_class");
  const auto& side = body.volume.cell_data.at("piece_side");
  for (int t = 0; t < body.volume.tets.rows(); ++t) {
    CHECK(cls(t) == em.cut_class[split.parent[t]]);
    CHECK(side(t) == split.tet_side[t]);
  }
}

TEST_CASE("deformed_mesh: bad material and non-finite displacements are errors", "[deformed_mesh]") {
  const xfem::EnrichedMesh em = cut_box();
  const auto split = split_of(em);
  xfem::DisplacementField f;
  f.value = [](int, const Eigen::Vector3d& x, int) { return Eigen::Vector3d(x[0] > 0.5 ? NAN : 0.0, 0, 0); };
  f.gradient = [](int, const Eigen::Vector3d&, int) { return Eigen::Matrix3d::Zero().eval(); };
  using Catch::Matchers::Contains;
  CHECK_THROWS_WITH(xfem::deformed_body(split, em.cut_class, f, -1, 0.3), Contains("E must be positive, got -1"));
  CHECK_THROWS_WITH(xfem::deformed_body(split, em.cut_class, f, 1, 0.5), Contains("nu must be in (-1, 0.5)"));
  CHECK_THROWS_WITH(xfem::deformed_body(split, em.cut_class, f, 1, 0.3), Contains("is not finite"));
}
