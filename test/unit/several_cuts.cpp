// SPDX-License-Identifier: MIT
#include "xfem/enrich/classification_several_cuts.h"
#include "xfem/enrich/cut_files.h"
#include "xfem/enrich/dof_numbering.h"
#include "xfem/enrich/side_codes.h"
#include "xfem/integrate/cut_element_splits.h"
#include "xfem/system/pieces.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <map>

#include "xfem/generate/box_mesh.h"
#include "xfem/generate/cut_generation.h"
#include "xfem/core/error.h"
#include "xfem/core/thread_limit.h"
#include "xfem/io/vtk_io.h"

namespace {

using Catch::Matchers::Contains;
using V3 = Eigen::Vector3d;

// A plane through the box as a parallelogram reaching 1 beyond it: corner, edge1, edge2.
xfem::TriangleMesh plane(const V3& corner, const V3& e1, const V3& e2) {
  return xfem::cut_parallelogram(corner, corner + e1, corner + e2, Eigen::Vector2i(1, 1));
}

// Classifies, numbers, writes and reads back (the file contract of xfem-classify -> xfem-enrich ->
// later stages), in a scratch folder named `tag`.
xfem::EnrichedMesh enriched(xfem::TetMesh mesh, const std::vector<xfem::TriangleMesh>& cuts, const std::string& tag,
                            xfem::CutsClassification* out = nullptr) {
  std::vector<xfem::CutSurface> surfaces;
  for (const auto& c : cuts) surfaces.emplace_back(c);
  std::vector<const xfem::CutSurface*> pointers;
  for (const auto& s : surfaces) pointers.push_back(&s);
  const xfem::CutsClassification c = xfem::classify_cuts(mesh, pointers);
  if (out) *out = c;
  xfem::store_cuts_classification(c, mesh);
  xfem::store_cut_fingerprints(cuts, mesh);
  xfem::number_several_cuts(mesh, "classified.vtu");
  const auto dir = std::filesystem::temp_directory_path() / ("xfem_several_cuts_" + tag);
  std::filesystem::create_directories(dir);
  const std::string vtu = (dir / "enriched.vtu").string();
  xfem::write_tet_mesh(mesh, vtu);
  std::vector<std::string> paths;
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    paths.push_back((dir / ("cut" + std::to_string(k) + ".vtp")).string());
    xfem::write_triangle_mesh(cuts[k], paths.back());
  }
  return xfem::read_enriched_mesh_cuts(vtu, paths);
}

// Volume per side code of the pieces of every cut tet.
std::map<int, double> volume_per_code(const xfem::CutElementSplits& s) {
  std::map<int, double> v;
  for (std::size_t q = 0; q < s.tets.size(); ++q)
    v[s.side[q]] += std::abs(xfem::signed_volume(s.tets[q][0], s.tets[q][1], s.tets[q][2], s.tets[q][3]));
  return v;
}

}  // namespace

TEST_CASE("several cuts: side codes pack the sides of every cut", "[several_cuts]") {
  const int sides[3] = {1, -1, 1};
  const int code = xfem::pack_sides(sides, 3);
  CHECK(code == 2 + 1 + 4);
  for (int k = 0; k < 3; ++k) CHECK(xfem::code_side(code, k) == sides[k]);
  const int below[2] = {-1, -1};
  CHECK(xfem::pack_sides(below, 2) == 2);  // never 0 (= decide by the cuts) nor +-1
}

TEST_CASE("several cuts: two parallel cuts get one sign enrichment each, numbered cut after cut", "[several_cuts]") {
  // 2 x 2 x 3 cubes over [0,1]^2 x [0,3]; cut 0 at z = 0.5 (normal +z), cut 1 at z = 2.5 (normal -z).
  const xfem::TetMesh mesh = xfem::box_mesh({2, 2, 3}, V3::Zero(), V3(1, 1, 3));
  xfem::CutsClassification c;
  const xfem::EnrichedMesh em = enriched(mesh, {plane(V3(-1, -1, 0.5), V3(3, 0, 0), V3(0, 3, 0)),
                                                plane(V3(-1, -1, 2.5), V3(0, 3, 0), V3(3, 0, 0))},
                                         "parallel", &c);
  REQUIRE(em.cuts.size() == 2);
  CHECK(c.products.empty());
  CHECK(c.ends_on == std::vector<int>{-1, -1});
  // Every node of the cut layers straddles its cut: 18 sign nodes per cut (z = 0, 1 and 2, 3).
  CHECK(em.cuts[0].ns == 18);
  CHECK(em.cuts[1].ns == 18);
  CHECK(em.np == 36);
  CHECK(em.ns == 36);
  CHECK(em.nb == 0);
  CHECK(em.n == 72);
  CHECK(em.cuts[0].sign_first == 36);
  CHECK(em.cuts[1].sign_first == 54);
  CHECK(em.cuts[0].side[0] == -1);   // z = 0: below cut 0
  CHECK(em.cuts[1].side[0] == 1);    // and on cut 1's normal side (-z)
  // The enriched DOFs of a tet of the bottom layer are cut 0's only, increasing.
  const long o = em.offsets[0];
  for (long e = o + 4; e < em.offsets[1]; ++e) {
    CHECK(em.dofs[e] >= 36);
    CHECK(em.dofs[e] < 54);
    if (e > o + 4) CHECK(em.dofs[e] > em.dofs[e - 1]);
  }
  // Three pieces, each region's volume exact: slab z < 0.5, 0.5 < z < 2.5, z > 2.5.
  const auto v = volume_per_code(xfem::split_cut_elements(em));
  REQUIRE(v.size() == 3);
  const int lo[2] = {-1, 1}, mid[2] = {1, 1}, hi[2] = {1, -1};  // cut 1's normal is -z
  CHECK(v.at(xfem::pack_sides(lo, 2)) == Approx(0.5).epsilon(1e-14));
  CHECK(v.at(xfem::pack_sides(mid, 2)) == Approx(1.0).epsilon(1e-14));  // the two halves inside the cut layers
  CHECK(v.at(xfem::pack_sides(hi, 2)) == Approx(0.5).epsilon(1e-14));
  std::vector<char> bottom(em.mesh.points.rows(), 0);
  for (Eigen::Index p = 0; p < em.mesh.points.rows(); ++p) bottom[p] = em.mesh.points(p, 2) == 0.0;
  const auto pieces = xfem::find_pieces(em, bottom);
  REQUIRE(pieces.size() == 3);
  int held = 0;
  for (const auto& p : pieces) held += p.constrained;
  CHECK(held == 1);  // the bottom slab only
}

TEST_CASE("several cuts: crossing cuts get the junction enrichment H_0 H_1 around the crossing", "[several_cuts]") {
  // One layer of 2 x 2 cubes over [0,1]^2 x [0,0.5]; cut 0 at x = 0.6, cut 1 at y = 0.4: four pieces.
  const xfem::TetMesh mesh = xfem::box_mesh({2, 2, 1}, V3::Zero(), V3(1, 1, 0.5));
  xfem::CutsClassification c;
  const xfem::EnrichedMesh em = enriched(mesh, {plane(V3(0.6, -1, -1), V3(0, 3, 0), V3(0, 0, 3)),
                                                plane(V3(-1, 0.4, -1), V3(0, 0, 3), V3(3, 0, 0))},
                                         "crossing", &c);
  REQUIRE(c.products.size() == 1);
  CHECK(c.products[0].a == 0);
  CHECK(c.products[0].b == 1);
  // Every node's support here reaches the crossing (the cube (0.5..1) x (0..0.5) holds it and every
  // node is a node of a tet around it) except the corners far from it.
  CHECK(c.products[0].count >= 4);
  REQUIRE(em.products.size() == 1);
  CHECK(em.products[0].first == em.np + em.cuts[0].ns + em.cuts[1].ns);
  CHECK(em.ns == em.cuts[0].ns + em.cuts[1].ns + em.products[0].count);
  // The regions inside the three cubes the cuts meet (x 0.5..1 / y 0..0.5, x 0.5..1 / y 0.5..1,
  // x 0..0.5 / y 0..0.5), 0.5 high: exact volumes.
  const auto v = volume_per_code(xfem::split_cut_elements(em));
  REQUIRE(v.size() == 4);
  const int a[2] = {-1, -1}, b[2] = {1, -1}, cc[2] = {-1, 1}, d[2] = {1, 1};
  CHECK(v.at(xfem::pack_sides(a, 2)) == Approx((0.1 * 0.4 + 0.5 * 0.4) * 0.5).epsilon(1e-13));
  CHECK(v.at(xfem::pack_sides(b, 2)) == Approx(0.4 * 0.4 * 0.5).epsilon(1e-13));
  CHECK(v.at(xfem::pack_sides(cc, 2)) == Approx((0.1 * 0.1 + 0.1 * 0.5 + 0.5 * 0.1) * 0.5).epsilon(1e-13));
  CHECK(v.at(xfem::pack_sides(d, 2)) == Approx((0.4 * 0.1 + 0.4 * 0.5) * 0.5).epsilon(1e-13));
  // The product function at a point of each region, for a node with the product enrichment.
  int node = -1;
  for (int p = 0; p < em.mesh.points.rows() && node < 0; ++p)
    if (c.products[0].node[p]) node = p;
  REQUIRE(node >= 0);
  const int s[2] = {em.cuts[0].side[node], em.cuts[1].side[node]};
  const int own = xfem::cut_function(em, 0, s) * xfem::cut_function(em, 1, s);
  for (const int* r : {a, b, cc, d})
    CHECK(0.5 * (xfem::cut_function(em, 0, r) * xfem::cut_function(em, 1, r) - own) == (r[0] * r[1] == own ? 0.0 : -own));
}

TEST_CASE("several cuts: a cut ending on another is a T-junction, no front there, its Heaviside restricted",
          "[several_cuts]") {
  // [0,1]^2 x [0,2], 2 x 2 x 4 cubes. Cut 0: z = 0.95 through the body (normal +z). Cut 1: x = 0.45
  // from z = 0.95 up and out of the body (normal +x): it ends on cut 0, above it.
  const xfem::TetMesh mesh = xfem::box_mesh({2, 2, 4}, V3::Zero(), V3(1, 1, 2));
  xfem::CutsClassification c;
  const xfem::EnrichedMesh em = enriched(mesh, {plane(V3(-1, -1, 0.95), V3(3, 0, 0), V3(0, 3, 0)),
                                                plane(V3(0.45, -1, 0.95), V3(0, 3, 0), V3(0, 0, 3))},
                                         "junction", &c);
  CHECK(c.ends_on == std::vector<int>{-1, 0});
  CHECK(c.ends_side == std::vector<int>{0, 1});
  CHECK(em.cuts[1].ends_on == 0);
  CHECK(em.cuts[1].front.empty());
  CHECK(c.cuts[1].counts.branch == 0);
  CHECK(c.cuts[1].counts.partial == 0);
  CHECK(c.products.empty());
  // g_1: H_1 above cut 0, 0 below.
  const int above_left[2] = {1, -1}, below_right[2] = {-1, 1};
  CHECK(xfem::cut_function(em, 1, above_left) == -1);
  CHECK(xfem::cut_function(em, 1, below_right) == 0);
  // Three pieces: below cut 0, and above it on either side of cut 1.
  std::vector<char> none(em.mesh.points.rows(), 0);
  const auto pieces = xfem::find_pieces(em, none);
  REQUIRE(pieces.size() == 3);
  // The nodes at z = 0.5, x = 1: their supports reach above cut 0 only right of cut 1, where g_1 is
  // +1 everywhere, and below it, where g_1 is 0: g_1 = (H_0 + 1) / 2 there, dependent on H_0: not
  // enriched (K would be singular).
  for (Eigen::Index p = 0; p < em.mesh.points.rows(); ++p)
    if (em.mesh.points(p, 2) == 0.5 && em.mesh.points(p, 0) == 1.0) {
      CHECK(c.cuts[0].enrichment[p] == xfem::Enrichment::Sign);
      CHECK(c.cuts[1].enrichment[p] == xfem::Enrichment::None);
    }
}

TEST_CASE("several cuts: configurations not handled are refused, naming them", "[several_cuts]") {
  const xfem::TetMesh box = xfem::box_mesh({4, 4, 4}, V3::Zero(), V3(1, 1, 1));
  auto classify = [&](const std::vector<xfem::TriangleMesh>& cuts) {
    std::vector<xfem::CutSurface> s;
    for (const auto& c : cuts) s.emplace_back(c);
    std::vector<const xfem::CutSurface*> p;
    for (const auto& x : s) p.push_back(&x);
    return xfem::classify_cuts(box, p);
  };
  SECTION("three cuts in one tet") {
    REQUIRE_THROWS_WITH(classify({plane(V3(-1, -1, 0.55), V3(3, 0, 0), V3(0, 3, 0)),
                                  plane(V3(-1, -1, 0.56), V3(3, 0, 0), V3(0, 3, 0)),
                                  plane(V3(-1, -1, 0.57), V3(3, 0, 0), V3(0, 3, 0))}),
                        Contains("meets cuts 0, 1 and 2: three cuts in one tet are not handled"));
  }
  SECTION("a front inside a tet another cut meets") {
    REQUIRE_THROWS_WITH(classify({xfem::cut_disc(V3(0.5, 0.5, 0.47), V3(0, 0, 1), 0.3, 4),
                                  plane(V3(0.61, -1, -1), V3(0, 3, 0), V3(0, 0, 3))}),
                        Contains("the front of cut 0 runs through it and cut 1 meets it"));
  }
  SECTION("two cuts ending on each other") {
    // A V: both half-planes end on the line x = 0.45, z = 0.45.
    REQUIRE_THROWS_WITH(classify({plane(V3(0.45, -1, 0.45), V3(0, 3, 0), V3(-1, 0, 1)),
                                  plane(V3(0.45, -1, 0.45), V3(0, 3, 0), V3(1, 0, 1))}),
                        Contains("cuts 0 and 1 end on each other (a V-shaped junction)"));
  }
  SECTION("a cut ending on another and also reaching its other side") {
    // Cut 1: a piece ending on cut 0 (z = 0.55) from above, and a piece crossing it at x = 0.2.
    const xfem::TriangleMesh ends = plane(V3(0.7, -1, 0.55), V3(0, 3, 0), V3(0, 0, 3));
    const xfem::TriangleMesh crosses = plane(V3(0.2, -1, 0.1), V3(0, 3, 0), V3(0, 0, 3));
    REQUIRE_THROWS_WITH(classify({plane(V3(-1, -1, 0.55), V3(3, 0, 0), V3(0, 3, 0)), xfem::merge_surfaces({ends, crosses})}),
                        Contains("cut 1 ends on cut 0 and also reaches its other side"));
  }
  SECTION("the fronts of two cuts in one tet") {
    REQUIRE_THROWS_WITH(classify({xfem::cut_disc(V3(0.5, 0.5, 0.47), V3(0, 0, 1), 0.3, 4),
                                  xfem::cut_disc(V3(0.5, 0.5, 0.55), V3(0, 0, 1), 0.3, 4)}),
                        Contains("has branch-enriched nodes of cuts 0 and 1"));
  }
}

TEST_CASE("several cuts: the cut tets split in threads give the same classification at any thread count",
          "[several_cuts][threads]") {
  // Two slanted planes crossing in an 8 x 8 x 8 box (hundreds of cut tets, split in chunks of 4
  // over the threads, their volumes then added in tet order): the same at 1 and 3 threads.
  const xfem::TetMesh mesh = xfem::box_mesh({8, 8, 8}, V3::Zero(), V3(1, 1, 1));
  const xfem::CutSurface c0(plane(V3(0.43, -0.5, -0.5), V3(0.2, 2, 0), V3(0, 0, 2)));
  const xfem::CutSurface c1(plane(V3(-0.5, 0.55, -0.5), V3(0, 0, 2), V3(2, -0.3, 0)));
  std::vector<xfem::CutsClassification> c;
  for (int n : {1, 3}) {
    xfem::set_thread_limit(n);
    c.push_back(xfem::classify_cuts(mesh, {&c0, &c1}));
  }
  xfem::set_thread_limit(0);
  REQUIRE(c[0].products.size() == 1);
  REQUIRE(c[1].products.size() == 1);
  CHECK(c[0].products[0].count > 0);
  CHECK(c[0].products[0].node == c[1].products[0].node);
  CHECK(c[0].product_tiny == c[1].product_tiny);
  for (int k = 0; k < 2; ++k) {
    CHECK(c[0].cuts[k].counts.complete > 50);
    CHECK(c[0].cuts[k].enrichment == c[1].cuts[k].enrichment);
    CHECK(c[0].cuts[k].cut_class == c[1].cuts[k].cut_class);
    CHECK(xfem::count_values(c[0].cuts[k].counts) == xfem::count_values(c[1].cuts[k].counts));
  }
}
