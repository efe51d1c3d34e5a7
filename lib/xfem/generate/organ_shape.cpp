// SPDX-License-Identifier: MIT
#include "xfem/generate/organ_shape.h"

namespace xfem {
namespace {
constexpr double a = 0.075, b = 0.05, c0 = 0.035;  // half-length, half-width, mid half-thickness
constexpr double taper = 0.35, bend = 0.012;        // thickness change over a, rise of the ends
constexpr double pi = 3.14159265358979323846;
}  // namespace

double organ_function(const Eigen::Vector3d& p) {
  const double xa = p.x() / a;
  const double c = c0 * (1 + taper * xa);  // positive on |x| <= a, where the body lives
  const double zs = (p.z() - bend * xa * xa) / c;
  return xa * xa + (p.y() / b) * (p.y() / b) + zs * zs - 1;
}

double organ_volume() { return 4.0 / 3.0 * pi * a * b * c0; }

}  // namespace xfem
