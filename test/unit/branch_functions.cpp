// SPDX-License-Identifier: MIT
#include "xfem/enrich/branch_functions.h"

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <memory>

#include "xfem/generate/box_mesh.h"
#include "xfem/enrich/classification.h"
#include "xfem/geometry/cut_surface.h"

namespace {
// A front along the line x = 0.5, z = 0.5 (direction -y), cut in the plane z = 0.5 for x < 0.5
// with normal +z: a = b x c = +x points away from the cut, into the intact material.
xfem::CrackTipFrame test_frame() {
  const xfem::CrackFront front({xfem::FrontSegment{{0.5, 1.0, 0.5}, {0.5, -1.0, 0.5}, {0, 0, 1}}});
  return front.frame({0.2, 0.3, 0.6});
}
}  // namespace

TEST_CASE("branch_functions: F1 jumps by 2 sqrt(r) across the cut and is continuous ahead of the front",
          "[branch_functions]") {
  const xfem::CrackTipFrame f = test_frame();
  const double eps = 1e-9;
  // Behind the front (x < 0.5) across the cut plane z = 0.5, at r = 0.25.
  const auto above = xfem::branch_functions(f, {0.25, 0.3, 0.5 + eps});
  const auto below = xfem::branch_functions(f, {0.25, 0.3, 0.5 - eps});
  CHECK_THAT(above.F[0], Catch::WithinAbs(0.5, 1e-6));  // sqrt(0.25) sin(pi/2)
  CHECK_THAT(below.F[0], Catch::WithinAbs(-0.5, 1e-6));
  // F2..F4 are continuous across the cut (cos(+-pi/2) = 0, sin(+-pi) = 0).
  for (int j = 1; j < 4; ++j) CHECK_THAT(above.F[j] - below.F[j], Catch::WithinAbs(0.0, 1e-6));
  // Ahead of the front (x > 0.5) F is continuous through z = 0.5.
  const auto up = xfem::branch_functions(f, {0.75, 0.3, 0.5 + eps});
  const auto down = xfem::branch_functions(f, {0.75, 0.3, 0.5 - eps});
  for (int j = 0; j < 4; ++j) CHECK_THAT(up.F[j] - down.F[j], Catch::WithinAbs(0.0, 1e-6));
  CHECK_THAT(up.F[1], Catch::WithinAbs(0.5, 1e-6));  // theta = 0: sqrt(r) cos 0
}

TEST_CASE("branch_functions: a point on the cut takes the face it is asked for", "[branch_functions]") {
  const xfem::CrackTipFrame f = test_frame();
  const Eigen::Vector3d on_cut(0.25, 0.3, 0.5);
  CHECK_THAT(xfem::branch_functions(f, on_cut, +1).F[0], Catch::WithinAbs(0.5, 1e-14));
  CHECK_THAT(xfem::branch_functions(f, on_cut, -1).F[0], Catch::WithinAbs(-0.5, 1e-14));
  // Without a side atan2 decides: theta = +pi.
  CHECK_THAT(xfem::branch_functions(f, on_cut, 0).F[0], Catch::WithinAbs(0.5, 1e-14));
  // On the front itself everything is 0 (the gradient's singularity is not evaluated).
  const auto tip = xfem::branch_functions(f, {0.5, 0.7, 0.5});
  CHECK(tip.F.norm() == 0.0);
  CHECK(tip.dF.norm() == 0.0);
}

TEST_CASE("branch_functions: the values of the definition with atan2, sin and cos in every direction",
          "[branch_functions]") {
  // branch_functions takes sin and cos of theta and theta/2 from (xa, xb, r) without trigonometric
  // functions: they must be the definition's, F = sqrt r (sin t/2, cos t/2, sin t/2 sin t,
  // cos t/2 sin t) with t = atan2(xb, xa), to round-off, all round the front and at every scale.
  auto definition = [](double xa, double xb) {
    const double r = std::hypot(xa, xb), t = std::atan2(xb, xa), sr = std::sqrt(r);
    return Eigen::Vector4d(sr * std::sin(t / 2), sr * std::cos(t / 2), sr * std::sin(t / 2) * std::sin(t),
                           sr * std::cos(t / 2) * std::sin(t));
  };
  double worst = 0;
  for (const double r : {1e-9, 1e-3, 0.37, 250.0})
    for (int k = 0; k <= 720; ++k) {
      const double t = -M_PI + 2 * M_PI * k / 720.0;
      xfem::TipCoordinates tc;
      tc.xa = r * std::cos(t);
      tc.xb = k == 0 ? -0.0 : k == 720 ? 0.0 : r * std::sin(t);  // -pi and pi: atan2 goes by xb's sign
      tc.grad.setZero();
      const Eigen::Vector4d F = xfem::branch_functions(tc, 0).F;
      const Eigen::Vector4d expected = definition(tc.xa, tc.xb);
      worst = std::max(worst, (F - expected).cwiseAbs().maxCoeff() / std::sqrt(r));
    }
  CAPTURE(worst);
  CHECK(worst < 1e-15);  // measured 3.7e-16: both sides round
  // On the cut's plane behind the front: xb = -0 is the lower face, as atan2 has it, and a side given
  // puts the point on that face whatever xb's rounding; a clamped point (the other sign of xb than its
  // side) has theta = side * pi exactly, F = sqrt r (side, 0, 0, 0).
  xfem::TipCoordinates tc;
  tc.grad.setZero();
  tc.xa = -0.25;
  tc.xb = -0.0;
  CHECK(xfem::branch_functions(tc, 0).F == Eigen::Vector4d(-0.5, 0.0, 0.0, 0.0));
  tc.xb = 0.0;
  CHECK(xfem::branch_functions(tc, 0).F == Eigen::Vector4d(0.5, 0.0, 0.0, 0.0));
  tc.xb = 1e-14;
  CHECK(xfem::branch_functions(tc, -1).F == Eigen::Vector4d(-0.5, 0.0, 0.0, 0.0));
  tc.xb = 0.01;  // above the plane, on the lower face: clamped
  const xfem::BranchValues clamped = xfem::branch_functions(tc, -1);
  CHECK(clamped.F == Eigen::Vector4d(-std::sqrt(std::hypot(-0.25, 0.01)), 0.0, 0.0, 0.0));
}

TEST_CASE("branch_functions: gradients match central finite differences", "[branch_functions]") {
  // A tilted frame so that every component of R matters.
  const Eigen::Vector3d b = Eigen::Vector3d(0.2, -0.3, 1.0).normalized();
  const Eigen::Vector3d p0(0.1, 0.2, 0.3);
  const Eigen::Vector3d dir = Eigen::Vector3d(1.0, 2.0, 0.0).normalized();
  const xfem::CrackFront front({xfem::FrontSegment{p0, p0 + dir, b}});
  const xfem::CrackTipFrame f = front.frame(p0);
  const Eigen::Vector3d x = GENERATE(Eigen::Vector3d(0.4, 0.1, 0.5), Eigen::Vector3d(-0.2, 0.6, 0.1),
                                     Eigen::Vector3d(0.3, 0.5, 0.2), Eigen::Vector3d(-0.1, -0.3, 0.4));
  CAPTURE(x.transpose());
  const auto at = xfem::branch_functions(f, x);
  const double h = 1e-6;
  for (int d = 0; d < 3; ++d) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(d) * h;
    const Eigen::Vector4d fd = (xfem::branch_functions(f, x + e).F - xfem::branch_functions(f, x - e).F) / (2 * h);
    // Central differences: error O(h^2 F''') ~ 1e-11 here; 1e-7 leaves room for rounding (1e-16 / h).
    for (int j = 0; j < 4; ++j) CHECK_THAT(at.dF(j, d), Catch::WithinAbs(fd[j], 1e-7));
  }
}

namespace {

// A cut of the unit box whose front is the curve x = 0.5 + 0.15 sin(pi y) (12 segments), lying
// in the plane z = 0.47 (flat) or on the curved blade z = 0.47 + 0.6 (x - 0.5)^2, normal up.
std::shared_ptr<xfem::CutSurface> curved_front_cut(bool curved_blade) {
  const int n = 12;
  xfem::TriangleMesh cut;
  cut.points.resize(2 * (n + 1), 3);
  cut.triangles.resize(2 * n, 3);
  const auto z = [&](double x) { return 0.47 + (curved_blade ? 0.6 * (x - 0.5) * (x - 0.5) : 0.0); };
  // Behind the front the blade is sampled at x = -0.1 and at the front only: between them it is
  // planar per triangle, as a triangulated cut is.
  for (int i = 0; i <= n; ++i) {
    const double y = -0.1 + 1.2 * i / n, xf = 0.5 + 0.15 * std::sin(M_PI * y);
    cut.points.row(2 * i) << -0.1, y, z(-0.1);
    cut.points.row(2 * i + 1) << xf, y, z(xf);
  }
  for (int i = 0; i < n; ++i) {
    cut.triangles.row(2 * i) << 2 * i, 2 * i + 1, 2 * i + 3;
    cut.triangles.row(2 * i + 1) << 2 * i, 2 * i + 3, 2 * i + 2;
  }
  return std::make_shared<xfem::CutSurface>(cut);
}

}  // namespace

TEST_CASE("branch_functions: continuous across every interior face of a curved-front mesh except across the cut",
          "[branch_functions]") {
  const xfem::TetMesh mesh = xfem::box_mesh({8, 8, 8}, {0, 0, 0}, {1, 1, 1});
  for (const bool blade : {false, true}) {
    const auto cut = curved_front_cut(blade);
    const xfem::Classification c = xfem::classify(mesh, *cut);
    REQUIRE(c.front.segments().size() >= 8);
    // Every interior face once: sorted node triples shared by two tets.
    std::map<std::array<int, 3>, int> uses;
    for (int t = 0; t < mesh.tets.rows(); ++t)
      for (int k = 0; k < 4; ++k) {
        std::array<int, 3> f;
        for (int i = 0, j = 0; i < 4; ++i)
          if (i != k) f[j++] = mesh.tets(t, i);
        std::sort(f.begin(), f.end());
        ++uses[f];
      }
    double jump_new = 0, jump_old = 0;
    long compared = 0;
    const double eps = 1e-9;
    for (const auto& [f, count] : uses) {
      if (count != 2) continue;
      Eigen::Vector3d P[3];
      for (int i = 0; i < 3; ++i) P[i] = mesh.points.row(f[i]).transpose();
      const Eigen::Vector3d n = (P[1] - P[0]).cross(P[2] - P[0]).normalized();
      for (const Eigen::Vector3d& l : {Eigen::Vector3d(0.6, 0.2, 0.2), Eigen::Vector3d(0.2, 0.6, 0.2),
                                      Eigen::Vector3d(0.2, 0.2, 0.6)}) {
        const Eigen::Vector3d x = l[0] * P[0] + l[1] * P[1] + l[2] * P[2];
        const Eigen::Vector3d xp = x + eps * n, xm = x - eps * n;
        const int sp = cut->side(xp), sm = cut->side(xm);
        if (sp != sm) continue;  // across the cut: F is meant to jump there
        double s, d;
        c.front.chains()[0].closest(x, s, d);
        if (d > 0.3) continue;  // the enrichment zone; far away the closest front point may jump
        const Eigen::Vector4d Fp = xfem::branch_functions(c.front.coordinates(xp), sp).F;
        const Eigen::Vector4d Fm = xfem::branch_functions(c.front.coordinates(xm), sm).F;
        jump_new = std::max(jump_new, (Fp - Fm).cwiseAbs().maxCoeff());
        const Eigen::Vector4d Gp = xfem::branch_functions(c.front.frame(xp), xp, sp).F;
        const Eigen::Vector4d Gm = xfem::branch_functions(c.front.frame(xm), xm, sm).F;
        jump_old = std::max(jump_old, (Gp - Gm).cwiseAbs().maxCoeff());
        ++compared;
      }
    }
    INFO((blade ? "curved blade" : "flat cut") << ": " << compared << " face points, largest jump of F "
                                               << jump_new << " (closest-segment frames: " << jump_old << ")");
    CHECK(compared > 1000);
    CHECK(jump_new < 1e-5);
    // What the test catches: on the curved blade the frame of the closest segment jumps (its b
    // turns from segment to segment); on the flat cut only its gradient directions do.
    if (blade) CHECK(jump_old > 1e-3);

    // theta = +-pi exactly on the faces of a flat cut behind the front: F1 = F2 = F3 = 0,
    // F0 = side sqrt(r). (On the curved blade only where the blade lies on the far side of the
    // front's tangent plane from the point's side; elsewhere theta is within the blade's bend of pi.)
    if (blade) continue;
    const xfem::TriangleMesh& cm = cut->mesh();
    for (int t = 0; t < cm.triangles.rows(); ++t) {
      const Eigen::Vector3d x = (cm.points.row(cm.triangles(t, 0)) + cm.points.row(cm.triangles(t, 1)) +
                                 cm.points.row(cm.triangles(t, 2))).transpose() / 3.0;
      if (x.y() < 0.05 || x.y() > 0.95 || x.x() < 0.0) continue;
      const xfem::TipCoordinates tc = c.front.coordinates(x);
      REQUIRE(tc.xa < 0);
      for (const int side : {1, -1}) {
        const Eigen::Vector4d F = xfem::branch_functions(tc, side).F;
        const double sr = std::sqrt(std::hypot(tc.xa, tc.xb));
        CHECK_THAT(F[0], Catch::WithinAbs(side * sr, 1e-14));
        CHECK_THAT(F[1], Catch::WithinAbs(0.0, 1e-14));
        CHECK_THAT(F[2], Catch::WithinAbs(0.0, 1e-14));
        CHECK_THAT(F[3], Catch::WithinAbs(0.0, 1e-14));
      }
    }
  }
}

TEST_CASE("branch_functions: gradients from continuous coordinates match finite differences on a curved front",
          "[branch_functions]") {
  const auto cut = curved_front_cut(true);
  const xfem::Classification c = xfem::classify(xfem::box_mesh({6, 6, 6}, {0, 0, 0}, {1, 1, 1}), *cut);
  const double h = 1e-6;
  for (const Eigen::Vector3d& x : {Eigen::Vector3d(0.3, 0.3, 0.6), Eigen::Vector3d(0.8, 0.55, 0.4),
                                  Eigen::Vector3d(0.55, 0.71, 0.52), Eigen::Vector3d(0.2, 0.4, 0.3)}) {
    const int side = cut->side(x);
    const xfem::BranchValues B = xfem::branch_functions(c.front.coordinates(x), side);
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(k);
      const Eigen::Vector4d d = (xfem::branch_functions(c.front.coordinates(x + e), side).F -
                                 xfem::branch_functions(c.front.coordinates(x - e), side).F) / (2 * h);
      for (int j = 0; j < 4; ++j) CHECK_THAT(B.dF(j, k), Catch::WithinAbs(d[j], 1e-6));
    }
  }
}
