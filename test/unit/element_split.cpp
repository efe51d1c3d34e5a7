// SPDX-License-Identifier: MIT
#include "xfem/geometry/element_split.h"

#include <catch2/catch.hpp>
#include <map>
#include <set>

#include "xfem/generate/box_mesh.h"
#include "xfem/enrich/classification.h"
#include "xfem/generate/cut_generation.h"
#include "xfem/geometry/cut_surface.h"
#include "xfem/core/error.h"
#include "mesh_checks.h"

namespace {

// The plane z = zc for x <= xf, as two triangles reaching past the unit box on three sides (the
// beam cut of DESIGN.md, scaled), with its front x = xf.
struct PlaneCut {
  double zc, xf;
  xfem::TriangleMesh surface() const {
    xfem::TriangleMesh m;
    m.points.resize(4, 3);
    m.points << -1, -1, zc, xf, -1, zc, xf, 2, zc, -1, 2, zc;
    m.triangles.resize(2, 3);
    m.triangles << 0, 1, 2, 0, 2, 3;
    return m;
  }
  std::vector<xfem::FrontSegment> front() const {
    if (xf > 1) return {};
    return {{Eigen::Vector3d(xf, 2, zc), Eigen::Vector3d(xf, -1, zc), Eigen::Vector3d(0, 0, 1)}};
  }
  int side(const Eigen::Vector3d& x) const { return x[2] >= zc ? 1 : -1; }
  bool cuts(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    if ((a[2] - zc) * (b[2] - zc) > 0) return false;
    const double t = (zc - a[2]) / (b[2] - a[2]);
    return a[0] + t * (b[0] - a[0]) <= xf;
  }
};

// Sides and classes as xfem-classify decides them (DESIGN.md 3.3), by hand for a plane.
void classify(const xfem::TetMesh& m, const PlaneCut& cut, std::vector<int>& side, std::vector<int>& cut_class) {
  side.resize(m.points.rows());
  for (Eigen::Index k = 0; k < m.points.rows(); ++k) side[k] = cut.side(m.points.row(k).transpose());
  cut_class.assign(m.tets.rows(), 0);
  for (int t = 0; t < m.tets.rows(); ++t) {
    bool cut_edge[4][4] = {};
    int n_cut = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (cut.cuts(m.points.row(m.tets(t, i)).transpose(), m.points.row(m.tets(t, j)).transpose())) {
          cut_edge[i][j] = cut_edge[j][i] = true;
          ++n_cut;
        }
    int complete_faces = 0;
    for (int skip = 0; skip < 4; ++skip) {
      int c = 0;
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
          if (i != skip && j != skip && cut_edge[i][j]) ++c;
      if (c >= 2) ++complete_faces;
    }
    cut_class[t] = n_cut == 0 ? 0 : complete_faces >= 3 ? 2 : 1;
  }
}

Eigen::Vector3d point(const xfem::SplitMesh& s, int id) { return s.points.row(id).transpose(); }

double tet_volume(const xfem::SplitMesh& s, int t) {
  return xfem::signed_volume(point(s, s.tets(t, 0)), point(s, s.tets(t, 1)), point(s, s.tets(t, 2)),
                             point(s, s.tets(t, 3)));
}

double triangle_area(const xfem::SplitMesh& s, const std::array<int, 3>& f) {
  return 0.5 * (point(s, f[1]) - point(s, f[0])).cross(point(s, f[2]) - point(s, f[0])).norm();
}

// Checks that the split mesh of the unit box has no crack or overlap away from the cut: every tet
// positive, every face shared by two tets except faces on the box's boundary and the wound's
// triangles (each of which bounds exactly one tet). Returns the wound's area per side.
std::map<int, double> check_conforming(const xfem::SplitMesh& s) {
  for (int t = 0; t < s.tets.rows(); ++t) CHECK(tet_volume(s, t) > 0);
  auto faces = xfem_test::face_counts(s.tets);
  std::set<std::array<int, 3>> wound;
  std::map<int, double> wound_area;
  for (int w = 0; w < s.wound.rows(); ++w) {
    std::array<int, 3> f = {s.wound(w, 0), s.wound(w, 1), s.wound(w, 2)};
    wound_area[s.wound_side[w]] += triangle_area(s, f);
    std::sort(f.begin(), f.end());
    CHECK(wound.insert(f).second);
    CHECK(faces[f] == 1);
  }
  double boundary_area = 0;
  for (const auto& [f, count] : faces) {
    CAPTURE(f[0], f[1], f[2]);
    REQUIRE(count <= 2);
    if (count == 2 || wound.count(f)) continue;
    bool on_boundary = false;
    for (int c = 0; c < 3; ++c)
      for (double plane : {0.0, 1.0})
        // Front points on the boundary are computed, so they lie on it to rounding only.
        if (std::abs(point(s, f[0])[c] - plane) < 1e-15 && std::abs(point(s, f[1])[c] - plane) < 1e-15 &&
            std::abs(point(s, f[2])[c] - plane) < 1e-15)
          on_boundary = true;
    CHECK(on_boundary);
    boundary_area += triangle_area(s, f);
  }
  CHECK_THAT(boundary_area, Catch::WithinRel(6.0, 1e-12));
  return wound_area;
}

}  // namespace

TEST_CASE("element_split: one tet cut across its top gives the hand-computed pieces", "[element_split]") {
  xfem::TetMesh m;
  m.points.resize(4, 3);
  m.points << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  m.tets.resize(1, 4);
  m.tets << 0, 1, 2, 3;
  const PlaneCut cut{0.25, 5.0};
  const auto s = xfem::split_mesh(m, {-1, -1, -1, 1}, {2}, cut.surface(), cut.front());
  // 4 nodes, 3 edge points and the centre, each of these twice; the bottom face stays whole, the
  // three side faces split into a triangle and a quad: 1 + 3 * 3 cone tets.
  CHECK(s.points.rows() == 4 + 2 * 3 + 2);
  CHECK(s.tets.rows() == 10);
  CHECK(s.split_complete == 1);
  CHECK(s.split_partial == 0);
  double above = 0, total = 0;
  for (int t = 0; t < s.tets.rows(); ++t) {
    const double v = tet_volume(s, t);
    CHECK(v > 0);
    total += v;
    if (s.tet_side[t] > 0) above += v;
  }
  // The piece above is the corner tet scaled by 0.75: volume 0.75^3 / 6.
  CHECK_THAT(total, Catch::WithinRel(1.0 / 6, 1e-14));
  CHECK_THAT(above, Catch::WithinRel(0.421875 / 6, 1e-14));
  // The wound: the section triangle (legs 0.75) on each side, 3 fan triangles each.
  REQUIRE(s.wound.rows() == 6);
  std::map<int, double> area;
  for (int w = 0; w < 6; ++w) {
    area[s.wound_side[w]] += triangle_area(s, {s.wound(w, 0), s.wound(w, 1), s.wound(w, 2)});
    // Out of its own piece: the upper face's normal points down, the lower face's up.
    const Eigen::Vector3d n = (point(s, s.wound(w, 1)) - point(s, s.wound(w, 0)))
                                  .cross(point(s, s.wound(w, 2)) - point(s, s.wound(w, 0)));
    CHECK(n[2] * s.wound_side[w] < 0);
    for (int c = 0; c < 3; ++c) {
      CHECK(s.point_side[s.wound(w, c)] == s.wound_side[w]);
      CHECK_THAT(point(s, s.wound(w, c))[2], Catch::WithinAbs(0.25, 1e-15));
    }
  }
  CHECK_THAT(area[1], Catch::WithinRel(0.5 * 0.75 * 0.75, 1e-14));
  CHECK_THAT(area[-1], Catch::WithinRel(0.5 * 0.75 * 0.75, 1e-14));
}

TEST_CASE("element_split: a box cut through completely splits into conforming pieces of the right volume",
          "[element_split]") {
  const auto m = xfem::box_mesh({3, 4, 5}, {0, 0, 0}, {1, 1, 1});
  const PlaneCut cut{0.43, 5.0};
  std::vector<int> side, cut_class;
  classify(m, cut, side, cut_class);
  const auto s = xfem::split_mesh(m, side, cut_class, cut.surface(), cut.front());
  CHECK(s.split_partial == 0);
  CHECK(s.split_complete == std::count_if(cut_class.begin(), cut_class.end(), [](int c) { return c > 0; }));
  CHECK(s.degenerate_faces == 0);
  // Volumes: the whole box, and the part above the cut, to rounding (1e-12 relative).
  double total = 0, above = 0;
  for (int t = 0; t < s.tets.rows(); ++t) {
    const double v = tet_volume(s, t);
    total += v;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) c += point(s, s.tets(t, k)) / 4;
    if (s.tet_side[t] != 0) CHECK(s.tet_side[t] == (c[2] > cut.zc ? 1 : -1));
    if (c[2] > cut.zc) above += v;
  }
  CHECK_THAT(total, Catch::WithinRel(1.0, 1e-12));
  CHECK_THAT(above, Catch::WithinRel(1.0 - cut.zc, 1e-12));
  // Conforming away from the cut; the wound covers the body's section once per side.
  const auto area = check_conforming(s);
  CHECK_THAT(area.at(1), Catch::WithinRel(1.0, 1e-12));
  CHECK_THAT(area.at(-1), Catch::WithinRel(1.0, 1e-12));
  // The original nodes keep their ids and positions.
  for (int k = 0; k < m.points.rows(); ++k) CHECK(point(s, k) == Eigen::Vector3d(m.points.row(k)));
}

TEST_CASE("element_split: a partial cut opens only behind its front", "[element_split]") {
  const auto m = xfem::box_mesh({4, 4, 5}, {0, 0, 0}, {1, 1, 1});
  const PlaneCut cut{0.43, 0.55};
  std::vector<int> side, cut_class;
  classify(m, cut, side, cut_class);
  const auto s = xfem::split_mesh(m, side, cut_class, cut.surface(), cut.front());
  CHECK(s.split_partial > 0);
  CHECK(s.split_complete > 0);
  CHECK(s.degenerate_faces == 0);
  double total = 0;
  for (int t = 0; t < s.tets.rows(); ++t) total += tet_volume(s, t);
  CHECK_THAT(total, Catch::WithinRel(1.0, 1e-12));
  // The wound is exactly the cut inside the body, x in [0, 0.55], y in [0, 1], once per side.
  std::map<int, double> area;
  for (int w = 0; w < s.wound.rows(); ++w)
    area[s.wound_side[w]] += triangle_area(s, {s.wound(w, 0), s.wound(w, 1), s.wound(w, 2)});
  CHECK_THAT(area.at(1), Catch::WithinRel(cut.xf, 1e-12));
  CHECK_THAT(area.at(-1), Catch::WithinRel(cut.xf, 1e-12));
  // Partially cut elements are split into their exact pieces (cut_pieces.h, split_at_front): those
  // behind the front lie on their side of the cut, those ahead of it (side 0) on either side of
  // the cut's plane extended, and the front x = 0.55 is an edge of the pieces, never crossed.
  for (int t = 0; t < s.tets.rows(); ++t) {
    CAPTURE(t);
    CHECK(tet_volume(s, t) > 0);
    double zlo = 1, zhi = 0;
    for (int c = 0; c < 4; ++c) {
      zlo = std::min(zlo, point(s, s.tets(t, c))[2] - cut.zc);
      zhi = std::max(zhi, point(s, s.tets(t, c))[2] - cut.zc);
    }
    if (cut_class[s.parent[t]] == 1) CHECK((zlo >= -1e-15 || zhi <= 1e-15));  // no piece straddles the cut's plane
    if (s.tet_side[t] > 0) CHECK(zlo >= -1e-15);
    if (s.tet_side[t] < 0) CHECK(zhi <= 1e-15);
    // A face of a piece of a partially cut element on the cut's plane lies behind the front or
    // ahead of it, never across. (This test classifies by the paper's face rule, which also calls
    // some elements the front passes through completely cut: those are split by the cut only.)
    double behind = 0, ahead = 0;  // how far the piece's corners on the plane reach to either side
    int on_plane = 0;
    for (int c = 0; c < 4; ++c) {
      const Eigen::Vector3d x = point(s, s.tets(t, c));
      if (std::abs(x[2] - cut.zc) > 1e-15) continue;
      ++on_plane;
      behind = std::max(behind, cut.xf - x[0]);
      ahead = std::max(ahead, x[0] - cut.xf);
    }
    if (cut_class[s.parent[t]] == 1 && on_plane == 3) CHECK(std::min(behind, ahead) <= 1e-15);
  }
  // Points of partially cut elements on the cut behind the front are duplicated, one per side.
  std::map<std::array<double, 3>, std::set<int>> sides_at;
  for (int k = static_cast<int>(m.points.rows()); k < s.points.rows(); ++k)
    if (cut_class[s.point_tet[k]] == 1 && std::abs(point(s, k)[2] - cut.zc) < 1e-15 && point(s, k)[0] < cut.xf - 1e-12)
      sides_at[{point(s, k)[0], point(s, k)[1], point(s, k)[2]}].insert(s.point_side[k]);
  CHECK(!sides_at.empty());
  for (const auto& [x, sides] : sides_at) {
    CAPTURE(x[0], x[1], x[2]);
    CHECK(sides == std::set<int>{-1, 1});
  }
}

TEST_CASE("element_split: uncut elements are kept whole", "[element_split]") {
  const auto m = xfem::box_mesh({2, 2, 2}, {0, 0, 0}, {1, 1, 1});
  const PlaneCut cut{0.3, 5.0};
  std::vector<int> side(m.points.rows(), 1), cut_class(m.tets.rows(), 0);
  for (Eigen::Index k = 0; k < m.points.rows(); ++k) side[k] = cut.side(m.points.row(k).transpose());
  const auto s = xfem::split_mesh(m, side, cut_class, cut.surface(), cut.front());
  CHECK(s.tets == m.tets);
  CHECK(s.points.rows() == m.points.rows());
  CHECK(s.wound.rows() == 0);
  for (int t = 0; t < s.tets.rows(); ++t) CHECK(s.tet_side[t] == 0);
}

TEST_CASE("element_split: sides and classes that do not fit the mesh are errors", "[element_split]") {
  const auto m = xfem::box_mesh({1, 1, 1}, {0, 0, 0}, {1, 1, 1});
  const PlaneCut cut{0.3, 5.0};
  std::vector<int> side(m.points.rows(), 1), cut_class(m.tets.rows(), 0);
  using Catch::Matchers::Contains;
  CHECK_THROWS_WITH(xfem::split_mesh(m, std::vector<int>(3, 1), cut_class, cut.surface(), {}),
                    Contains("3 point sides for 8 points"));
  CHECK_THROWS_WITH(xfem::split_mesh(m, side, std::vector<int>(2, 0), cut.surface(), {}),
                    Contains("2 cut classes for 6 tets"));
  side[5] = 0;
  CHECK_THROWS_WITH(xfem::split_mesh(m, side, cut_class, cut.surface(), {}), Contains("point 5 has side 0"));
  side[5] = 1;
  cut_class[4] = 3;
  CHECK_THROWS_WITH(xfem::split_mesh(m, side, cut_class, cut.surface(), {}), Contains("tet 4 has cut class 3"));
}

namespace {

// Sides, classes and front of `m` against `cut` as xfem-classify decides them.
struct Classified {
  std::vector<int> side, cut_class;
  std::vector<xfem::FrontSegment> front;
};
Classified classified(const xfem::TetMesh& m, const xfem::CutSurface& cut) {
  const xfem::Classification c = xfem::classify(m, cut);
  Classified out{c.side, {}, c.front.segments()};
  for (const xfem::CutClass k : c.cut_class) out.cut_class.push_back(static_cast<int>(k));
  return out;
}

// Checks that split_mesh splits every cut tet of `m` as it splits that tet alone: split_mesh works
// on the cut tets in parallel (parallel_for.h) and numbers their points afterwards, in tet order;
// a tet alone is split on one thread. Compared: each output tet's corners (positions, and sides
// of the points), side and parent, in order, and the wound. Also: the overload given the
// CutSurface gives the same result.
void check_split_as_alone(const xfem::TetMesh& m, const xfem::CutSurface& cut, int min_partial) {
  const Classified c = classified(m, cut);
  const auto s = xfem::split_mesh(m, c.side, c.cut_class, cut.mesh(), c.front);
  const auto given = xfem::split_mesh(m, c.side, c.cut_class, cut, c.front);
  CHECK(given.points == s.points);
  CHECK(given.point_side == s.point_side);
  CHECK(given.point_tet == s.point_tet);
  CHECK(given.tets == s.tets);
  CHECK(given.parent == s.parent);
  CHECK(given.tet_side == s.tet_side);
  CHECK(given.wound == s.wound);
  CHECK(given.wound_side == s.wound_side);
  // Enough cut tets for several chunks of work on several threads.
  CHECK(s.split_complete > 100);
  CHECK(s.split_partial >= min_partial);

  int next_tet = 0, next_wound = 0, cut_tets = 0;
  std::vector<int> first_user(s.points.rows(), -1);  // per point: the first tet whose pieces or wound use it
  for (int t = 0; t < m.tets.rows(); ++t) {
    CAPTURE(t);
    // The tet alone, its nodes numbered in the order of their numbers in m (quads on faces are
    // split along the diagonal from their lowest-numbered node).
    xfem::TetMesh one;
    one.points.resize(4, 3);
    one.tets.resize(1, 4);
    std::vector<int> side(4);
    for (int k = 0; k < 4; ++k) {
      int rank = 0;
      for (int l = 0; l < 4; ++l) rank += m.tets(t, l) < m.tets(t, k);
      one.points.row(rank) = m.points.row(m.tets(t, k));
      one.tets(0, k) = rank;
      side[rank] = c.side[m.tets(t, k)];
    }
    const auto a = xfem::split_mesh(one, side, {c.cut_class[t]}, cut, c.front);
    if (c.cut_class[t] > 0) ++cut_tets;
    for (int i = 0; i < a.tets.rows(); ++i, ++next_tet) {
      REQUIRE(next_tet < s.tets.rows());
      CHECK(s.parent[next_tet] == t);
      CHECK(s.tet_side[next_tet] == a.tet_side[i]);
      for (int k = 0; k < 4; ++k) {
        CHECK(point(s, s.tets(next_tet, k)) == point(a, a.tets(i, k)));
        CHECK(s.point_side[s.tets(next_tet, k)] == a.point_side[a.tets(i, k)]);
        if (first_user[s.tets(next_tet, k)] < 0) first_user[s.tets(next_tet, k)] = t;
      }
    }
    for (int w = 0; w < a.wound.rows(); ++w, ++next_wound) {
      REQUIRE(next_wound < s.wound.rows());
      CHECK(s.wound_side[next_wound] == a.wound_side[w]);
      for (int k = 0; k < 3; ++k) {
        CHECK(point(s, s.wound(next_wound, k)) == point(a, a.wound(w, k)));
        if (first_user[s.wound(next_wound, k)] < 0) first_user[s.wound(next_wound, k)] = t;
      }
    }
  }
  // A new point's field is evaluated in the first tet that uses it (the one that made it).
  for (int k = static_cast<int>(m.points.rows()); k < s.points.rows(); ++k)
    if (first_user[k] >= 0) CHECK(s.point_tet[k] == first_user[k]);
  CHECK(next_tet == s.tets.rows());
  CHECK(next_wound == s.wound.rows());
  CHECK(cut_tets == s.split_complete + s.split_partial);
}

}  // namespace

TEST_CASE("element_split: a folded cut splits each element as it splits it alone, in parallel or given the CutSurface",
          "[element_split]") {
  // Five folds through a box of 6^3 cubes: elements with a fold inside (exact pieces) and elements
  // crossed by one flat strip (split face by face), the cut reaching past the box on every side.
  const auto m = xfem::box_mesh({6, 6, 6}, {0, 0, 0}, {1, 1, 1});
  const xfem::CutSurface cut(xfem::cut_zigzag({-0.2, -0.2}, {1.2, 1.2}, 0.47, 0.1, 5, 3));
  check_split_as_alone(m, cut, 0);
}

TEST_CASE("element_split: a partial curved cut splits each element as it splits it alone, in parallel or given the "
          "CutSurface", "[element_split]") {
  // A sinusoidal sheet whose front x = 0.63 runs through the box: elements split behind the front.
  const auto m = xfem::box_mesh({6, 6, 6}, {0, 0, 0}, {1, 1, 1});
  const xfem::CutSurface cut(xfem::cut_sine({-0.2, -0.2}, {0.63, 1.2}, 0.47, 0.05, 0.4, {16, 6}));
  check_split_as_alone(m, cut, 10);
}
