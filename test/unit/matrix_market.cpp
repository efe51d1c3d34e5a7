// SPDX-License-Identifier: MIT
#include "xfem/io/matrix_market.h"

#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "xfem/core/error.h"

namespace {
std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "xfem_unit";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}
}  // namespace

TEST_CASE("matrix_market: a symmetric matrix round-trips exactly", "[matrix_market]") {
  xfem::SparseMatrix K(3, 3);
  std::vector<Eigen::Triplet<double>> t = {{0, 0, 4.0}, {1, 0, -1.0 / 3.0}, {0, 1, -1.0 / 3.0},
                                           {1, 1, 1e-300}, {2, 2, 12345.678901234567}, {2, 0, 0.1}, {0, 2, 0.1}};
  K.setFromTriplets(t.begin(), t.end());
  const auto path = scratch("K.mtx");
  xfem::write_symmetric_matrix(K, path);
  const xfem::SparseMatrix back = xfem::read_matrix(path);
  REQUIRE(back.rows() == 3);
  // Shortest round-trip formatting: every bit comes back.
  CHECK((back - K).norm() == 0.0);
}

TEST_CASE("matrix_market: a vector round-trips exactly", "[matrix_market]") {
  Eigen::VectorXd v(4);
  v << 1.0, -2.5e-17, 3.141592653589793, 0.0;
  const auto path = scratch("v.mtx");
  xfem::write_vector(v, path);
  CHECK(xfem::read_vector(path) == v);
}

TEST_CASE("matrix_market: a non-finite value is refused and no file is left", "[matrix_market]") {
  Eigen::VectorXd v(2);
  v << 1.0, std::nan("");
  const auto path = scratch("nan.mtx");
  std::remove(path.c_str());
  CHECK_THROWS_WITH(xfem::write_vector(v, path), Catch::Contains("non-finite value at row 2"));
  CHECK_FALSE(std::filesystem::exists(path));
}

TEST_CASE("matrix_market: bad files are named with the problem", "[matrix_market]") {
  const auto path = scratch("bad.mtx");
  {
    std::ofstream(path) << "hello\n";
  }
  CHECK_THROWS_WITH(xfem::read_vector(path), Catch::Contains("not a Matrix Market file"));
  {
    std::ofstream(path) << "%%MatrixMarket matrix array real general\n3 1\n1.0\n2.0\n";
  }
  CHECK_THROWS_WITH(xfem::read_vector(path), Catch::Contains("unexpected end of file (expected a number)"));
  {
    std::ofstream(path) << "%%MatrixMarket matrix coordinate real general\n2 2 1\n3 1 1.0\n";
  }
  CHECK_THROWS_WITH(xfem::read_matrix(path), Catch::Contains("index out of range"));
  {
    std::ofstream(path) << "%%MatrixMarket matrix array real general\n2 1\n1.0\nabc\n";
  }
  CHECK_THROWS_WITH(xfem::read_vector(path), Catch::Contains("line 4: expected a number"));
  CHECK_THROWS_WITH(xfem::read_matrix(scratch("missing.mtx")), Catch::Contains("cannot open"));
}

TEST_CASE("matrix_market: a large matrix written in blocks by several threads comes back exactly, in order",
          "[matrix_market]") {
  // 200,000 columns x 3 stored lower entries = 600,000 entries: 2 blocks of 2^18 and more, formatted
  // concurrently and written in column order; the upper-triangle entries are not written.
  const int n = 200000;
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < n; ++j) {
    t.emplace_back(j, j, 4.0 + j / 7.0);
    if (j + 1 < n) t.emplace_back(j + 1, j, -1.0 / (j + 3.0)), t.emplace_back(j, j + 1, -1.0 / (j + 3.0));
    if (j + 5 < n) t.emplace_back(j + 5, j, 1e-3 * j), t.emplace_back(j, j + 5, 1e-3 * j);
  }
  xfem::SparseMatrix K(n, n);
  K.setFromTriplets(t.begin(), t.end());
  const auto path = scratch("K_large.mtx");
  xfem::write_symmetric_matrix(K, path);
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  CHECK(line == "200000 200000 599994");
  long lines = 0, last_column = 0;
  bool ordered = true;
  long row = 0, column = 0;
  double value = 0;
  while (in >> row >> column >> value) {
    ordered = ordered && column >= last_column && row >= column;
    last_column = column;
    ++lines;
  }
  CHECK(lines == 599994);
  CHECK(ordered);
  const xfem::SparseMatrix back = xfem::read_matrix(path);
  CHECK((back - K).norm() == 0.0);
  std::remove(path.c_str());
}
