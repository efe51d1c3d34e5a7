// SPDX-License-Identifier: MIT
#include "xfem/integrate/conforming_quadrature.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <memory>

#include "xfem/system/assembly.h"
#include "xfem/generate/box_mesh.h"
#include "xfem/core/error.h"
#include "xfem/system/problem.h"
#include "enriched_test_meshes.h"

namespace {

using V = Eigen::Vector3d;

double sum(const std::vector<double>& w) {
  double s = 0;
  for (double x : w) s += x;
  return s;
}

// Exact integral over tet (p0..p3) of lambda_0^a lambda_1^b lambda_2^c lambda_3^d:
// 6 V a! b! c! d! / (a + b + c + d + 3)!.
double barycentric_moment(double volume, int a, int b, int c, int d) {
  auto f = [](int n) { return std::tgamma(n + 1.0); };
  return 6 * volume * f(a) * f(b) * f(c) * f(d) / f(a + b + c + d + 3);
}

using xfem_test::cut_box;
using xfem_test::plain;
using xfem_test::plane_cut;

// One cube [0,1]^3 (6 tets), every node branch enriched, the front the line x = -0.2, z = 0.5
// (parallel to y) outside the box: no cut element, every element integrates the ACTFs.
xfem::EnrichedMesh all_branch_box() {
  xfem::EnrichedMesh em = xfem_test::all_branch(xfem::box_mesh({1, 1, 1}, {0, 0, 0}, {1, 1, 1}));
  em.front = xfem::CrackFront({xfem::FrontSegment{{-0.2, 2.0, 0.5}, {-0.2, -1.0, 0.5}, {0, 0, 1}}});
  em.cut = plane_cut(0.5);
  return em;
}

Eigen::MatrixXd dense_full(const xfem::SparseMatrix& lower) {
  const Eigen::MatrixXd L = Eigen::MatrixXd(lower);
  Eigen::MatrixXd K = L + L.transpose();
  K.diagonal() = L.diagonal();
  return K;
}

int zero_eigenvalues(const xfem::SparseMatrix& lower, double& min_over_max) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(dense_full(lower));
  const Eigen::VectorXd ev = eig.eigenvalues();
  min_over_max = ev.minCoeff() / ev.maxCoeff();
  return static_cast<int>((ev.array().abs() < 1e-10 * ev.maxCoeff()).count());
}

}  // namespace

TEST_CASE("conforming_quadrature: Gauss-Legendre on [0,1] is exact to degree 2n - 1", "[conforming_quadrature]") {
  for (int n : {1, 2, 5, 12, 40}) {
    std::vector<double> x, w;
    xfem::gauss_legendre_01(n, x, w);
    for (int p : {0, 1, 2 * n - 1}) {
      double s = 0;
      for (int i = 0; i < n; ++i) s += w[i] * std::pow(x[i], p);
      CHECK(s == Approx(1.0 / (p + 1)).epsilon(1e-14));
    }
  }
  std::vector<double> x, w;
  CHECK_THROWS_WITH(xfem::gauss_legendre_01(0, x, w), Catch::Contains("order must be in 1..64, got 0"));
}

TEST_CASE("conforming_quadrature: edge and vertex rules give the volume and integrate cubics exactly",
          "[conforming_quadrature]") {
  const V p0(0.1, -0.2, 0.05), p1(1.3, 0.1, -0.2), p2(0.2, 0.9, 0.3), p3(0.4, 0.3, 1.1);
  const double volume = std::abs(xfem::signed_volume(p0, p1, p2, p3));
  const Eigen::Matrix4d T = (Eigen::Matrix4d() << p0, p1, p2, p3, 1, 1, 1, 1).finished();
  const Eigen::Matrix4d Tinv = T.inverse();
  auto lambda = [&](const V& x) { return Eigen::Vector4d(Tinv * Eigen::Vector4d(x[0], x[1], x[2], 1)); };
  for (int rule = 0; rule < 2; ++rule) {
    xfem::PointRule r;
    if (rule == 0) xfem::append_edge_rule(p0, p1, p2, p3, 6, 1, r);
    else xfem::append_vertex_rule(p0, p1, p2, p3, 6, -1, r);
    REQUIRE(r.size() == 216);
    CHECK(sum(r.weights) == Approx(volume).epsilon(1e-13));
    for (int s : r.side) CHECK(s == (rule == 0 ? 1 : -1));
    double m1 = 0, m2 = 0, m3 = 0;
    for (int q = 0; q < r.size(); ++q) {
      const Eigen::Vector4d l = lambda(r.x[q]);
      CHECK(l.minCoeff() > 0);
      m1 += r.weights[q] * l[0] * l[1] * l[2];
      m2 += r.weights[q] * l[3] * l[3] * l[3];
      m3 += r.weights[q] * l[1] * l[1] * l[3];
    }
    CAPTURE(rule);
    CHECK(m1 == Approx(barycentric_moment(volume, 1, 1, 1, 0)).epsilon(1e-12));
    CHECK(m2 == Approx(barycentric_moment(volume, 0, 0, 0, 3)).epsilon(1e-12));
    CHECK(m3 == Approx(barycentric_moment(volume, 0, 2, 0, 1)).epsilon(1e-12));
  }
}

TEST_CASE("conforming_quadrature: the plain collapsed rule (s = sigma) integrates cubics with 3 points per direction",
          "[conforming_quadrature]") {
  // Degree p exact for 2 radial - 1 >= p + 2 (the Jacobian s (1 - s) adds 2), against 2p + 5 for
  // s = sigma^2: the graded rule's choice on pieces off the front (TetRuleLayout::graded()).
  const V p0(0.1, -0.2, 0.05), p1(1.3, 0.1, -0.2), p2(0.2, 0.9, 0.3), p3(0.4, 0.3, 1.1);
  const double volume = std::abs(xfem::signed_volume(p0, p1, p2, p3));
  const Eigen::Matrix4d T = (Eigen::Matrix4d() << p0, p1, p2, p3, 1, 1, 1, 1).finished();
  const Eigen::Matrix4d Tinv = T.inverse();
  auto lambda = [&](const V& x) { return Eigen::Vector4d(Tinv * Eigen::Vector4d(x[0], x[1], x[2], 1)); };
  xfem::PointRule plain, squared;
  xfem::append_edge_rule(p0, p1, p2, p3, 3, 3, 3, 1, plain, false);
  xfem::append_edge_rule(p0, p1, p2, p3, 3, 3, 3, 1, squared, true);
  REQUIRE(plain.size() == 27);
  CHECK(sum(plain.weights) == Approx(volume).epsilon(1e-13));
  double m_plain = 0, m_squared = 0;
  for (int q = 0; q < 27; ++q) {
    const Eigen::Vector4d a = lambda(plain.x[q]), b = lambda(squared.x[q]);
    m_plain += plain.weights[q] * a[2] * a[3] * a[3];
    m_squared += squared.weights[q] * b[2] * b[3] * b[3];
  }
  const double exact = barycentric_moment(volume, 0, 0, 1, 2);
  CHECK(m_plain == Approx(exact).epsilon(1e-13));
  CHECK(std::abs(m_squared - exact) > 1e-6 * exact);  // the sigma^2 rule needs 6 points for this
  // The graded layout covers a tet without a vertex on the front with the tet's volume.
  xfem::PointRule graded;
  xfem::append_tet_rule({p0, p1, p2, p3}, xfem::CrackFront(), xfem::TetRuleLayout::graded(), -1, graded);
  CHECK(graded.size() == 64);
  CHECK(sum(graded.weights) == Approx(volume).epsilon(1e-13));
}

TEST_CASE("conforming_quadrature: the rule of order n lays out its points by the piece's place to the front",
          "[conforming_quadrature]") {
  // TetRuleLayout::of_order(3), what conforming_rule(..., 3, ...) uses (issue 35): an edge on the
  // front 3 x 2 x 3 points, a vertex on it 3 x 3 x 3, a piece without one 4^3 (plain collapse)
  // within its longest edge of the front and the symmetric 4-point rule beyond; no bisection at
  // order 3.
  const xfem::TetRuleLayout l = xfem::TetRuleLayout::of_order(3);
  CHECK((l.radial == 3 && l.along == 2 && l.across == 3 && l.far == 4 && !l.far_squared));
  CHECK((l.remote == 4 && l.remote_symmetric && l.remote_ratio == 1.0 && l.split_at_touch));
  CHECK((l.near_levels == 0 && l.far_levels == 0 && l.distant_ratio == 1.0));
  // From order 4 up the points at the front as before: n - 2 along it, n - 1 in the angle.
  CHECK((xfem::TetRuleLayout::of_order(4).along == 2 && xfem::TetRuleLayout::of_order(4).across == 3));
  CHECK((xfem::TetRuleLayout::of_order(6).along == 4 && xfem::TetRuleLayout::of_order(6).across == 5));
  CHECK(!xfem::TetRuleLayout::of_order(6).remote_symmetric);
  CHECK(xfem::consistent_face_points(3) == 4);
  // From order 4 up the bisection depth of the rule before (uniform(n)).
  CHECK(xfem::TetRuleLayout::of_order(5).near_levels == xfem::TetRuleLayout::uniform(5).near_levels);
  const V o(0, 0, 0), ex(1, 0, 0), ey(0, 1, 0), ez(0, 0, 1);
  const double volume = 1.0 / 6.0;
  auto points = [&](const xfem::CrackFront& front) {
    xfem::PointRule r;
    xfem::append_tet_rule({o, ex, ey, ez}, front, 3, 1, r);
    CHECK(sum(r.weights) == Approx(volume).epsilon(1e-13));
    return r.size();
  };
  // Front the z axis: through edge o-ez.
  CHECK(points(xfem::CrackFront({xfem::FrontSegment{{0, 0, 2}, {0, 0, -1}, {1, 0, 0}}})) == 18);
  // Through vertex o only: a front ending at o, x = -t (1, 1, 1). Its extension runs through the tet,
  // so the angle around it is not defined there: two bisections by angle (max_angle's cap), 4 x 27.
  CHECK(points(xfem::CrackFront({xfem::FrontSegment{{-1, -1, -1}, {0, 0, 0}, V(1, -1, 0).normalized()}})) == 108);
  {
    // A front through o along (1, -1, 0), which meets the tet (o, ex, ey, (1, 1, 0.5)) at o alone;
    // the face opposite o spans 19.5 degrees around it: the vertex rule's 3 x 3 x 3 points.
    const xfem::CrackFront through_o({xfem::FrontSegment{{-1, 1, 0}, {1, -1, 0}, {0, 0, 1}}});
    xfem::PointRule r;
    xfem::append_tet_rule({o, ex, ey, V(1, 1, 0.5)}, through_o, 3, 1, r);
    CHECK(r.size() == 27);
    CHECK(sum(r.weights) == Approx(0.5 / 6).epsilon(1e-13));
  }
  // Near (0.5 from the tet, longest edge sqrt 2) and far (5 away) without touching it.
  CHECK(points(xfem::CrackFront({xfem::FrontSegment{{-0.5, 0, -1}, {-0.5, 0, 2}, {1, 0, 0}}})) == 64);
  CHECK(points(xfem::CrackFront({xfem::FrontSegment{{-5, 0, -1}, {-5, 0, 2}, {1, 0, 0}}})) == 4);
  // far_split_ratio: a piece off the front is bisected (far_levels) only while the front is nearer
  // than that ratio times its longest edge (sqrt 2 here; the front 0.5 away).
  const xfem::CrackFront near_front({xfem::FrontSegment{{-0.5, 0, -1}, {-0.5, 0, 2}, {1, 0, 0}}});
  xfem::TetRuleLayout split = l;
  split.far_levels = 1;
  CHECK(split.far_split_ratio == 0.5);
  xfem::PointRule halves, whole;
  xfem::append_tet_rule({o, ex, ey, ez}, near_front, split, 1, halves);  // 0.5 < 0.5 sqrt 2: bisected
  split.far_split_ratio = 0.3;                                           // 0.5 > 0.3 sqrt 2: not
  xfem::append_tet_rule({o, ex, ey, ez}, near_front, split, 1, whole);
  CHECK(halves.size() == 128);
  CHECK(whole.size() == 64);
  CHECK(sum(halves.weights) == Approx(volume).epsilon(1e-13));
}

TEST_CASE("conforming_quadrature: 1/r to a front through an edge or a vertex converges to the closed form",
          "[conforming_quadrature]") {
  // Tet (0, e_x, e_y, e_z), front the z axis (through edge 0-3): integral of 1/r, r = sqrt(x^2 + y^2),
  // = integral_0^1 (1 - z) dz * integral_0^(pi/2) dphi / (cos phi + sin phi) = sqrt(2) ln(1 + sqrt 2) / 2.
  const double exact = std::sqrt(2.0) * std::log(1 + std::sqrt(2.0)) / 2;
  const xfem::CrackFront front({xfem::FrontSegment{{0, 0, 2}, {0, 0, -1}, {1, 0, 0}}});
  const V o(0, 0, 0), ex(1, 0, 0), ey(0, 1, 0), ez(0, 0, 1);
  auto integral = [&](const xfem::PointRule& r) {
    double s = 0;
    for (int q = 0; q < r.size(); ++q) s += r.weights[q] / std::hypot(r.x[q][0], r.x[q][1]);
    return s;
  };
  SECTION("edge on the front, vertices in any order") {
    for (const auto& p : {std::array<V, 4>{o, ex, ey, ez}, std::array<V, 4>{ey, ez, ex, o}}) {
      xfem::PointRule r;
      // Order 7 (of_order: 6 points in the angle; the order-6 rule's 5 give 1.9e-8).
      xfem::append_tet_rule(p, front, 7, 0, r);
      CHECK(std::abs(integral(r) - exact) < 1e-8 * exact);
      CHECK(sum(r.weights) == Approx(1.0 / 6).epsilon(1e-13));
    }
  }
  SECTION("split into a tet with only the vertex 0 on the front and one with the edge 0-3 on it") {
    const V m = 0.5 * (ex + ez);
    xfem::PointRule vertex_part, edge_part;
    xfem::append_tet_rule({o, ex, ey, m}, front, 7, 0, vertex_part);
    xfem::append_tet_rule({o, m, ey, ez}, front, 7, 0, edge_part);
    CHECK(std::abs(integral(vertex_part) + integral(edge_part) - exact) < 1e-8 * exact);
    CHECK(sum(vertex_part.weights) + sum(edge_part.weights) == Approx(1.0 / 6).epsilon(1e-13));
  }
  SECTION("for contrast, the same tensor rule collapsed away from the front errs far more") {
    xfem::PointRule r;
    xfem::append_edge_rule(ex, ey, o, ez, 6, 0, r);  // collapsed on the edge opposite the front
    CHECK(std::abs(integral(r) - exact) > 1e-6 * exact);
  }
}

TEST_CASE("conforming_quadrature: a front piercing an edge between its ends is split there (split_at_touch)",
          "[conforming_quadrature]") {
  // The front is the y axis (x = z = 0). The tet touches the plane x = 0 only along its edge a-b,
  // which crosses z = 0 at an interior point P: the integrand 1/r, r = sqrt(x^2 + z^2), is singular
  // at P alone. A mesh with nodes in the front's plane has such tets beside the cut (the beams of
  // the convergence study at sizes 0.03 and 0.015).
  const xfem::CrackFront front({xfem::FrontSegment{{0, -2, 0}, {0, 2, 0}, {0, 0, 1}}});
  const V a(0, 0.3, -0.6), b(0, -0.2, 0.7), c(0.8, 0.1, 0.0), d(0.6, 0.5, 0.4);
  const double volume = std::abs((b - a).cross(c - a).dot(d - a)) / 6;
  auto integral = [&](const xfem::PointRule& r) {
    double s = 0;
    for (int q = 0; q < r.size(); ++q) s += r.weights[q] / std::hypot(r.x[q][0], r.x[q][2]);
    return s;
  };
  // The reference, independently: the two halves at P, each with the vertex rule at P of order 24.
  const V P = a + (0.6 / 1.3) * (b - a);
  xfem::PointRule reference;
  xfem::append_vertex_rule(P, a, c, d, 24, 0, reference);
  xfem::append_vertex_rule(P, b, c, d, 24, 0, reference);
  REQUIRE(sum(reference.weights) == Approx(volume).epsilon(1e-12));
  const double exact = integral(reference);
  auto error = [&](const xfem::TetRuleLayout& layout) {
    xfem::PointRule r;
    xfem::append_tet_rule({a, b, c, d}, front, layout, 0, r);
    CHECK(sum(r.weights) == Approx(volume).epsilon(1e-13));
    for (const V& x : r.x) CHECK(x[0] >= -1e-15);  // every point in the tet's half-space x >= 0
    return std::abs(integral(r) - exact) / exact;
  };
  const double split3 = error(xfem::TetRuleLayout::of_order(3)), split5 = error(xfem::TetRuleLayout::of_order(5));
  xfem::TetRuleLayout whole = xfem::TetRuleLayout::of_order(3);
  whole.split_at_touch = false;
  const double unsplit3 = error(whole);
  whole = xfem::TetRuleLayout::of_order(5);
  whole.split_at_touch = false;
  const double unsplit5 = error(whole);
  INFO("order 3: split " << split3 << ", whole " << unsplit3 << "; order 5: split " << split5 << ", whole " << unsplit5);
  // Split, the rule converges exponentially (measured 7.4e-3 at order 3, 7.4e-8 at order 5);
  // collapsed onto the whole edge, algebraically (2.9e-2, 3.6e-4).
  CHECK(split3 < 1e-2);
  CHECK(split5 < 1e-6);
  CHECK(unsplit3 > 3 * split3);
  CHECK(unsplit5 > 1000 * split5);
}

TEST_CASE("conforming_quadrature: a piece at the front spanning more than a right angle is bisected (max_angle)",
          "[conforming_quadrature]") {
  // Edge o-ez on the front (the z axis), the opposite edge from c (5.7 degrees around the front) to d
  // (174 degrees): ahead of a front nothing else splits such a piece (the cut's triangles stop at the
  // front). The integrand cos(theta / 2) / r varies with the angle as the branch functions.
  // gradient products do.
  const xfem::CrackFront front({xfem::FrontSegment{{0, 0, 2}, {0, 0, -1}, {0, 1, 0}}});
  const V o(0, 0, 0), ez(0, 0, 1), c(1, 0.1, 0), d(-1, 0.1, 0.5);
  auto integral = [&](const xfem::PointRule& r) {
    double s = 0;
    for (int q = 0; q < r.size(); ++q) {
      const double x = r.x[q][0], y = r.x[q][1];
      s += r.weights[q] * std::cos(0.5 * std::atan2(y, x)) / std::hypot(x, y);
    }
    return s;
  };
  xfem::PointRule reference;  // 60 points in the angle: converged
  xfem::append_edge_rule(o, ez, c, d, 3, 2, 60, 0, reference);
  const double exact = integral(reference);
  auto error = [&](double max_angle) {
    xfem::TetRuleLayout layout = xfem::TetRuleLayout::of_order(3);
    layout.max_angle = max_angle;
    xfem::PointRule r;
    xfem::append_tet_rule({o, ez, c, d}, front, layout, 0, r);
    CHECK(sum(r.weights) == Approx(sum(reference.weights)).epsilon(1e-13));
    return std::abs(integral(r) - exact) / std::abs(exact);
  };
  CHECK(xfem::TetRuleLayout::of_order(3).max_angle == Approx(std::acos(-1.0) / 2));
  const double split = error(xfem::TetRuleLayout::of_order(3).max_angle), whole = error(0);
  INFO("bisected by angle " << split << ", whole " << whole);
  // Measured: 4.7e-3 bisected (twice: kMaxAngleSplits), 0.93 whole (its 3 points in the angle miss
  // the part of edge cd that passes 0.1 from the front).
  CHECK(split < 1e-2);
  CHECK(whole > 20 * split);
}

TEST_CASE("conforming_quadrature: a completely cut cube integrates H exactly; volumes sum per element",
          "[conforming_quadrature]") {
  for (double z : {0.3, 0.4999, 1e-4}) {
    CAPTURE(z);
    const xfem::EnrichedMesh em = cut_box(z);
    const xfem::CutElementSplits splits = xfem::split_cut_elements(em);
    double above = 0, below = 0, moment_above = 0;
    for (int t = 0; t < em.tets(); ++t) {
      xfem::PointRule r;
      xfem::conforming_rule(em, splits, t, 4, r);  // n = 4: exact for linear functions
      CHECK(sum(r.weights) == Approx(std::abs(xfem::signed_volume(em.mesh, t))).epsilon(1e-13));
      if (em.cut_class[t] == 0) continue;
      for (int q = 0; q < r.size(); ++q) {
        REQUIRE(r.side[q] != 0);
        CHECK(r.side[q] * (r.x[q][2] - z) > 0);  // each point on its own side of the plane
        if (r.side[q] > 0) {
          above += r.weights[q];
          moment_above += r.weights[q] * r.x[q][2];
        } else {
          below += r.weights[q];
        }
      }
    }
    CHECK(std::abs(above - (0.5 - z)) < 1e-13);
    CHECK(std::abs(below - z) < 1e-13);
    CHECK(std::abs(moment_above - (0.25 - z * z) / 2) < 1e-13);
  }
}

TEST_CASE("conforming_quadrature: K is PSD with 12 zero eigenvalues when cut through, no zero rows for a sliver",
          "[conforming_quadrature]") {
  const xfem::Lame material = xfem::lame(300e3, 0.35);
  const xfem::Quadrature unused = xfem::oversampling_quadrature(1);
  for (double z : {0.3, 0.4999}) {
    CAPTURE(z);
    const xfem::EnrichedMesh em = cut_box(z);
    const xfem::SparseMatrix K = xfem::stiffness_matrix(em, material, unused, nullptr, {}, 5);
    // The sliver's sign DOFs are supported (no zero row) but nearly singular, like the paper's tiny
    // enrichment: the count of eigenvalues below 1e-10 is exact only for a regular cut.
    double ratio = 0;
    const int zeros = zero_eigenvalues(K, ratio);
    if (z == 0.3) CHECK(zeros == 12);
    CHECK(ratio > -1e-10);
    CHECK(xfem::unsupported_dofs(K, em.np).empty());
  }
  // The oversampling rule leaves the sign DOFs of the sliver 0.4999 < z < 0.5 without any point.
  const xfem::EnrichedMesh em = cut_box(0.4999);
  CHECK(!xfem::unsupported_dofs(xfem::stiffness_matrix(em, material, xfem::oversampling_quadrature(30)), em.np).empty());
}

TEST_CASE("conforming_quadrature: K of an all-branch-enriched uncut cube has the null space of a converged rule",
          "[conforming_quadrature]") {
  const xfem::EnrichedMesh em = all_branch_box();
  const xfem::SparseMatrix K =
      xfem::stiffness_matrix(em, xfem::lame(1.0, 0.3), xfem::oversampling_quadrature(1), nullptr, {}, 5);
  REQUIRE(K.rows() == 3 * 40);
  // The enriched space itself has 6 more zero-energy modes on this one-cube mesh: a converged
  // oversampling rule finds the same count, so the conforming rule adds none and loses none.
  double ratio = 0, ratio_oversampling = 0;
  const int reference =
      zero_eigenvalues(xfem::stiffness_matrix(em, xfem::lame(1.0, 0.3), xfem::oversampling_quadrature(1000)),
                       ratio_oversampling);
  CHECK(reference == 12);
  CHECK(zero_eigenvalues(K, ratio) == reference);
  CHECK(ratio > -1e-10);
}

TEST_CASE("conforming_quadrature: problem.json integration.rule and order", "[conforming_quadrature]") {
  const std::string head = R"({"material": {"E": 1, "nu": 0.3}, "integration": )";
  auto parse = [&](const std::string& integration) {
    return xfem::parse_problem(xfem::Json::parse(head + integration + "}"), "problem.json");
  };
  CHECK(parse(R"({"points": 30})").rule == xfem::Problem::Rule::Oversampling);
  const xfem::Problem p = parse(R"({"rule": "conforming", "order": 7})");
  CHECK(p.rule == xfem::Problem::Rule::Conforming);
  CHECK(p.order == 7);
  CHECK(parse(R"({"rule": "conforming"})").order == 3);
  // The conforming rule is the default; points or refine alone keep a file's old meaning.
  CHECK(xfem::parse_problem(xfem::Json::parse(R"({"material": {"E": 1, "nu": 0.3}})"), "p.json").rule ==
        xfem::Problem::Rule::Conforming);
  CHECK(parse(R"({"refine": 1})").rule == xfem::Problem::Rule::Oversampling);
  CHECK_THROWS_WITH(parse(R"({"rule": "gauss"})"), "problem.json: integration.rule must be \"oversampling\", "
                                                   "\"conforming\", \"graded\" or \"pieces\", got \"gauss\"");
  // "conforming" (the default) computes the blocks without branch functions in closed form,
  // "pieces" every block from the points (the rule before issue 35), "graded" also lays out the
  // branch functions' points by TetRuleLayout::graded().
  const xfem::Problem fallback = xfem::parse_problem(xfem::Json::parse(R"({"material": {"E": 1, "nu": 0.3}})"), "p.json");
  CHECK((fallback.closed_form && !fallback.graded));
  const xfem::Problem pieces = parse(R"({"rule": "pieces", "order": 5})");
  CHECK((pieces.rule == xfem::Problem::Rule::Conforming && !pieces.closed_form && !pieces.graded && pieces.order == 5));
  const xfem::Problem graded = parse(R"({"rule": "graded"})");
  CHECK((graded.rule == xfem::Problem::Rule::Conforming && graded.closed_form && graded.graded));
  CHECK_THROWS_WITH(parse(R"({"rule": "conforming", "order": 0})"),
                    "problem.json: integration.order must be an integer in 1..20, got 0");
  CHECK(parse(R"({"rule": "oversampling"})").points == 30);
}

TEST_CASE("conforming_quadrature: the symmetric tet rules integrate degree 2 (4 points) and 5 (14 points) exactly",
          "[conforming_quadrature]") {
  // Reference: the plain collapsed rule with 6 points per direction, exact far beyond degree 5
  // (2 * 6 - 1 >= p + 2 radially, >= p along and across).
  const V a(0.1, -0.2, 0.05), b(1.3, 0.1, -0.1), c(0.2, 0.9, 0.3), d(0.4, 0.3, 1.1);
  xfem::PointRule ref;
  xfem::append_edge_rule(a, b, c, d, 6, 6, 6, 0, ref, false);
  auto integrate = [](const xfem::PointRule& r, int i, int j, int k) {
    double s = 0;
    for (int p = 0; p < r.size(); ++p)
      s += r.weights[p] * std::pow(r.x[p].x(), i) * std::pow(r.x[p].y(), j) * std::pow(r.x[p].z(), k);
    return s;
  };
  for (int points : {4, 14}) {
    xfem::PointRule r;
    xfem::append_symmetric_tet_rule(a, b, c, d, points, -1, r);
    REQUIRE(r.size() == points);
    for (int p = 0; p < r.size(); ++p) CHECK((r.weights[p] > 0 && r.side[p] == -1));
    const int degree = points == 4 ? 2 : 5;
    double worst_exact = 0, worst_above = 0;  // relative errors at the rule's degree and one above
    for (int i = 0; i <= degree + 1; ++i)
      for (int j = 0; i + j <= degree + 1; ++j)
        for (int k = 0; i + j + k <= degree + 1; ++k) {
          const double e = integrate(ref, i, j, k);
          const double err = std::abs(integrate(r, i, j, k) - e) / std::abs(e);
          (i + j + k <= degree ? worst_exact : worst_above) = std::max(i + j + k <= degree ? worst_exact : worst_above, err);
        }
    INFO(points << " points: worst relative error up to degree " << degree << ": " << worst_exact << ", above: " << worst_above);
    CHECK(worst_exact < 1e-13);
    CHECK(worst_above > 1e-6);  // and no more: the rule's degree is what it claims
  }
  xfem::PointRule r;
  CHECK_THROWS_AS(xfem::append_symmetric_tet_rule(a, b, c, d, 5, 0, r), xfem::Error);
}

TEST_CASE("conforming_quadrature: the fast rule lays out fewer points where the front is far on the piece's scale",
          "[conforming_quadrature]") {
  // TetRuleLayout::fast() (--rule fast): the default's points at the front and within half a
  // longest edge of it, the symmetric 14-point rule beyond.
  const xfem::TetRuleLayout l = xfem::TetRuleLayout::fast();
  const V o(0, 0, 0), ex(1, 0, 0), ey(0, 1, 0), ez(0, 0, 1);
  auto points = [&](const xfem::CrackFront& front) {
    xfem::PointRule r;
    xfem::append_tet_rule({o, ex, ey, ez}, front, l, 1, r);
    CHECK(sum(r.weights) == Approx(1.0 / 6.0).epsilon(1e-13));
    return r.size();
  };
  CHECK(points(xfem::CrackFront({xfem::FrontSegment{{0, 0, 2}, {0, 0, -1}, {1, 0, 0}}})) == 18);
  CHECK(points(xfem::CrackFront({xfem::FrontSegment{{-1, -1, -1}, {0, 0, 0}, V(1, -1, 0).normalized()}})) == 108);
  // Longest edge sqrt 2: 0.5 away is within half of it (0.71), 1.2 and 5 beyond.
  CHECK(points(xfem::CrackFront({xfem::FrontSegment{{-0.5, 0, -1}, {-0.5, 0, 2}, {1, 0, 0}}})) == 64);
  CHECK(points(xfem::CrackFront({xfem::FrontSegment{{-1.2, 0, -1}, {-1.2, 0, 2}, {1, 0, 0}}})) == 14);
  CHECK(points(xfem::CrackFront({xfem::FrontSegment{{-5, 0, -1}, {-5, 0, 2}, {1, 0, 0}}})) == 14);
}
