// SPDX-License-Identifier: MIT
// xfem::cli's helpers that xfem-assemble, -solve and -sweep share: three-digit numbers and the
// check of an output directory.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "xfem/core/cli.h"
#include "xfem/core/error.h"

TEST_CASE("three_digits writes %.3g", "[cli]") {
  CHECK(xfem::cli::three_digits(0.012345) == "0.0123");
  CHECK(xfem::cli::three_digits(1e-8) == "1e-08");
  CHECK(xfem::cli::three_digits(1234.5) == "1.23e+03");
  CHECK(xfem::cli::three_digits(2) == "2");
}

TEST_CASE("check_output_directory accepts a missing directory under a writable one", "[cli]") {
  namespace fs = std::filesystem;
  const fs::path base = fs::temp_directory_path() / "xfem_check_output_directory";
  fs::remove_all(base);
  fs::create_directories(base);
  CHECK_NOTHROW(xfem::cli::check_output_directory((base / "a" / "b").string()));
  CHECK_NOTHROW(xfem::cli::check_output_directory(base.string()));
  const fs::path file = base / "file";
  { std::ofstream(file.string()) << "x"; }
  CHECK_THROWS_WITH(xfem::cli::check_output_directory((file / "system").string()),
                    Catch::Contains("is not a directory"));
  fs::remove_all(base);
}
