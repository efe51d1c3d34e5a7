// SPDX-License-Identifier: MIT
#include "xfem/exact_fields.h"

#include <cmath>

namespace xfem {

Eigen::Vector3d WilliamsField::displacement(const Eigen::Vector3d& x, int side) const {
  const Eigen::Vector3d c = a.cross(b);  // a = b x c  <=>  c = a x b for an orthonormal frame
  const Eigen::Vector3d d = x - origin;
  const double xa = a.dot(d), xb = b.dot(d);
  const double r = std::hypot(xa, xb);
  double theta = std::atan2(xb, xa);
  // On a cut face up to round-off, the requested face decides the branch of atan2.
  if (side != 0 && xa < 0.0 && std::abs(xb) <= 1e-9 * r) theta = side > 0 ? M_PI : -M_PI;
  const double mu = E / (2.0 * (1.0 + nu)), kappa = 3.0 - 4.0 * nu;
  const double s = std::sqrt(r / (2.0 * M_PI)), sh = std::sin(theta / 2), ch = std::cos(theta / 2);
  // Anderson, Fracture Mechanics, table 2.2 (plane strain), and the anti-plane mode III field.
  const double ua = K1 / (2 * mu) * s * ch * (kappa - 1 + 2 * sh * sh) +
                    K2 / (2 * mu) * s * sh * (kappa + 1 + 2 * ch * ch);
  const double ub = K1 / (2 * mu) * s * sh * (kappa + 1 - 2 * ch * ch) -
                    K2 / (2 * mu) * s * ch * (kappa - 1 - 2 * sh * sh);
  const double uc = 2 * K3 / mu * s * sh;
  return ua * a + ub * b + uc * c;
}

}  // namespace xfem
