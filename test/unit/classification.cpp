// SPDX-License-Identifier: MIT
#include "xfem/enrich/classification.h"
#include "xfem/enrich/growing_classification.h"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <random>

#include "xfem/generate/box_mesh.h"
#include "xfem/generate/cut_sweep.h"
#include "xfem/generate/organ_shape.h"
#include "xfem/enrich/dof_numbering.h"
#include "xfem/core/error.h"
#include "xfem/core/thread_limit.h"
#include "xfem/enrich/split_by_cuts.h"
#include "xfem/geometry/cut_pieces.h"
#include "xfem/generate/unstructured_mesh.h"

using xfem::CutClass;
using xfem::Enrichment;

namespace {

/// The rectangle [x0, x1] x [y0, y1] in the plane z, as two triangles with normal +z.
xfem::TriangleMesh rectangle(double x0, double x1, double y0, double y1, double z) {
  xfem::TriangleMesh m;
  m.points.resize(4, 3);
  m.points << x0, y0, z, x1, y0, z, x0, y1, z, x1, y1, z;
  m.triangles.resize(2, 3);
  m.triangles << 0, 1, 3, 0, 3, 2;
  return m;
}

xfem::TetMesh single_tet(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2, const Eigen::Vector3d& p3) {
  xfem::TetMesh m;
  m.points.resize(4, 3);
  m.points.row(0) << 0, 0, 0;
  m.points.row(1) = p1;
  m.points.row(2) = p2;
  m.points.row(3) = p3;
  m.tets.resize(1, 4);
  m.tets << 0, 1, 2, 3;
  return m;
}

/// The paper's beam cut (DESIGN.md): z = 0.1 for x <= 0.015, beyond the body on three sides.
xfem::TriangleMesh beam_cut() { return rectangle(-0.01, 0.015, -0.01, 0.07, 0.1); }

template <class E>
std::vector<int> ints(const std::vector<E>& v) {
  std::vector<int> out;
  for (E e : v) out.push_back(static_cast<int>(e));
  return out;
}

double front_length(const xfem::CrackFront& f) {
  double l = 0;
  for (const auto& s : f.segments()) l += (s.p1 - s.p0).norm();
  return l;
}

// pipelines/sweep's blade: an arc of radius 0.1 m over the top of the organ, 0.05 m deep, its
// triangles timed along the sweep.
xfem::TriangleMesh sweep_blade() {
  xfem::BladePath path;
  path.centre = {0, -0.09, 0.06};
  path.radius = 0.1;
  path.a0 = 40;
  path.a1 = 140;
  return xfem::cut_sweep(path, 0.05, {0, 0, -1}, 0.0, 0.006, 4.0);
}

}  // namespace

TEST_CASE("classification: a tet cut completely with a 1|3 split", "[classification]") {
  const auto mesh = single_tet({1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  const xfem::CutSurface cut(rectangle(-1, 2, -1, 2, 0.5));
  const auto c = xfem::classify(mesh, cut);
  CHECK(c.side == std::vector<int>{-1, -1, -1, 1});
  CHECK(c.cut_edges[0] == 3);  // the three edges to the apex
  CHECK(c.cut_faces[0] == 3);
  CHECK(c.cut_class[0] == CutClass::Complete);
  CHECK(c.enrichment == std::vector<Enrichment>(4, Enrichment::Sign));
  CHECK(c.front.empty());  // the rectangle's boundary lies outside the body
  CHECK(c.counts.complete == 1);
  CHECK(c.counts.cut_edges == 3);
}

TEST_CASE("classification: a tet cut completely with a 2|2 split", "[classification]") {
  const auto mesh = single_tet({1, 0, 0}, {0, 1, 1}, {0, 0, 1});
  REQUIRE(xfem::signed_volume(mesh, 0) > 0);
  const xfem::CutSurface cut(rectangle(-1, 2, -1, 2, 0.5));
  const auto c = xfem::classify(mesh, cut);
  CHECK(c.side == std::vector<int>{-1, -1, 1, 1});
  CHECK(c.cut_edges[0] == 4);  // all but 0-1 (z = 0) and 2-3 (z = 1)
  CHECK(c.cut_faces[0] == 4);
  CHECK(c.cut_class[0] == CutClass::Complete);
  CHECK(c.counts.sign == 4);
}

TEST_CASE("classification: a tet cut partially, front inside", "[classification]") {
  const auto mesh = single_tet({1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  // z = 0.5 for x <= 0.1: cuts edges 0-3 (at x = 0) and 2-3 (at x = 0, y = 0.5), misses 1-3
  // (crossing at x = 0.5). One completely cut face (0, 2, 3): partially cut.
  const xfem::CutSurface cut(rectangle(-1, 0.1, -1, 2, 0.5));
  const auto c = xfem::classify(mesh, cut);
  CHECK(c.cut_edges[0] == 2);
  CHECK(c.cut_faces[0] == 1);
  CHECK(c.cut_class[0] == CutClass::Partial);
  CHECK(c.enrichment == std::vector<Enrichment>(4, Enrichment::Branch));
  // The front: x = 0.1 in the section z = 0.5 (x, y >= 0, x + y <= 0.5), i.e. y in [0, 0.4],
  // oriented so that a = b x c = +x points away from the cut: b = +z, c = -y.
  REQUIRE(c.front.segments().size() == 1);
  const auto& s = c.front.segments()[0];
  CHECK(s.p0.isApprox(Eigen::Vector3d(0.1, 0.4, 0.5), 1e-12));
  CHECK(s.p1.isApprox(Eigen::Vector3d(0.1, 0.0, 0.5), 1e-12));
  CHECK(s.b.isApprox(Eigen::Vector3d(0, 0, 1)));
  CHECK(c.front.frame(Eigen::Vector3d(0.2, 0.1, 0.5)).R.col(0).isApprox(Eigen::Vector3d(1, 0, 0)));
  const auto d = xfem::dof_numbering(mesh.tets, 4, {2, 2, 2, 2}, {1});
  CHECK((d.np == 4 && d.ns == 0 && d.nb == 4 && d.n == 20));
}

TEST_CASE("classification: a 3D analogue of figure 2 with sign, branch and blending tets", "[classification]") {
  // Three unit cubes along x, cut z = 0.5 for x <= 1.5: cube 0 completely cut, the front in
  // cube 1, cube 2 uncut. Edges cross z = 0.5 only if they join z = 0 and z = 1, at their
  // midpoint; cut iff that midpoint has x <= 1.5.
  const auto mesh = xfem::box_mesh({3, 1, 1}, {0, 0, 0}, {3, 1, 1});
  const xfem::CutSurface cut(rectangle(-1, 1.5, -1, 2, 0.5));
  const auto c = xfem::classify(mesh, cut);
  auto P = [&](int i) { return Eigen::Vector3d(mesh.points.row(i).transpose()); };
  long branch_in_uncut = 0;
  for (int t = 0; t < mesh.tets.rows(); ++t) {
    int edges = 0;
    double xmin = 9, xmax = -9;
    for (int i = 0; i < 4; ++i) {
      xmin = std::min(xmin, P(mesh.tets(t, i)).x());
      xmax = std::max(xmax, P(mesh.tets(t, i)).x());
      for (int j = i + 1; j < 4; ++j) {
        const auto a = P(mesh.tets(t, i)), b = P(mesh.tets(t, j));
        edges += a.z() != b.z() && (a.x() + b.x()) / 2 <= 1.5;
      }
    }
    CAPTURE(t);
    CHECK(c.cut_edges[t] == edges);
    if (xmax <= 1) CHECK(c.cut_class[t] == CutClass::Complete);  // cube 0
    if (xmin >= 2) CHECK(c.cut_class[t] == CutClass::Uncut);     // cube 2
    if (c.cut_class[t] == CutClass::Partial) CHECK((xmin == 1 && xmax == 2));
    if (c.cut_class[t] == CutClass::Uncut)
      for (int i = 0; i < 4; ++i) branch_in_uncut += c.enrichment[mesh.tets(t, i)] == Enrichment::Branch;
  }
  // The front x = 1.5, z = 0.5 lies in the Kuhn faces u = w of cube 1: it only touches tets, so
  // none is partially cut; the tets behind it are completely cut, and every tet touching it has
  // branch nodes.
  CHECK(c.counts.partial == 0);
  CHECK(c.counts.branch > 0);
  CHECK(branch_in_uncut > 0);  // uncut blending tets in cube 2
  // Nodes: x = 0 sign; x = 1 and x = 2 are in partially cut tets of cube 1 (each of its tets
  // holds the diagonal (1,0,0)-(2,1,1), so all of them share those two nodes); x = 3 none.
  for (int i = 0; i < mesh.points.rows(); ++i) {
    CAPTURE(i);
    const double x = P(i).x();
    if (x == 0) CHECK(c.enrichment[i] == Enrichment::Sign);
    if (x == 3) CHECK(c.enrichment[i] == Enrichment::None);
    CHECK(c.side[i] == (P(i).z() > 0.5 ? 1 : -1));
  }
  CHECK(c.enrichment[1] == Enrichment::Branch);   // (1, 0, 0)
  CHECK(c.enrichment[14] == Enrichment::Branch);  // (2, 1, 1)
  CHECK_THAT(front_length(c.front), Catch::WithinAbs(1.0, 1e-12));  // x = 1.5, y in [0, 1]
  // The numbering is consistent with the counts: N = NP + NS + 4 NB.
  const auto d = xfem::dof_numbering(mesh.tets, mesh.points.rows(), ints(c.enrichment), ints(c.cut_class));
  CHECK(d.ns == c.counts.sign);
  CHECK(d.nb == c.counts.branch);
  CHECK(d.n == 16 + d.ns + 4 * d.nb);
}

TEST_CASE("classification: the paper's beam cut over a structured beam", "[classification]") {
  const auto mesh = xfem::box_mesh({3, 6, 19}, {0, 0, 0}, {0.03, 0.06, 0.2});
  const xfem::CutSurface cut(beam_cut());
  const auto c = xfem::classify(mesh, cut);
  for (int t = 0; t < mesh.tets.rows(); ++t) {
    double xmin = 1, xmax = -1, zmin = 1, zmax = -1;
    for (int i = 0; i < 4; ++i) {
      const auto p = mesh.points.row(mesh.tets(t, i));
      xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x());
      zmin = std::min(zmin, p.z()), zmax = std::max(zmax, p.z());
    }
    CAPTURE(t);
    const bool crosses = zmin < 0.1 && zmax > 0.1;
    if (!crosses || xmin >= 0.015) CHECK(c.cut_class[t] == CutClass::Uncut);
    if (crosses && xmax <= 0.015) CHECK(c.cut_class[t] == CutClass::Complete);
    if (c.cut_class[t] == CutClass::Partial) CHECK((xmin < 0.015 && xmax > 0.015));
  }
  for (int i = 0; i < mesh.points.rows(); ++i) CHECK(c.side[i] == (mesh.points(i, 2) > 0.1 ? 1 : -1));
  // z = 0.1 is the middle of a cell layer and x = 0.015 the middle of a cell column: the front lies
  // in the Kuhn faces u = w, touching tets (branch nodes) without passing through any.
  CHECK(c.counts.partial == 0);
  CHECK(c.counts.branch > 0);
  CHECK(c.counts.points_on_cut == 0);
  CHECK_THAT(front_length(c.front), Catch::WithinAbs(0.06, 1e-12));
  for (const auto& s : c.front.segments()) {
    CHECK_THAT(s.p0.x(), Catch::WithinAbs(0.015, 1e-15));
    CHECK_THAT(s.p0.z(), Catch::WithinAbs(0.1, 1e-15));
    CHECK(c.front.frame(s.p0).R.col(0).isApprox(Eigen::Vector3d(1, 0, 0)));
  }
}

namespace {

/// Checks a classification by the beam cut against the plane's own answer: an edge is cut iff it
/// crosses z = 0.1 at x <= 0.015, or (D2) has an end on the cut and ends on both sides; partially
/// cut tets straddle the front x = 0.015; sides by z (D1: z = 0.1 is +1).
void check_beam_cut(const xfem::TetMesh& mesh) {
  auto side = [](const Eigen::Vector3d& p) { return p.z() >= 0.1 ? 1 : -1; };
  auto on_cut = [](const Eigen::Vector3d& p) { return p.z() == 0.1 && p.x() <= 0.015; };
  const xfem::CutSurface cut(beam_cut());
  const auto c = xfem::classify(mesh, cut);
  for (int t = 0; t < mesh.tets.rows(); ++t) {
    int edges = 0;
    double xmin = 1, xmax = -1;
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector3d a = mesh.points.row(mesh.tets(t, i));
      xmin = std::min(xmin, a.x()), xmax = std::max(xmax, a.x());
      for (int j = i + 1; j < 4; ++j) {
        const Eigen::Vector3d b = mesh.points.row(mesh.tets(t, j));
        REQUIRE(!(a.z() == 0.1 && b.z() == 0.1));  // no edge in the cut's plane (not modelled here)
        if (on_cut(a) || on_cut(b)) {
          edges += side(a) != side(b);
          continue;
        }
        if ((a.z() - 0.1) * (b.z() - 0.1) >= 0) continue;
        const double s = (0.1 - a.z()) / (b.z() - a.z());
        edges += a.x() + s * (b.x() - a.x()) <= 0.015;
      }
    }
    CAPTURE(t);
    CHECK(c.cut_edges[t] == edges);
    if (c.cut_class[t] == CutClass::Partial) CHECK((xmin < 0.015 && xmax > 0.015));
    if (c.cut_class[t] == CutClass::Complete) CHECK(xmin < 0.015);
  }
  for (int i = 0; i < mesh.points.rows(); ++i) CHECK(c.side[i] == side(mesh.points.row(i).transpose()));
  CHECK(c.counts.partial > 0);
  CHECK(c.counts.complete > 0);
  CHECK_THAT(front_length(c.front), Catch::WithinAbs(0.06, 1e-12));
  for (const auto& s : c.front.segments())
    CHECK(c.front.frame(0.5 * (s.p0 + s.p1)).R.col(0).isApprox(Eigen::Vector3d(1, 0, 0), 1e-12));
}

}  // namespace

TEST_CASE("classification: the beam cut over a jittered beam", "[classification]") {
  auto mesh = xfem::box_mesh({6, 12, 38}, {0, 0, 0}, {0.03, 0.06, 0.2});
  // Move interior nodes by up to 0.2 cells (seeded): no grid planes remain; cells stay positive.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  const Eigen::Vector3d h(0.005, 0.005, 0.2 / 38);
  for (int i = 0; i < mesh.points.rows(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double x = mesh.points(i, k), hi = k == 0 ? 0.03 : k == 1 ? 0.06 : 0.2;
      if (x > 1e-12 && x < hi - 1e-12) mesh.points(i, k) += u(rng) * h[k];
    }
  for (int t = 0; t < mesh.tets.rows(); ++t) REQUIRE(xfem::signed_volume(mesh, t) > 0);
  check_beam_cut(mesh);
}

TEST_CASE("classification: the beam cut over an unstructured beam", "[classification]") {
  check_beam_cut(xfem::unstructured_box_mesh({0, 0, 0}, {0.03, 0.06, 0.2}, 0.007));
}

TEST_CASE("classification: degenerate geometry follows rules D1-D4", "[classification]") {
  SECTION("a cut that misses the body: everything uncut, N = NP") {
    const auto mesh = xfem::box_mesh({2, 2, 2}, {0, 0, 0}, {1, 1, 1});
    const auto c = xfem::classify(mesh, xfem::CutSurface(rectangle(-1, 2, -1, 2, 1.5)));
    CHECK(c.counts.uncut == mesh.tets.rows());
    CHECK(c.counts.none == mesh.points.rows());
    CHECK(c.front.empty());
    CHECK(xfem::dof_numbering(mesh.tets, mesh.points.rows(), ints(c.enrichment), ints(c.cut_class)).n ==
          mesh.points.rows());
  }
  SECTION("nodes exactly on the cut (a grid plane): D1, D2, D3") {
    // z = 0.5 is a grid plane of 2x2x2 cubes; the cut covers it all.
    const auto mesh = xfem::box_mesh({2, 2, 2}, {0, 0, 0}, {1, 1, 1});
    const auto c = xfem::classify(mesh, xfem::CutSurface(rectangle(-1, 2, -1, 2, 0.5)));
    CHECK(c.counts.points_on_cut == 9);
    CHECK(c.counts.partial == 0);
    for (int i = 0; i < mesh.points.rows(); ++i) {
      const double z = mesh.points(i, 2);
      CHECK(c.side[i] == (z >= 0.5 ? 1 : -1));  // D1: on the cut is +1
      // D3: only the nodes on the cut carry a (non-vanishing) sign enrichment.
      CHECK(c.enrichment[i] == (z == 0.5 ? Enrichment::Sign : Enrichment::None));
    }
    for (int t = 0; t < mesh.tets.rows(); ++t) {
      double zmax = 0;
      for (int i = 0; i < 4; ++i) zmax = std::max(zmax, mesh.points(mesh.tets(t, i), 2));
      // D2: the upper layer only touches the cut from its side: uncut; the lower one is cut.
      CHECK(c.cut_class[t] == (zmax > 0.5 ? CutClass::Uncut : CutClass::Complete));
    }
    // Nodes below the plane have no support above it: nothing to enrich, nothing tiny removed.
    CHECK(c.counts.sign_tiny == 0);
  }
  SECTION("a cut through the whole body: no partial tets, no front") {
    const auto mesh = xfem::box_mesh({2, 2, 3}, {0, 0, 0}, {1, 1, 1});
    const auto c = xfem::classify(mesh, xfem::CutSurface(rectangle(-1, 2, -1, 2, 0.5)));
    CHECK(c.counts.partial == 0);
    CHECK(c.counts.branch == 0);
    CHECK(c.front.empty());
    CHECK(c.counts.complete > 0);
  }
  SECTION("a front lying exactly on interior faces, and on the body's surface (D4)") {
    const auto mesh = xfem::box_mesh({2, 1, 3}, {0, 0, 0}, {2, 1, 1});
    // Front x = 1: the grid plane between the two columns of cubes.
    const auto c = xfem::classify(mesh, xfem::CutSurface(rectangle(-1, 1, -1, 2, 0.5)));
    CHECK_THAT(front_length(c.front), Catch::WithinAbs(1.0, 1e-12));
    // Front x = 2 on the body's surface: the cut goes through the whole body.
    const auto d = xfem::classify(mesh, xfem::CutSurface(rectangle(-1, 2, -1, 2, 0.5)));
    CHECK(d.front.empty());
    CHECK(d.counts.partial == 0);
  }
  SECTION("disconnected cut pieces give separate fronts") {
    const auto mesh = xfem::box_mesh({4, 1, 3}, {0, 0, 0}, {4, 1, 1});
    xfem::TriangleMesh two = rectangle(-1, 1.5, -1, 2, 0.5);
    const xfem::TriangleMesh right = rectangle(2.5, 5, -1, 2, 0.5);
    two.points.conservativeResize(8, 3);
    two.points.bottomRows(4) = right.points;
    two.triangles.conservativeResize(4, 3);
    two.triangles.bottomRows(2) = right.triangles.array() + 4;
    const auto c = xfem::classify(mesh, xfem::CutSurface(two));
    REQUIRE(c.front.segments().size() == 2);
    // Each front points away from its own piece: +x at x = 1.5, -x at x = 2.5.
    CHECK(c.front.frame({1.6, 0.5, 0.5}).R.col(0).isApprox(Eigen::Vector3d(1, 0, 0)));
    CHECK(c.front.frame({2.4, 0.5, 0.5}).R.col(0).isApprox(Eigen::Vector3d(-1, 0, 0)));
    for (int t = 0; t < mesh.tets.rows(); ++t) {
      if (c.cut_class[t] != CutClass::Partial) continue;
      double xmin = 9, xmax = -9;
      for (int i = 0; i < 4; ++i)
        xmin = std::min(xmin, mesh.points(mesh.tets(t, i), 0)), xmax = std::max(xmax, mesh.points(mesh.tets(t, i), 0));
      CHECK(((xmin < 1.5 && xmax > 1.5) || (xmin < 2.5 && xmax > 2.5)));
    }
    CHECK(c.counts.branch > 0);  // both fronts lie in Kuhn faces (u = w): they touch tets
  }
}

TEST_CASE("classification: radius enrichment branch-enriches nodes near the front", "[classification]") {
  const auto mesh = xfem::box_mesh({3, 6, 19}, {0, 0, 0}, {0.03, 0.06, 0.2});
  const xfem::CutSurface cut(beam_cut());
  const auto plain = xfem::classify(mesh, cut);
  xfem::ClassifyOptions o;
  o.tip_radius = 0.02;
  const auto wide = xfem::classify(mesh, cut, o);
  CHECK(wide.counts.branch > plain.counts.branch);
  CHECK(wide.counts.radius_branch == wide.counts.branch - plain.counts.branch);
  for (int i = 0; i < mesh.points.rows(); ++i) {
    const double r = std::hypot(mesh.points(i, 0) - 0.015, mesh.points(i, 2) - 0.1);
    if (r <= 0.02 - 1e-12) CHECK(wide.enrichment[i] == Enrichment::Branch);
    if (plain.enrichment[i] == Enrichment::Branch) CHECK(wide.enrichment[i] == Enrichment::Branch);
  }
}

TEST_CASE("classification: a cut lying in a surface face with its boundary on the surface separates nothing",
          "[classification]") {
  // Edges in the face z = 0 touch the cut, but the front pieces all lie on the surface (D4) and the
  // cut separates no volume: no tet is partially cut, nothing is enriched.
  const auto mesh = single_tet({1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  const auto c = xfem::classify(mesh, xfem::CutSurface(rectangle(0.2, 0.3, -1, 0.1, 0.0)));
  CHECK(c.counts.partial == 0);
  CHECK(c.counts.sign + c.counts.branch == 0);
}

TEST_CASE("classification: a folded cut through the body is completely cut, with no front", "[classification]") {
  // A zig-zag sheet z = 0.5 +- 0.15 with folds across the width (y), reaching outside the box on all
  // sides: the paper's face count calls tets at a fold partially cut; geometry says they are cut through.
  const auto mesh = xfem::box_mesh({5, 2, 4}, {0, 0, 0}, {1, 0.4, 1});
  xfem::TriangleMesh zz;
  const double xs[] = {-0.2, 0.13, 0.41, 0.77, 1.2};
  const double zs[] = {0.5, 0.65, 0.37, 0.62, 0.45};
  zz.points.resize(10, 3);
  for (int i = 0; i < 5; ++i) {
    zz.points.row(2 * i) << xs[i], -0.2, zs[i];
    zz.points.row(2 * i + 1) << xs[i], 0.6, zs[i];
  }
  zz.triangles.resize(8, 3);
  for (int i = 0; i < 4; ++i) {
    zz.triangles.row(2 * i) << 2 * i, 2 * i + 2, 2 * i + 3;
    zz.triangles.row(2 * i + 1) << 2 * i, 2 * i + 3, 2 * i + 1;
  }
  const auto c = xfem::classify(mesh, xfem::CutSurface(zz));
  CHECK(c.front.empty());
  CHECK(c.counts.partial == 0);
  CHECK(c.counts.branch == 0);
  CHECK(c.counts.complete > 0);
  auto g = [&](double x) {
    for (int i = 0; i < 4; ++i)
      if (x <= xs[i + 1]) return zs[i] + (x - xs[i]) / (xs[i + 1] - xs[i]) * (zs[i + 1] - zs[i]);
    return zs[4];
  };
  for (int i = 0; i < mesh.points.rows(); ++i)
    CHECK(c.side[i] == (mesh.points(i, 2) >= g(mesh.points(i, 0)) ? 1 : -1));
}

TEST_CASE("classification: without a cut everything is uncut and plain", "[classification]") {
  const auto mesh = xfem::box_mesh({2, 1, 1}, {0, 0, 0}, {2, 1, 1});
  const auto c = xfem::classify_without_cut(mesh);
  CHECK(c.counts.uncut == 12);
  CHECK(c.counts.none == 12);
  CHECK(c.counts.edges == 20 + 11 + 2);  // grid edges, one diagonal per square face, one per cube
  CHECK(c.side == std::vector<int>(12, 1));
  CHECK(c.front.empty());
}

namespace {

// The incremental classification `a` equals the one from scratch `b`: every array, the counts and
// the front.
void check_same(const xfem::Classification& a, const xfem::Classification& b) {
  CHECK(a.side == b.side);
  CHECK(a.on_cut == b.on_cut);
  CHECK(a.enrichment == b.enrichment);
  CHECK(a.cut_class == b.cut_class);
  CHECK(a.cut_edges == b.cut_edges);
  CHECK(a.cut_faces == b.cut_faces);
  CHECK(xfem::count_values(a.counts) == xfem::count_values(b.counts));
  REQUIRE(a.front.segments().size() == b.front.segments().size());
  for (std::size_t i = 0; i < a.front.segments().size(); ++i) {
    CHECK(a.front.segments()[i].p0 == b.front.segments()[i].p0);
    CHECK(a.front.segments()[i].p1 == b.front.segments()[i].p1);
    CHECK(a.front.segments()[i].b == b.front.segments()[i].b);
  }
}

}  // namespace

TEST_CASE("classification: a growing cut classified incrementally equals classify at every step",
          "[classification][progressive_cut]") {
  // Blades moving through a box: along y at x = 0.43 (between nodes), at x = 0.5 (through a plane of
  // nodes: points on the cut, rules D1/D2), tilted along an arc with radius enrichment; steps in
  // order (incremental), then back and out of order (from scratch), then on again in order.
  const xfem::TetMesh mesh = xfem::box_mesh({8, 8, 4}, {0, 0, 0}, {1, 1, 0.5});
  struct Sweep {
    const char* name;
    xfem::BladePath path;
    double tilt;
    double tip_radius = 0;
  };
  std::vector<Sweep> sweeps(3);
  sweeps[0] = {"x = 0.43", {}, 0.0};
  sweeps[0].path.polyline = {{0.43, -0.05, 0.6}, {0.43, 0.95, 0.6}};
  sweeps[1] = {"x = 0.5, through nodes", {}, 0.0};
  sweeps[1].path.polyline = {{0.5, -0.05, 0.625}, {0.5, 0.5, 0.625}, {0.5, 0.95, 0.625}};
  sweeps[2] = {"arc, tilted, radius enrichment", {}, 20.0, 0.25};
  sweeps[2].path.centre = {0.5, -0.3, 0.6};
  sweeps[2].path.radius = 0.8;
  sweeps[2].path.a0 = 60;
  sweeps[2].path.a1 = 120;
  for (const Sweep& s : sweeps) {
    INFO(s.name);
    const xfem::TriangleMesh sweep = xfem::cut_sweep(s.path, 0.3, {0, 0, -1}, s.tilt, 0.06, 1.0);
    const std::vector<double> times = xfem::cut_times(sweep, "sweep");
    const std::vector<double> t = xfem::step_times(times, 8);
    xfem::ClassifyOptions options;
    options.tip_radius = s.tip_radius;
    xfem::GrowingCutClassifier growing(mesh, options);
    long incremental = 0, tested = 0, edges = 0;
    for (int k : {0, 1, 2, 3, 4, 5, 6, 7, 3, 1, 2, 6, 7}) {
      INFO("step " << k + 1);
      const xfem::CutSurface cut(xfem::cut_until(sweep, times, t[k]));
      const xfem::Classification a = growing.classify(cut, xfem::cut_until_ids(times, t[k]));
      const xfem::Classification b = xfem::classify(mesh, cut, options);
      check_same(a, b);
      CHECK(b.counts.partial + b.counts.complete > 0);
      if (s.tip_radius > 0) CHECK(b.counts.radius_branch > 0);
      incremental += growing.stats().incremental;
      tested += growing.stats().tets;
      edges += growing.stats().edges;
    }
    // Steps 2-8, and 3, 7, 8 after the jumps back, grew the previous cut: incremental; steps 1, 4
    // and 2 (after 8 and 4) from scratch.
    CHECK(incremental == 10);
    // The point of it: far fewer edges tested than the 13 classifications' whole meshes.
    CHECK(edges < 13 * static_cast<long>(mesh.tets.rows()));
    CHECK(tested > 0);
  }
}

TEST_CASE("classification: an organ's growing cut classified incrementally equals classify at every step, judging "
          "the sides of only the points the new triangles come near",
          "[classification][progressive_cut]") {
  // pipelines/sweep's blade (an arc over the top, 0.05 m deep) through a coarse organ, every step:
  // the classifier keeps each point's distance to the cut and judges its side anew only where a
  // new triangle comes as close (issue 35).
  const xfem::TetMesh mesh = xfem::implicit_mesh(xfem::organ_function, xfem::organ_bounding_radius, 0.012);
  const xfem::TriangleMesh sweep = sweep_blade();
  const std::vector<double> times = xfem::cut_times(sweep, "sweep");
  const std::vector<double> t = xfem::step_times(times, 12);
  xfem::GrowingCutClassifier growing(mesh);
  long incremental = 0, judged_late = 0, late = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    INFO("step " << k + 1);
    const std::vector<int> ids = xfem::cut_until_ids(times, t[k]);
    if (ids.empty()) continue;
    const xfem::CutSurface cut(xfem::cut_until(sweep, times, t[k]));
    const xfem::Classification a = growing.classify(cut, ids);
    const xfem::Classification b = xfem::classify(mesh, cut);
    check_same(a, b);
    incremental += growing.stats().incremental;
    if (k + 4 >= t.size()) {  // the last steps: the blade's front far from most of the body
      judged_late += growing.stats().sides;
      late += 1;
    }
  }
  CHECK(incremental >= 10);
  CHECK(judged_late < late * mesh.points.rows() / 2);
}

TEST_CASE("classification: a growing cut's classifier refuses ids that do not match the triangles",
          "[classification]") {
  const xfem::TetMesh mesh = xfem::box_mesh({2, 2, 2}, {0, 0, 0}, {1, 1, 1});
  const xfem::CutSurface cut(rectangle(-0.1, 0.5, -0.1, 1.1, 0.45));
  xfem::GrowingCutClassifier growing(mesh);
  CHECK_THROWS_WITH(growing.classify(cut, {0}), Catch::Contains("1 triangle ids for 2 triangles"));
  CHECK_THROWS_WITH(growing.classify(cut, {3, 3}), Catch::Contains("triangle id 3 given twice"));
  // A triangle id that names other corners than before: classified from scratch, still right.
  CHECK(growing.classify(cut, {0, 1}).cut_class == xfem::classify(mesh, cut).cut_class);
  const xfem::CutSurface moved(rectangle(-0.1, 0.5, -0.1, 1.1, 0.55));
  CHECK(growing.classify(moved, {0, 1}).cut_class == xfem::classify(mesh, moved).cut_class);
  CHECK_FALSE(growing.stats().incremental);
}

TEST_CASE("classification: the side volumes of the cut tets, split in threads, are each tet's own and do not depend "
          "on the thread count",
          "[classification][threads]") {
  // A coarse organ and a curved cut (pipelines/sweep's arc, 0.05 m deep): a few hundred cut tets,
  // split in chunks of 4 over the threads (issue 35). Each tet's volumes must be those split_by_cut
  // gives that very tet (a wrong index would move them), and everything the same at 1 and 3 threads.
  const xfem::TetMesh mesh = xfem::implicit_mesh(xfem::organ_function, xfem::organ_bounding_radius, 0.012);
  const xfem::CutSurface cut(sweep_blade());
  std::vector<xfem::Classification> c;
  std::vector<xfem::ClassificationMemory> memory(2);
  for (int i = 0; i < 2; ++i) {
    xfem::set_thread_limit(i == 0 ? 1 : 3);
    xfem::ClassifyWork work;
    c.push_back(xfem::classify_with(mesh, cut, {}, memory[i], nullptr, work));
    CHECK(work.tets > 50);  // enough split tets for many chunks
  }
  INFO("split tets " << std::count(memory[1].split.begin(), memory[1].split.end(), 1));
  xfem::set_thread_limit(0);
  check_same(c[0], c[1]);
  CHECK(memory[0].above == memory[1].above);
  CHECK(memory[0].below == memory[1].below);
  CHECK(memory[0].split == memory[1].split);
  long split = 0;
  for (long t = 0; t < mesh.tets.rows(); ++t) {
    if (!memory[1].split[t]) continue;
    ++split;
    const xfem::CutPieces pieces = xfem::split_by_cut(xfem::tet_corners(mesh, static_cast<int>(t)), cut);
    CHECK(memory[1].above[t] == pieces.volume_above);
    CHECK(memory[1].below[t] == pieces.volume_below);
  }
  // Every completely cut tet was split (a tet the front runs through is not).
  CHECK(c[1].counts.complete > 50);
  CHECK(split >= c[1].counts.complete);
}
