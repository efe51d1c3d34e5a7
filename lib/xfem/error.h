// SPDX-License-Identifier: MIT
#pragma once
#include <stdexcept>
#include <string>

namespace xfem {

/// Bad input or a failed computation. The message names the object (file, array, element or
/// node index, offending value) so that a tool can print it as one line and exit 1.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace xfem
