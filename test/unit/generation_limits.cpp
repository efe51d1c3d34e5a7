// SPDX-License-Identifier: MIT
#include "xfem/generate/generation_limits.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "xfem/core/error.h"

TEST_CASE("check_element_estimate refuses more than 2e7 elements unless allowed", "[generate]") {
  CHECK_NOTHROW(xfem::check_element_estimate(2e7, "tets", false));
  CHECK_NOTHROW(xfem::check_element_estimate(6e9, "tets", true));
  CHECK_THROWS_WITH(xfem::check_element_estimate(6e9, "tets", false),
                    "about 6e+09 tets requested (limit 2e+07; a larger --size or fewer divisions, or --allow-large)");
  CHECK_THROWS_AS(xfem::check_element_estimate(std::numeric_limits<double>::quiet_NaN(), "triangles", false),
                  xfem::Error);
}

TEST_CASE("tets_for estimates regular tets of a given edge", "[generate]") {
  CHECK(xfem::tets_for(1.0, 1.0) == Approx(6 * std::sqrt(2.0)));
  CHECK(xfem::tets_for(1e-3, 0.1) == Approx(6 * std::sqrt(2.0)));
}

TEST_CASE("check_extent keeps coordinates within 1e6 m", "[generate]") {
  CHECK_NOTHROW(xfem::check_extent({1e6, -1e6, 0}, "--lo"));
  CHECK_THROWS_WITH(xfem::check_extent({0, 2e6, 0}, "--hi"), "--hi 2e+06: coordinates must lie within 1e6 m of the origin");
  CHECK_THROWS_AS(xfem::check_extent({std::nan(""), 0, 0}, "--corner"), xfem::Error);
}
