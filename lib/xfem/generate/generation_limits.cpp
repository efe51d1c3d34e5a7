// SPDX-License-Identifier: MIT
#include "xfem/generate/generation_limits.h"

#include <cmath>
#include <string>

#include "xfem/core/error.h"

namespace xfem {

void check_element_estimate(double estimate, const char* what, bool allowed) {
  if (!(estimate <= kMaxGeneratedElements) && !allowed)
    throw Error("about " + short_number(estimate) + " " + what + " requested (limit " +
                short_number(kMaxGeneratedElements) + "; a larger --size or fewer divisions, or --allow-large)");
}

double tets_for(double volume, double size) { return 6 * std::sqrt(2.0) * volume / (size * size * size); }

void check_extent(const std::array<double, 3>& a, const char* option) {
  for (double v : a)
    if (!(std::fabs(v) <= 1e6))
      throw Error(std::string(option) + " " + short_number(v) + ": coordinates must lie within 1e6 m of the origin");
}

}  // namespace xfem
