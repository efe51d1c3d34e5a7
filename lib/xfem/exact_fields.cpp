// SPDX-License-Identifier: MIT
#include "xfem/exact_fields.h"

#include <cmath>
#include <sstream>

#include "xfem/branch_functions.h"
#include "xfem/error.h"

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

CrackTipFrame WilliamsField::frame() const {
  CrackTipFrame f;
  f.R.col(0) = a;
  f.R.col(1) = b;
  f.R.col(2) = a.cross(b);
  f.origin = origin;
  return f;
}

Eigen::Matrix<double, 3, 4> WilliamsField::branch_coefficients() const {
  // displacement() rewritten with sin(t/2) sin t = 2 sin^2(t/2) cos(t/2) and
  // cos(t/2) sin t = 2 sin(t/2) cos^2(t/2): every term is sqrt r times one of the four F_j / sqrt r.
  const double mu = E / (2.0 * (1.0 + nu)), kappa = 3.0 - 4.0 * nu;
  const double g = 1.0 / (2.0 * mu * std::sqrt(2.0 * M_PI));
  const Eigen::Vector3d c = a.cross(b);
  Eigen::Matrix<double, 3, 4> C;
  C.col(0) = g * ((kappa + 1) * (K1 * b + K2 * a) + 4 * K3 * c);
  C.col(1) = g * (kappa - 1) * (K1 * a - K2 * b);
  C.col(2) = g * (K1 * a + K2 * b);
  C.col(3) = g * (K2 * a - K1 * b);
  return C;
}

Eigen::Matrix<double, 3, 4> WilliamsField::branch_coefficients(const CrackTipFrame& other, double tolerance) const {
  const Eigen::Vector3d a2 = other.R.col(0), b2 = other.R.col(1), c = a.cross(b);
  const Eigen::Vector3d offset = other.origin - origin;
  const double off_line = (offset - offset.dot(c) * c).norm();
  const double cos_b = b2.dot(b);
  if (a2.dot(a) < 1 - 1e-9 || std::abs(cos_b) < 1 - 1e-9 || off_line > tolerance) {
    std::ostringstream m;
    m << "the Williams field's front (origin " << origin.transpose() << ", ahead " << a.transpose() << ", normal "
      << b.transpose() << ") is not the mesh's cut front (point " << other.origin.transpose() << ", ahead "
      << a2.transpose() << ", normal " << b2.transpose() << "; " << off_line << " m apart)";
    throw Error(m.str());
  }
  Eigen::Matrix<double, 3, 4> C = branch_coefficients();
  // b2 = -b: theta2 = -theta, so F2_0 = -F_0, F2_3 = -F_3 and F2_1, F2_2 are unchanged.
  if (cos_b < 0) {
    C.col(0) *= -1;
    C.col(3) *= -1;
  }
  return C;
}

Eigen::Matrix3d WilliamsField::gradient(const Eigen::Vector3d& x, int side) const {
  const BranchValues F = branch_functions(frame(), x, side);
  return branch_coefficients() * F.dF;
}

Eigen::Matrix3d RigidMotion::gradient() const {
  Eigen::Matrix3d W;
  W << 0, -rotation.z(), rotation.y(), rotation.z(), 0, -rotation.x(), -rotation.y(), rotation.x(), 0;
  return W;
}

Eigen::Vector3d ExactField::displacement(const Eigen::Vector3d& x, int side) const {
  if (kind == Kind::Williams) return williams.displacement(x, side);
  if (kind == Kind::Linear) return linear_translation + linear_gradient * x;
  return side < 0 ? below.displacement(x) : above.displacement(x);
}

Eigen::Matrix3d ExactField::gradient(const Eigen::Vector3d& x, int side) const {
  if (kind == Kind::Williams) return williams.gradient(x, side);
  if (kind == Kind::Linear) return linear_gradient;
  return side < 0 ? below.gradient() : above.gradient();
}

}  // namespace xfem
