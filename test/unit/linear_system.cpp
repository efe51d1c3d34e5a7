// SPDX-License-Identifier: MIT
#include "xfem/linear_system.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "xfem/error.h"

namespace {

namespace fs = std::filesystem;

std::string scratch_dir(const std::string& name) {
  const auto dir = fs::temp_directory_path() / "xfem_unit" / name;
  fs::remove_all(dir);
  return dir.string();
}

// Two 3-vectors (N = 2, NP = 1, NS = 1): a small SPD matrix with a few off-diagonal entries.
xfem::LinearSystem small_system() {
  xfem::LinearSystem s;
  s.np = 1;
  s.ns = 1;
  s.n = 2;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < 6; ++i) t.emplace_back(i, i, 4.0 + i / 3.0);
  for (int i = 1; i < 6; ++i) {
    t.emplace_back(i, i - 1, -1.0 / 7.0);
    t.emplace_back(i - 1, i, -1.0 / 7.0);
  }
  s.K.resize(6, 6);
  s.K.setFromTriplets(t.begin(), t.end());
  s.f = Eigen::VectorXd::LinSpaced(6, -1.0, 1.0 / 3.0);
  s.fixed = {0, 2};
  s.fixed_values = {0.0, 0.02};
  s.pieces = {{12, true}, {3, false}};
  s.coordinates = Eigen::RowVector3d(0.1, 0.2, 1.0 / 3.0);
  return s;
}

void overwrite(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST_CASE("linear_system: a system round-trips exactly through its directory", "[linear_system]") {
  const auto dir = scratch_dir("system_roundtrip");
  const xfem::LinearSystem s = small_system();
  xfem::write_linear_system(s, dir, "test 0");
  for (const char* f : {"K.mtx", "f.mtx", "dirichlet.mtx", "coordinates.mtx", "system.json"})
    CHECK(fs::exists(fs::path(dir) / f));
  const xfem::LinearSystem r = xfem::read_linear_system(dir);
  CHECK(r.np == 1);
  CHECK(r.ns == 1);
  CHECK(r.nb == 0);
  CHECK(r.n == 2);
  // Shortest round-trip decimal form: every bit comes back, and K is the full symmetric matrix.
  CHECK((r.K - s.K).norm() == 0.0);
  CHECK(r.f == s.f);
  CHECK(r.fixed == s.fixed);
  CHECK(r.fixed_values == s.fixed_values);  // the DOF fixed to 0 is still listed
  REQUIRE(r.pieces.size() == 2);
  CHECK(r.pieces[1].tets == 3);
  CHECK_FALSE(r.pieces[1].constrained);
  CHECK(r.coordinates == s.coordinates);
}

TEST_CASE("linear_system: coordinates and pieces are optional", "[linear_system]") {
  const auto dir = scratch_dir("system_minimal");
  xfem::LinearSystem s = small_system();
  s.coordinates.resize(0, 0);
  s.pieces.clear();
  xfem::write_linear_system(s, dir, "test 0");
  CHECK_FALSE(fs::exists(fs::path(dir) / "coordinates.mtx"));
  const xfem::LinearSystem r = xfem::read_linear_system(dir);
  CHECK(r.coordinates.size() == 0);
  CHECK(r.pieces.empty());
}

TEST_CASE("linear_system: a missing directory or file is named", "[linear_system]") {
  using Catch::Matchers::Contains;
  const auto dir = scratch_dir("system_missing");
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("no such directory"));
  xfem::write_linear_system(small_system(), dir, "test 0");
  fs::remove(fs::path(dir) / "f.mtx");
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("f.mtx: cannot open for reading"));
  fs::remove(fs::path(dir) / "system.json");
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("system.json: cannot open for reading"));
}

TEST_CASE("linear_system: a size mismatch between the files is an error", "[linear_system]") {
  using Catch::Matchers::Contains;
  const auto dir = scratch_dir("system_mismatch");
  xfem::write_linear_system(small_system(), dir, "test 0");
  overwrite((fs::path(dir) / "f.mtx").string(), "%%MatrixMarket matrix array real general\n3 1\n1\n2\n3\n");
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("f.mtx: 3 rows, expected 3N = 6"));

  xfem::write_linear_system(small_system(), dir, "test 0");
  overwrite((fs::path(dir) / "K.mtx").string(), "%%MatrixMarket matrix coordinate real symmetric\n3 3 1\n1 1 1\n");
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("K.mtx: 3 x 3, expected 3N x 3N = 6 x 6"));

  xfem::write_linear_system(small_system(), dir, "test 0");
  overwrite((fs::path(dir) / "system.json").string(), R"({"np": 1, "ns": 1, "nb": 0, "n": 3})");
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("n = 3 but np + ns + 4 nb = 2"));
}

TEST_CASE("linear_system: a fixed DOF out of range is an error", "[linear_system]") {
  using Catch::Matchers::Contains;
  const auto dir = scratch_dir("system_fixed_range");
  xfem::LinearSystem s = small_system();
  s.fixed = {0, 6};
  CHECK_THROWS_WITH(xfem::write_linear_system(s, dir, "test 0"), Contains("fixed DOF 6 out of range 0..5"));
  s.fixed = {2, 2};
  CHECK_THROWS_WITH(xfem::write_linear_system(s, dir, "test 0"), Contains("fixed DOF 2 listed twice"));

  xfem::write_linear_system(small_system(), dir, "test 0");
  overwrite((fs::path(dir) / "dirichlet.mtx").string(),
            "%%MatrixMarket matrix coordinate real general\n6 1 1\n7 1 0.5\n");
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("dirichlet.mtx: line 3: index out of range"));
  overwrite((fs::path(dir) / "dirichlet.mtx").string(),
            "%%MatrixMarket matrix coordinate real general\n9 1 1\n7 1 0.5\n");
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("dirichlet.mtx: 9 x 1, expected 3N x 1 = 6 x 1"));
}
