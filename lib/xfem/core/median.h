// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <vector>

namespace xfem {

/// The median of `values`: the middle one, or the mean of the two middle ones for an even count;
/// 0 for none (the per-step timings of xfem-sweep's report and the benches).
inline double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t h = values.size() / 2;
  return values.size() % 2 ? values[h] : 0.5 * (values[h - 1] + values[h]);
}

}  // namespace xfem
