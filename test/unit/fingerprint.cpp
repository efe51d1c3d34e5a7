// SPDX-License-Identifier: MIT
#include "xfem/core/fingerprint.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "xfem/core/error.h"
#include "xfem/io/matrix_market.h"
#include "xfem/post/solution_provenance_check.h"

namespace {
std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "xfem_unit_fingerprint";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

xfem::TriangleMesh triangle(double z) {
  xfem::TriangleMesh m;
  m.points.resize(3, 3);
  m.points << 0, 0, z, 1, 0, z, 0, 1, z;
  m.triangles.resize(1, 3);
  m.triangles << 0, 1, 2;
  return m;
}
}  // namespace

TEST_CASE("fingerprint: FNV-1a 64 matches the published test vectors", "[fingerprint]") {
  CHECK(xfem::fnv1a64("", 0) == 0xcbf29ce484222325ULL);
  CHECK(xfem::fnv1a64("a", 1) == 0xaf63dc4c8601ec8cULL);
  CHECK(xfem::fnv1a64("foobar", 6) == 0x85944171f73967e8ULL);
}

TEST_CASE("fingerprint: text form round-trips; malformed text is refused", "[fingerprint]") {
  const xfem::Fingerprint f = 0x0123456789abcdefULL;
  CHECK(xfem::to_string(f) == "fnv1a64:0123456789abcdef");
  xfem::Fingerprint back = 0;
  REQUIRE(xfem::parse_fingerprint(xfem::to_string(f), &back));
  CHECK(back == f);
  CHECK_FALSE(xfem::parse_fingerprint("fnv1a64:0123456789abcdeg", &back));
  CHECK_FALSE(xfem::parse_fingerprint("fnv1a64:0123", &back));
  CHECK_FALSE(xfem::parse_fingerprint("sha1:0123456789abcdef", &back));
}

TEST_CASE("fingerprint: a VTK field array keeps all 64 bits", "[fingerprint]") {
  xfem::DataArrays field;
  const xfem::Fingerprint f = 0xfedcba9876543210ULL;  // above 2^53: two 32-bit halves
  xfem::store_fingerprint(field, "cut_fingerprint", f);
  xfem::Fingerprint back = 0;
  REQUIRE(xfem::stored_fingerprint(field, "cut_fingerprint", &back));
  CHECK(back == f);
  CHECK_FALSE(xfem::stored_fingerprint(field, "other", &back));
}

TEST_CASE("fingerprint: the geometry decides, arrays do not", "[fingerprint]") {
  xfem::TriangleMesh a = triangle(0.1), b = triangle(0.1), c = triangle(0.1 + 1e-15);
  b.cell_data["area"] = xfem::make_array(xfem::DataArray::Type::Float64, 1, 1, 0.5);
  CHECK(xfem::fingerprint(a) == xfem::fingerprint(b));
  CHECK(xfem::fingerprint(a) != xfem::fingerprint(c));
  b.triangles << 0, 2, 1;  // the same points, the other orientation
  CHECK(xfem::fingerprint(a) != xfem::fingerprint(b));
}

TEST_CASE("fingerprint: a mesh classified with one cut refuses another, naming both files", "[fingerprint]") {
  xfem::TetMesh mesh;
  xfem::store_fingerprint(mesh.field_data, "cut_fingerprint", xfem::fingerprint(triangle(0.1)));
  CHECK_NOTHROW(xfem::check_cut_matches(mesh, "enriched.vtu", triangle(0.1), "cut.vtp"));
  CHECK_THROWS_WITH(xfem::check_cut_matches(mesh, "enriched.vtu", triangle(0.2), "other.vtp"),
                    Catch::StartsWith("other.vtp: not the cut enriched.vtu was classified with (cut fnv1a64:"));
  // A mesh written before fingerprints existed: nothing to check.
  CHECK_NOTHROW(xfem::check_cut_matches(xfem::TetMesh{}, "old.vtu", triangle(0.2), "other.vtp"));
}

TEST_CASE("fingerprint: JSON content, not its spelling", "[fingerprint]") {
  CHECK(xfem::fingerprint(xfem::Json::parse("{\"E\": 300e3, \"nu\": 0.35}")) ==
        xfem::fingerprint(xfem::Json::parse("{ \"E\":300000.0,\n \"nu\":0.35 }")));
  CHECK(xfem::fingerprint(xfem::Json::parse("{\"E\": 300e3}")) != xfem::fingerprint(xfem::Json::parse("{\"E\": 400e3}")));
}

TEST_CASE("fingerprint: a solution records its provenance in Matrix Market comments", "[fingerprint]") {
  const xfem::Provenance p{{"enriched", 1}, {"problem", 0xffffffffffffffffULL}};
  const std::string path = scratch("u.mtx");
  xfem::write_vector(Eigen::Vector3d(1, 2, 3), path, xfem::provenance_comments(p));
  CHECK(xfem::read_vector(path) == Eigen::Vector3d(1, 2, 3));
  CHECK(xfem::read_mtx_provenance(path) == p);
  CHECK(xfem::provenance_from_json(xfem::Json{{"fingerprints", xfem::provenance_json(p)}}, "p.json") == p);
  CHECK_NOTHROW(xfem::check_provenance(p, "u.mtx", "enriched", 1, "enriched.vtu"));
  CHECK_NOTHROW(xfem::check_provenance(p, "u.mtx", "cut", 7, "cut.vtp"));  // not recorded: not checked
  CHECK_THROWS_WITH(xfem::check_provenance(p, "u.mtx", "enriched", 2, "other.vtu"),
                    Catch::StartsWith("u.mtx: does not belong to other.vtu (made for the enriched"));
  std::ofstream(path) << "%%MatrixMarket matrix array real general\n% xfem-fingerprint enriched 12\n1 1\n0\n";
  CHECK_THROWS_WITH(xfem::read_mtx_provenance(path), Catch::Contains("malformed fingerprint line"));
}

TEST_CASE("fingerprint: conflicting or malformed fingerprint lines are refused, naming the file", "[fingerprint]") {
  const std::string path = scratch("lines.mtx");
  const auto header = [&](const std::string& lines) {
    std::ofstream(path) << "%%MatrixMarket matrix array real general\n" << lines << "1 1\n0\n";
  };
  header("% xfem-fingerprint cut fnv1a64:0000000000000001\n% xfem-fingerprint cut fnv1a64:0000000000000002\n");
  CHECK_THROWS_WITH(xfem::read_mtx_provenance(path),
                    Catch::StartsWith(path + ": conflicting fingerprint lines for 'cut' (fnv1a64:0000000000000001 and "
                                             "fnv1a64:0000000000000002)"));
  header("% xfem-fingerprint cut fnv1a64:0000000000000001\n% xfem-fingerprint cut fnv1a64:0000000000000001\n");
  CHECK(xfem::read_mtx_provenance(path) == xfem::Provenance{{"cut", 1}});  // the same value twice: no conflict
  header("% xfem-fingerprint  fnv1a64:0000000000000001\n");  // no name
  CHECK_THROWS_WITH(xfem::read_mtx_provenance(path), Catch::StartsWith(path + ": malformed fingerprint line"));
  header("% xfem-fingerprint cut fnv1a64:\x01\xff" "00000000000000\n");  // raw bytes are not echoed
  CHECK_THROWS_WITH(xfem::read_mtx_provenance(path), Catch::Contains("fnv1a64:??00000000000000'"));
}

TEST_CASE("fingerprint: a solution belongs to the mesh, cuts and problem it is read with", "[fingerprint]") {
  xfem::TetMesh mesh;  // only its geometry's fingerprint is checked: an empty mesh has one too
  const xfem::TriangleMesh cut = triangle(0.5), other = triangle(0.25);
  const std::string problem = scratch("problem.json"), u = scratch("u_prov.mtx");
  std::ofstream(problem) << "{\"E\": 1}";
  const xfem::Provenance made_for{{"enriched", xfem::fingerprint(mesh)},
                                  {"cut", xfem::fingerprint(cut)},
                                  {"problem", xfem::fingerprint_json_file(problem)}};
  xfem::write_vector(Eigen::Vector3d(1, 2, 3), u, xfem::provenance_comments(made_for));
  const xfem::SolutionFiles files{u, "enriched.vtu", {"cut.vtp"}, problem};
  CHECK_NOTHROW(xfem::check_solution_provenance(files, mesh, {&cut}));
  CHECK_THROWS_WITH(xfem::check_solution_provenance(files, mesh, {&other}),
                    Catch::StartsWith(u + ": does not belong to cut.vtp (made for the cut"));
  // Solved with a cut, read without it: refused, unless only the standard DOFs are read.
  xfem::SolutionFiles plain{u, "classified.vtu"};
  CHECK_THROWS_WITH(xfem::check_solution_provenance(plain, mesh, {}),
                    Catch::StartsWith(u + ": solved with a cut (cut fnv1a64:") &&
                        Catch::EndsWith("but classified.vtu is given without it"));
  plain.standard_dofs_only = true;
  CHECK_NOTHROW(xfem::check_solution_provenance(plain, mesh, {}));
  // Another problem; no problem given (the reader does not use it): not checked.
  std::ofstream(scratch("other.json")) << "{\"E\": 2}";
  CHECK_THROWS_WITH(xfem::check_solution_provenance({u, "enriched.vtu", {"cut.vtp"}, scratch("other.json")}, mesh, {&cut}),
                    Catch::StartsWith(u + ": does not belong to " + scratch("other.json") + " (made for the problem"));
  CHECK_NOTHROW(xfem::check_solution_provenance({u, "enriched.vtu", {"cut.vtp"}}, mesh, {&cut}));
  // Solved without a cut (its record names the mesh only), given one: taken for a mesh classified
  // without a cut (no enriched DOFs), refused for a mesh classified with it.
  xfem::write_vector(Eigen::Vector3d(1, 2, 3), u, xfem::provenance_comments({{"enriched", xfem::fingerprint(mesh)}}));
  CHECK_NOTHROW(xfem::check_solution_provenance(files, mesh, {&cut}));
  xfem::store_fingerprint(mesh.field_data, "cut_fingerprint", xfem::fingerprint(cut));
  CHECK_THROWS_WITH(xfem::check_solution_provenance(files, mesh, {&cut}),
                    Catch::StartsWith(u + ": does not belong to cut.vtp (solved without a cut, but enriched.vtu was "
                                          "classified with cut.vtp)"));
  // Without fingerprints (another solver's u.mtx): nothing to check.
  xfem::write_vector(Eigen::Vector3d(1, 2, 3), u);
  CHECK_NOTHROW(xfem::check_solution_provenance(files, mesh, {&other}));
}
