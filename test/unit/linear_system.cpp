// SPDX-License-Identifier: MIT
#include "xfem/system/linear_system.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "xfem/core/error.h"
#include "xfem/io/petsc_binary.h"

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

TEST_CASE("linear_system: a system round-trips exactly through its directory, in both formats", "[linear_system]") {
  const auto dir = scratch_dir("system_roundtrip");
  const xfem::LinearSystem s = small_system();
  const bool binary = GENERATE(true, false);
  const std::string ext = binary ? ".petsc" : ".mtx";
  xfem::write_linear_system(s, dir, "test 0", binary ? xfem::SystemFormat::Petsc : xfem::SystemFormat::MatrixMarket);
  for (const std::string f : {"K" + ext, "f" + ext, std::string("dirichlet.mtx"), "coordinates" + ext,
                              std::string("system.json")})
    CHECK(fs::exists(fs::path(dir) / f));
  CHECK(xfem::system_format(dir) == (binary ? xfem::SystemFormat::Petsc : xfem::SystemFormat::MatrixMarket));
  const xfem::LinearSystem r = xfem::read_linear_system(dir);
  CHECK(r.np == 1);
  CHECK(r.ns == 1);
  CHECK(r.nb == 0);
  CHECK(r.n == 2);
  // Binary or the shortest round-trip decimal form: every bit comes back, K as the full symmetric matrix.
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
  CHECK_FALSE(fs::exists(fs::path(dir) / "coordinates.petsc"));
  CHECK_FALSE(fs::exists(fs::path(dir) / "coordinates.mtx"));
  const xfem::LinearSystem r = xfem::read_linear_system(dir);
  CHECK(r.coordinates.size() == 0);
  CHECK(r.pieces.empty());
}

TEST_CASE("linear_system: a missing directory or file is named", "[linear_system]") {
  using Catch::Matchers::Contains;
  const auto dir = scratch_dir("system_missing");
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("no such directory"));
  xfem::write_linear_system(small_system(), dir, "test 0", xfem::SystemFormat::MatrixMarket);
  fs::remove(fs::path(dir) / "f.mtx");
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("f.mtx: cannot open for reading"));
  xfem::write_linear_system(small_system(), dir, "test 0");
  fs::remove(fs::path(dir) / "K.petsc");
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("K.petsc: cannot open for reading"));
  CHECK_THROWS_WITH(xfem::read_linear_system(dir, false), Contains("K.petsc: cannot open for reading"));
  fs::remove(fs::path(dir) / "system.json");
  CHECK_THROWS_WITH(xfem::read_linear_system(dir),
                    Contains(dir + ": no system.json") && Contains("the directory is incomplete"));
}

TEST_CASE("linear_system: a size mismatch between the files is an error", "[linear_system]") {
  using Catch::Matchers::Contains;
  const auto dir = scratch_dir("system_mismatch");
  const auto mtx = xfem::SystemFormat::MatrixMarket;
  xfem::write_linear_system(small_system(), dir, "test 0", mtx);
  overwrite((fs::path(dir) / "f.mtx").string(), "%%MatrixMarket matrix array real general\n3 1\n1\n2\n3\n");
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("f.mtx: 3 rows, expected 3N = 6"));

  xfem::write_linear_system(small_system(), dir, "test 0", mtx);
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

TEST_CASE("linear_system: a binary K that is not symmetric is refused", "[linear_system]") {
  using Catch::Matchers::Contains;
  const auto dir = scratch_dir("system_asymmetric");
  xfem::write_linear_system(small_system(), dir, "test 0");
  const std::string path = (fs::path(dir) / "K.petsc").string();
  const long nnz = xfem::read_petsc_matrix_header(path).nonzeros;
  // Change the last (least significant) byte of row 0's second value, K(0,1); K(1,0) stays.
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  f.seekp(16 + 4 * 6 + 4 * nnz + 8 * 1 + 7);
  f.put(static_cast<char>(0x01));
  f.close();
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("K.petsc: K is not symmetric"));
}

TEST_CASE("linear_system: the directory appears whole or not at all", "[linear_system]") {
  using Catch::Matchers::Contains;
  const auto dir = scratch_dir("system_atomic");
  const fs::path parent = fs::path(dir).parent_path();
  const auto leftovers = [&] {
    int n = 0;
    for (const auto& e : fs::directory_iterator(parent))
      n += e.path().filename().string().rfind(".system_atomic", 0) == 0;
    return n;
  };
  // A write that fails (a non-finite value in K) leaves no directory and no temporary one.
  xfem::LinearSystem bad = small_system();
  bad.K.coeffRef(3, 3) = std::nan("");
  CHECK_THROWS_WITH(xfem::write_linear_system(bad, dir, "test 0"), Contains("non-finite"));
  CHECK_FALSE(fs::exists(dir));
  CHECK(leftovers() == 0);

  // Over an existing system: a failed write leaves the old one as it was ...
  xfem::write_linear_system(small_system(), dir, "test 0", xfem::SystemFormat::MatrixMarket);
  CHECK_THROWS(xfem::write_linear_system(bad, dir, "test 0"));
  CHECK(fs::exists(fs::path(dir) / "K.mtx"));
  CHECK((xfem::read_linear_system(dir).K - small_system().K).norm() == 0.0);  // small_system's K has both triangles
  CHECK(leftovers() == 0);
  // ... a successful one replaces it whole (no stale K.mtx next to K.petsc).
  xfem::write_linear_system(small_system(), dir, "test 0");
  CHECK(fs::exists(fs::path(dir) / "K.petsc"));
  CHECK_FALSE(fs::exists(fs::path(dir) / "K.mtx"));
  CHECK(leftovers() == 0);

  // An interrupted write (simulated: a temporary directory without system.json left behind) does
  // not disturb the system, and a directory without the marker is refused.
  fs::create_directory(parent / ".system_atomic.tmp1");
  CHECK_NOTHROW(xfem::read_linear_system(dir));
  CHECK_THROWS_WITH(xfem::read_linear_system((parent / ".system_atomic.tmp1").string()), Contains("no system.json"));
  fs::remove_all(parent / ".system_atomic.tmp1");

  // A directory holding something else is not replaced.
  const auto other = scratch_dir("not_a_system");
  fs::create_directories(other);
  overwrite((fs::path(other) / "notes.txt").string(), "mine\n");
  CHECK_THROWS_WITH(xfem::write_linear_system(small_system(), other, "test 0"),
                    Contains("holds notes.txt, which is not part of a system directory"));
  CHECK(fs::exists(fs::path(other) / "notes.txt"));
  // A trailing slash names the same directory.
  xfem::write_linear_system(small_system(), dir + "/", "test 0");
  CHECK(fs::exists(fs::path(dir) / "system.json"));
}

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// What xfem-assemble adds to a system: files written into the temporary directory by write_more.
void write_extras(const std::string& tmp) {
  overwrite((fs::path(tmp) / "provenance.json").string(), "{\"fingerprints\": {}}\n");
  overwrite((fs::path(tmp) / "dirichlet_conditions.json").string(), "{\"conditions\": []}\n");
}

}  // namespace

TEST_CASE("linear_system: system.json's manifest ties the files of the directory together", "[linear_system]") {
  using Catch::Matchers::Contains;
  const auto dir = scratch_dir("system_manifest");
  const auto mtx = xfem::SystemFormat::MatrixMarket;
  const auto file = [&](const char* name) { return (fs::path(dir) / name).string(); };

  // The extra files written by write_more are in the directory and in the manifest.
  xfem::write_linear_system(small_system(), dir, "test 0", mtx, write_extras);
  const xfem::Json manifest = xfem::read_json(file("system.json")).at("files");
  for (const char* name : {"K.mtx", "f.mtx", "dirichlet.mtx", "coordinates.mtx", "provenance.json",
                           "dirichlet_conditions.json"}) {
    INFO(name);
    REQUIRE(manifest.contains(name));
    CHECK(manifest[name]["bytes"].get<long>() == static_cast<long>(fs::file_size(file(name))));
  }
  CHECK(manifest.size() == 6);
  CHECK_NOTHROW(xfem::read_linear_system(dir));

  // A prescribed value truncated (0.02 -> 0.0) still parses: the manifest catches it.
  std::string text = read_text(file("dirichlet.mtx"));
  REQUIRE(text.find("0.02\n") != std::string::npos);
  text.replace(text.find("0.02\n"), 5, "0.0\n");
  overwrite(file("dirichlet.mtx"), text);
  CHECK_THROWS_WITH(xfem::read_linear_system(dir),
                    Contains("dirichlet.mtx: ") && Contains("bytes, but system.json's manifest says") &&
                        Contains("assemble again"));

  // A K of the same size from another assembly (twice as stiff): same bytes count, other content.
  const auto other = scratch_dir("system_manifest_other");
  xfem::LinearSystem stiffer = small_system();
  stiffer.K *= 2.0;
  xfem::write_linear_system(small_system(), dir, "test 0", xfem::SystemFormat::Petsc, write_extras);
  xfem::write_linear_system(stiffer, other, "test 0", xfem::SystemFormat::Petsc, write_extras);
  REQUIRE(fs::file_size(file("K.petsc")) == fs::file_size(fs::path(other) / "K.petsc"));
  fs::copy_file(fs::path(other) / "K.petsc", file("K.petsc"), fs::copy_options::overwrite_existing);
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("K.petsc: content differs from system.json's manifest"));
  // The PETSc backend's read (without K) checks it too.
  CHECK_THROWS_WITH(xfem::read_linear_system(dir, false), Contains("K.petsc: content differs"));

  // A listed file missing (a kill before provenance.json was written, as xfem-assemble once could).
  xfem::write_linear_system(small_system(), dir, "test 0", mtx, write_extras);
  fs::remove(file("provenance.json"));
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("provenance.json: missing, but listed in system.json's manifest"));
  // A system file not listed (written after the system, or copied in from another).
  xfem::write_linear_system(small_system(), dir, "test 0", mtx);
  write_extras(dir);
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("dirichlet_conditions.json: not in system.json's manifest"));

  // The manifest tampered with: a changed hash, a malformed entry, none at all (an older system).
  xfem::write_linear_system(small_system(), dir, "test 0", mtx, write_extras);
  xfem::Json j = xfem::read_json(file("system.json"));
  const xfem::Json original = j;
  j["files"]["f.mtx"]["content"] = "fnv1a64:0123456789abcdef";
  xfem::write_json(j, file("system.json"));
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("f.mtx: content differs from system.json's manifest"));
  j = original;
  j["files"]["f.mtx"]["bytes"] = "many";
  xfem::write_json(j, file("system.json"));
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("system.json: manifest entry 'f.mtx' is not"));
  j = original;
  j["files"]["../elsewhere"] = original["files"]["f.mtx"];
  xfem::write_json(j, file("system.json"));
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("system.json: manifest entry '../elsewhere' is not"));
  j = original;
  j.erase("files");
  xfem::write_json(j, file("system.json"));
  CHECK_THROWS_WITH(xfem::read_linear_system(dir), Contains("system.json: no manifest of the system's files") &&
                                                       Contains("assemble again"));
  // Restored, it reads again: the checks above refused the changes, not the directory.
  xfem::write_json(original, file("system.json"));
  CHECK_NOTHROW(xfem::read_linear_system(dir));
}
