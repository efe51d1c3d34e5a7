// SPDX-License-Identifier: MIT
#pragma once
#include <cstdio>
#include <stdexcept>
#include <string>

namespace xfem {

/// Bad input or a failed computation. The message names the object (file, array, element or
/// node index, offending value) so that a tool can print it as one line and exit 1.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A number for a message in short form: 6 significant digits ("0.006", "1e+300", "nan"), never
/// the 309 digits std::to_string prints for 1e308.
inline std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace xfem
