// SPDX-License-Identifier: MIT
#include "xfem/integrate/polygon_split.h"

#include <cmath>

namespace xfem {

bool split_polygon(const Polygon& poly, const Eigen::Vector3d& point, const Eigen::Vector3d& normal, double tolerance,
                   Polygon& above, Polygon& below) {
  above.clear();
  below.clear();
  bool positive = false, negative = false;
  const std::size_t n = poly.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d &u = poly[k], &v = poly[(k + 1) % n];
    double du = normal.dot(u - point), dv = normal.dot(v - point);
    if (std::abs(du) <= tolerance) du = 0;
    if (std::abs(dv) <= tolerance) dv = 0;
    positive = positive || du > 0;
    negative = negative || du < 0;
    if (du >= 0) above.push_back(u);
    if (du <= 0) below.push_back(u);
    if ((du > 0 && dv < 0) || (du < 0 && dv > 0)) {
      const Eigen::Vector3d x = u + du / (du - dv) * (v - u);
      above.push_back(x);
      below.push_back(x);
    }
  }
  return positive && negative;
}

}  // namespace xfem
