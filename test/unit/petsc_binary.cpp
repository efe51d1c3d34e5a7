// SPDX-License-Identifier: MIT
#include "xfem/io/petsc_binary.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

#include "xfem/core/error.h"

namespace {

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

std::string scratch(const std::string& name) {
  const auto dir = fs::temp_directory_path() / "xfem_unit" / "petsc_binary";
  fs::create_directories(dir);
  return (dir / name).string();
}

// A 5 x 5 symmetric matrix with awkward values (1/3, a denormal, -0, huge), lower triangle only.
xfem::SparseMatrix awkward_lower() {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < 5; ++i) t.emplace_back(i, i, 1.0 / (3.0 + i));
  t.emplace_back(1, 0, std::numeric_limits<double>::denorm_min());
  t.emplace_back(3, 0, -0.0);
  t.emplace_back(4, 2, -1.7e300);
  t.emplace_back(4, 3, 0.1);
  xfem::SparseMatrix K(5, 5);
  K.setFromTriplets(t.begin(), t.end());
  return K;
}

std::vector<char> bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), {});
}

void write_bytes(const std::string& path, const std::vector<char>& b) {
  std::ofstream(path, std::ios::binary).write(b.data(), static_cast<std::streamsize>(b.size()));
}

// Big-endian int32 at byte `offset`.
void put_int(std::vector<char>& b, std::size_t offset, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) b[offset + k] = static_cast<char>((v >> (24 - 8 * k)) & 0xff);
}

}  // namespace

TEST_CASE("petsc_binary: a symmetric matrix and a vector come back bit for bit", "[petsc_binary]") {
  const xfem::SparseMatrix lower = awkward_lower();
  const std::string path = scratch("K.petsc");
  xfem::write_petsc_symmetric_matrix(lower, path);
  const xfem::SparseMatrix full = lower.selfadjointView<Eigen::Lower>();
  // The layout PETSc documents for MatView/MatLoad: header, row lengths, columns, values.
  CHECK(fs::file_size(path) == 16 + 4 * 5 + 12 * static_cast<std::size_t>(full.nonZeros()));
  const std::vector<char> b = bytes_of(path);
  CHECK(static_cast<unsigned char>(b[0]) == 0x00);
  CHECK(static_cast<unsigned char>(b[1]) == 0x12);  // 1211216 = 0x00127B50, big-endian
  CHECK(static_cast<unsigned char>(b[2]) == 0x7B);
  CHECK(static_cast<unsigned char>(b[3]) == 0x50);
  const xfem::PetscMatrixHeader h = xfem::read_petsc_matrix_header(path);
  CHECK(h.rows == 5);
  CHECK(h.cols == 5);
  CHECK(h.nonzeros == full.nonZeros());

  const xfem::SparseMatrix back = xfem::read_petsc_matrix(path);
  REQUIRE(back.nonZeros() == full.nonZeros());
  CHECK(std::equal(back.outerIndexPtr(), back.outerIndexPtr() + 6, full.outerIndexPtr()));
  CHECK(std::equal(back.innerIndexPtr(), back.innerIndexPtr() + full.nonZeros(), full.innerIndexPtr()));
  for (long k = 0; k < full.nonZeros(); ++k)  // bit patterns: -0 and the denormal too
    CHECK(std::memcmp(back.valuePtr() + k, full.valuePtr() + k, 8) == 0);

  Eigen::VectorXd v(4);
  v << 1.0 / 3.0, -0.0, std::numeric_limits<double>::denorm_min(), -2.5e-300;
  const std::string vpath = scratch("f.petsc");
  xfem::write_petsc_vector(v, vpath);
  CHECK(fs::file_size(vpath) == 8 + 8 * 4);
  const Eigen::VectorXd w = xfem::read_petsc_vector(vpath);
  REQUIRE(w.size() == 4);
  CHECK(std::memcmp(w.data(), v.data(), 4 * 8) == 0);
  xfem::write_petsc_vector(Eigen::VectorXd(), vpath);  // empty is allowed
  CHECK(xfem::read_petsc_vector(vpath).size() == 0);
}

TEST_CASE("petsc_binary: some rows of a symmetric matrix are its columns, bit for bit, the rest empty",
          "[petsc_binary]") {
  const xfem::SparseMatrix lower = awkward_lower();
  const std::string path = scratch("K_rows.petsc");
  xfem::write_petsc_symmetric_matrix(lower, path);
  const xfem::SparseMatrix full = lower.selfadjointView<Eigen::Lower>();
  const xfem::SparseMatrix some = xfem::read_petsc_symmetric_matrix_rows(path, {3, 0, 3});  // unsorted, repeated
  REQUIRE(some.rows() == 5);
  REQUIRE(some.cols() == 5);
  for (int j = 0; j < 5; ++j) {
    const bool asked = j == 0 || j == 3;
    CHECK(some.outerIndexPtr()[j + 1] - some.outerIndexPtr()[j] ==
          (asked ? full.outerIndexPtr()[j + 1] - full.outerIndexPtr()[j] : 0));
    if (!asked) continue;
    for (int k = 0; k < some.outerIndexPtr()[j + 1] - some.outerIndexPtr()[j]; ++k) {
      CHECK(some.innerIndexPtr()[some.outerIndexPtr()[j] + k] == full.innerIndexPtr()[full.outerIndexPtr()[j] + k]);
      CHECK(std::memcmp(some.valuePtr() + some.outerIndexPtr()[j] + k, full.valuePtr() + full.outerIndexPtr()[j] + k, 8) == 0);
    }
  }
  Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(5, 1, 5);
  for (int d : {0, 3}) CHECK(some.col(d).dot(u) == full.col(d).dot(u));
  CHECK(xfem::read_petsc_symmetric_matrix_rows(path, {}).nonZeros() == 0);
  CHECK_THROWS_WITH(xfem::read_petsc_symmetric_matrix_rows(path, {5}), Contains("row 5 asked for, the matrix has 5"));
  std::vector<char> b = bytes_of(path);  // truncated: the header check refuses it first
  std::ofstream(path, std::ios::binary).write(b.data(), static_cast<std::streamsize>(b.size() - 3));
  CHECK_THROWS_WITH(xfem::read_petsc_symmetric_matrix_rows(path, {0}), Contains("(truncated?)"));
}

TEST_CASE("petsc_binary: damaged files are refused with what is wrong", "[petsc_binary]") {
  const std::string path = scratch("good.petsc"), bad = scratch("bad.petsc");
  xfem::write_petsc_symmetric_matrix(awkward_lower(), path);
  const std::vector<char> good = bytes_of(path);
  const long nnz = xfem::read_petsc_matrix_header(path).nonzeros;

  SECTION("truncated") {
    write_bytes(bad, std::vector<char>(good.begin(), good.end() - 3));
    CHECK_THROWS_WITH(xfem::read_petsc_matrix(bad), Contains("bad.petsc:") && Contains("(truncated?)"));
    CHECK_THROWS_WITH(xfem::read_petsc_matrix_header(bad), Contains("(truncated?)"));
    write_bytes(bad, std::vector<char>(good.begin(), good.begin() + 10));
    CHECK_THROWS_WITH(xfem::read_petsc_matrix(bad), Contains("too short"));
    write_bytes(bad, {});
    CHECK_THROWS_WITH(xfem::read_petsc_matrix(bad), Contains("0 bytes, too short"));
  }
  SECTION("trailing bytes") {
    std::vector<char> b = good;
    b.push_back(0);
    write_bytes(bad, b);
    CHECK_THROWS_WITH(xfem::read_petsc_matrix(bad), Contains("(trailing bytes)"));
  }
  SECTION("wrong class id: a vector or a text file where a matrix belongs") {
    xfem::write_petsc_vector(Eigen::VectorXd::Ones(3), bad);
    CHECK_THROWS_WITH(xfem::read_petsc_matrix(bad), Contains("class id 1211214, expected 1211216"));
    CHECK_THROWS_WITH(xfem::read_petsc_matrix_header(bad), Contains("class id 1211214, expected 1211216"));
    CHECK_THROWS_WITH(xfem::read_petsc_vector(path), Contains("class id 1211216, expected 1211214"));
    std::ofstream(bad) << "%%MatrixMarket matrix coordinate real symmetric\n";
    CHECK_THROWS_WITH(xfem::read_petsc_matrix(bad), Contains("class id") && Contains("a PETSc matrix"));
  }
  SECTION("sizes that disagree with the file") {
    std::vector<char> b = good;
    put_int(b, 12, static_cast<std::uint32_t>(nnz + 1));  // one non-zero more than stored
    write_bytes(bad, b);
    CHECK_THROWS_WITH(xfem::read_petsc_matrix(bad), Contains("(truncated?)"));
    b = good;
    put_int(b, 4, 0xffffffffu);  // rows -1
    write_bytes(bad, b);
    CHECK_THROWS_WITH(xfem::read_petsc_matrix(bad), Contains("negative size"));
    b = good;
    put_int(b, 16, 2);  // row 0 claims 2 entries instead of its own: the lengths no longer add up
    write_bytes(bad, b);
    CHECK_THROWS_WITH(xfem::read_petsc_matrix(bad), Contains("row lengths add up to"));
    b = good;
    put_int(b, 16 + 4 * 5, 7);  // row 0's first column index 7 >= 5
    write_bytes(bad, b);
    CHECK_THROWS_WITH(xfem::read_petsc_matrix(bad), Contains("row 0: column index 7 out of range 0..4"));
    b = good;
    put_int(b, 16 + 4 * 5 + 4, 0);  // row 0's second column index equal to its first
    write_bytes(bad, b);
    CHECK_THROWS_WITH(xfem::read_petsc_matrix(bad), Contains("not increasing"));
  }
  SECTION("non-finite values") {
    std::vector<char> b = good;
    const std::size_t value0 = 16 + 4 * 5 + 4 * static_cast<std::size_t>(nnz);
    b[value0] = 0x7f, b[value0 + 1] = static_cast<char>(0xf0);  // +inf: exponent all ones, mantissa 0
    for (int k = 2; k < 8; ++k) b[value0 + k] = 0;
    write_bytes(bad, b);
    CHECK_THROWS_WITH(xfem::read_petsc_matrix(bad), Contains("value 0 is not finite"));
    Eigen::VectorXd v = Eigen::VectorXd::Ones(2);
    v[1] = std::nan("");
    CHECK_THROWS_WITH(xfem::write_petsc_vector(v, bad), Contains("not finite"));
  }
  SECTION("a missing file") {
    CHECK_THROWS_WITH(xfem::read_petsc_matrix(scratch("none.petsc")), Contains("cannot open for reading"));
    CHECK_THROWS_WITH(xfem::read_petsc_vector(scratch("none.petsc")), Contains("cannot open for reading"));
  }
}
