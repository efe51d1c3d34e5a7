// SPDX-License-Identifier: MIT
#pragma once

#include <chrono>

namespace xfem {

/// Wall-clock seconds elapsed since `start` (the stage timings of the tools' reports).
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace xfem
