// SPDX-License-Identifier: MIT
#include "xfem/fracture/exact_fields.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>
#include <vector>

#include "xfem/enrich/branch_functions.h"
#include "xfem/core/error.h"

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

namespace {

// A function f(mu, theta) of the oblate spheroidal coordinates, z + i r = a sinh(W), W = mu + i theta,
// and its partial derivatives up to the second order.
struct Spheroidal {
  double f = 0, m = 0, t = 0, mm = 0, mt = 0, tt = 0;
};

// f's derivatives in (r, z): the map W(s), s = z + i r, is analytic, so with W' = dW/ds and
// W'' = d2W/ds2: dW/dz = W', dW/dr = i W', d2W/dz2 = W'', d2W/dr dz = i W'', d2W/dr2 = -W''.
struct Cylindrical {
  double f = 0, r = 0, z = 0, rr = 0, rz = 0;
};

Cylindrical to_cylindrical(const Spheroidal& g, std::complex<double> w1, std::complex<double> w2) {
  const std::complex<double> I(0.0, 1.0);
  const double mz = w1.real(), tz = w1.imag();
  const std::complex<double> wr = I * w1;
  const double mr = wr.real(), tr = wr.imag();
  const std::complex<double> wrz = I * w2, wrr = -w2;
  Cylindrical c;
  c.f = g.f;
  c.z = g.m * mz + g.t * tz;
  c.r = g.m * mr + g.t * tr;
  c.rz = g.mm * mr * mz + g.mt * (mr * tz + mz * tr) + g.tt * tr * tz + g.m * wrz.real() + g.t * wrz.imag();
  c.rr = g.mm * mr * mr + 2 * g.mt * mr * tr + g.tt * tr * tr + g.m * wrr.real() + g.t * wrr.imag();
  return c;
}

}  // namespace

double PennyField::K1() const { return 2.0 * sigma * std::sqrt(radius / M_PI); }

Eigen::Vector3d PennyField::stress_intensity(const Eigen::Vector3d& x) const {
  const Eigen::Vector3d n = normal.normalized();
  Eigen::Vector3d a = (x - centre) - n.dot(x - centre) * n;
  if (!(a.norm() > 0)) throw Error("penny field: the disc's axis has no closest front point");
  a.normalize();
  const Eigen::Vector3d c = a.cross(n);
  const double g = std::sqrt(radius / M_PI) / (2.0 - nu);
  return {K1(), 4.0 * g * shear.dot(a), 4.0 * (1.0 - nu) * g * shear.dot(c)};
}

namespace {

// Gauss-Legendre nodes and weights on [0, 1] (Newton on P_n, computed once).
struct GaussLegendre {
  std::vector<double> x, w;
  explicit GaussLegendre(int n) {
    for (int i = 0; i < n; ++i) {
      double t = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 1.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = t;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (t * p1 - p0) / (t * t - 1);
        const double dt = p1 / dp;
        t -= dt;
        if (std::abs(dt) < 1e-16) break;
      }
      x.push_back(0.5 * (1 - t));
      w.push_back(1.0 / ((1 - t * t) * dp * dp));
    }
  }
};

}  // namespace

Eigen::Vector3d PennyField::elliptical_jump_displacement(const Eigen::Vector3d& x, const Eigen::Vector3d& jump) const {
  static const GaussLegendre gl(32);
  const int nphi = 128;
  const double a = radius;
  const Eigen::Vector3d n = normal.normalized();
  const Eigen::Vector3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  // Distance to the disc: the quadrature resolves Kelvin's 1/R^2 kernel from 0.25 a on.
  const Eigen::Vector3d d = x - centre;
  const double zl = n.dot(d), rl = (d - zl * n).norm();
  if (std::hypot(zl, std::max(0.0, rl - a)) < 0.25 * a)
    throw Error("penny field with shear: a point closer than 0.25 radius to the disc (the quadrature of its "
                "shear part does not resolve it; keep the boundary away from the disc)");
  const double k = -1.0 / (8.0 * M_PI * (1.0 - nu));
  Eigen::Vector3d u = Eigen::Vector3d::Zero();
  for (std::size_t it = 0; it < gl.x.size(); ++it) {
    // r = a sin t, t in [0, pi/2]: sqrt(a^2 - r^2) r dr = a^3 sin t cos^2 t dt.
    const double t = 0.5 * M_PI * gl.x[it];
    const double wt = 0.5 * M_PI * gl.w[it] * a * a * a * std::sin(t) * std::cos(t) * std::cos(t) * (2 * M_PI / nphi);
    const double r = a * std::sin(t);
    for (int ip = 0; ip < nphi; ++ip) {
      const double phi = 2 * M_PI * (ip + 0.5) / nphi;
      const Eigen::Vector3d y = centre + r * (std::cos(phi) * e1 + std::sin(phi) * e2);
      const Eigen::Vector3d rv = y - x;
      const double R = rv.norm();
      const Eigen::Vector3d rh = rv / R;
      const double bn = jump.dot(n), br = jump.dot(rh), nr = n.dot(rh);
      // b_i n_j sigma^(m)_ij of Kelvin's unit force e_m at x, sigma at y (r = y - x).
      const Eigen::Vector3d s = k / (R * R) * ((1 - 2 * nu) * (jump * nr + n * br - bn * rh) + 3 * br * nr * rh);
      u += wt * s;
    }
  }
  return u;
}

void PennyField::evaluate(const Eigen::Vector3d& x, int side, Eigen::Vector3d* u_out, Eigen::Matrix3d* grad_out) const {
  const double a = radius;
  const Eigen::Vector3d n = normal.normalized();
  const Eigen::Vector3d d = x - centre;
  const double zl = n.dot(d);
  Eigen::Vector3d rvec = d - zl * n;
  double r = rvec.norm();
  Eigen::Vector3d er;
  if (r > 1e-9 * a) {
    er = rvec / r;
  } else {  // on the axis: any radial direction (the radial parts vanish like r)
    er = n.unitOrthogonal();
    r = 1e-9 * a;
  }
  // The upper half z >= 0 carries the potentials; the lower half is its mirror image.
  double s = zl > 0 ? 1.0 : zl < 0 ? -1.0 : 0.0;
  double z = std::abs(zl);
  if (z <= 1e-12 * a) {
    z = 0.0;
    s = side < 0 && r < a ? -1.0 : 1.0;
  }
  // At the front the potentials' derivatives are infinite: a point within 1e-10 a of it moves out
  // radially by that much (u is continuous there; the gradient is reported as 0).
  const bool at_front = std::hypot(r - a, z) < 1e-10 * a;
  if (at_front) r = a * (1 + 1e-10);
  // zeta^2 = p, eta^2 = q: p - q = (r^2 + z^2) / a^2 - 1, p q = z^2 / a^2, each root taken where it
  // does not cancel.
  const double D = (r * r + z * z) / (a * a) - 1.0, Z = z * z / (a * a);
  const double root = std::sqrt(D * D + 4 * Z);
  double p, q;
  if (D >= 0) {
    p = 0.5 * (D + root);
    q = p > 0 ? Z / p : 0.0;
  } else {
    q = 0.5 * (-D + root);
    p = Z / q;
  }
  q = std::min(q, 1.0);
  const double zeta = std::sqrt(p), eta = std::sqrt(q);
  const double cosh_mu = std::sqrt(1 + p), sin_t = std::sqrt(1 - q);
  const double A = std::atan2(1.0, zeta);  // arccot zeta, in (0, pi/2]
  // dW/ds = 1 / (a cosh W), d2W/ds2 = -(s / a) a^2 (dW/ds)^3 with sinh W = s / a, s = z + i r.
  const std::complex<double> coshW(cosh_mu * eta, zeta * sin_t);
  const std::complex<double> w1 = 1.0 / (a * coshW);
  const std::complex<double> w2 = -std::complex<double>(z, r) * w1 * w1 * w1;

  // chi = C a cos(theta) g(mu), g = 1 - sinh(mu) arccot(sinh mu); d arccot(sinh mu) / dmu = -1 / cosh mu.
  const double C = -2.0 * sigma / M_PI;
  const double g = 1 - zeta * A, g1 = -cosh_mu * A + zeta / cosh_mu, g2 = -zeta * A + 1 + 1 / (1 + p);
  Spheroidal chi_s;
  chi_s.f = C * a * eta * g;
  chi_s.m = C * a * eta * g1;
  chi_s.t = -C * a * sin_t * g;
  chi_s.mm = C * a * eta * g2;
  chi_s.mt = -C * a * sin_t * g1;
  chi_s.tt = -C * a * eta * g;
  // phi = -(C a^2 / 3) (arccot zeta + P2(cos theta) q2(zeta)): only its first derivatives are needed.
  const double q2 = 0.5 * (3 * p + 1) * A - 1.5 * zeta;
  const double dq2 = cosh_mu * (3 * zeta * A - (3 * p + 1) / (2 * (1 + p)) - 1.5);
  const double P2 = 0.5 * (3 * q - 1), dP2 = -3 * eta * sin_t;
  Spheroidal phi_s;
  phi_s.m = -C * a * a / 3 * (-1 / cosh_mu + P2 * dq2);
  phi_s.t = -C * a * a / 3 * dP2 * q2;
  const Cylindrical chi = to_cylindrical(chi_s, w1, w2);
  const Cylindrical phi = to_cylindrical(phi_s, w1, w2);

  const double mu = E / (2 * (1 + nu));
  // The perturbation in the upper half: u = U_r e_r + u_z n.
  const double Ur = ((1 - 2 * nu) * phi.r + z * chi.r) / (2 * mu);
  const double uz = (-2 * (1 - nu) * chi.f + z * chi.z) / (2 * mu);
  // The remote field sigma n n^T: eps = sigma / E ((1 + nu) n n^T - nu I), u = eps (x - centre).
  const Eigen::Matrix3d eps = remote ? Eigen::Matrix3d(sigma / E * ((1 + nu) * n * n.transpose() - nu * Eigen::Matrix3d::Identity()))
                                     : Eigen::Matrix3d::Zero();
  if (u_out) *u_out = Ur * er + s * uz * n + eps * d;
  if (grad_out) {
    if (at_front) {
      grad_out->setZero();
      return;
    }
    // phi_zz = chi_z and Laplace: phi_rr = -chi_z - phi_r / r; chi_zz = -chi_rr - chi_r / r.
    const double phi_rr = -chi.z - phi.r / r, chi_zz = -chi.rr - chi.r / r;
    const double Ur_r = ((1 - 2 * nu) * phi_rr + z * chi.rr) / (2 * mu);
    const double Ur_z = (2 * (1 - nu) * chi.r + z * chi.rz) / (2 * mu);
    const double uz_r = (-2 * (1 - nu) * chi.r + z * chi.rz) / (2 * mu);
    const double uz_z = (-(1 - 2 * nu) * chi.z + z * chi_zz) / (2 * mu);
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - n * n.transpose(), Err = er * er.transpose();
    // Mirror: dz/dzl = s, u_z changes sign: the mixed terms take s, the others stay.
    *grad_out = Ur_r * Err + Ur / r * (P - Err) + s * Ur_z * er * n.transpose() + s * uz_r * n * er.transpose() +
                uz_z * n * n.transpose() + eps;
  }
}

// The uniform strain of the remote normal tension sigma n n^T.
static Eigen::Matrix3d penny_normal_strain(const PennyField& p) {
  const Eigen::Vector3d n = p.normal.normalized();
  return p.sigma / p.E * ((1 + p.nu) * n * n.transpose() - p.nu * Eigen::Matrix3d::Identity());
}

Eigen::Vector3d PennyField::displacement(const Eigen::Vector3d& x, int side) const {
  Eigen::Vector3d u;
  if (closed)
    u = penny_normal_strain(*this) * (x - centre);  // faces shut: the uniform field alone
  else
    evaluate(x, side, &u, nullptr);
  if (shear.squaredNorm() > 0) {
    const Eigen::Vector3d n = normal.normalized();
    if (std::abs(shear.dot(n)) > 1e-12 * shear.norm()) throw Error("penny field: shear must lie in the disc's plane");
    // The remote shear strain (tau n^T + n tau^T) (1 + nu) / E, then the slid crack's perturbation.
    const Eigen::Matrix3d eps = (1 + nu) / E * (shear * n.transpose() + n * shear.transpose());
    // Friction (closed faces) carries mu |sigma| of the shear: the rest slides (0: the faces stick).
    const double sliding = closed && friction > 0 ? std::max(0.0, 1 - friction * std::abs(sigma) / shear.norm()) : 1.0;
    if (sliding == 1.0)  // frictionless: the expression as before friction, bit for bit
      u += (remote ? Eigen::Vector3d(eps * (x - centre)) : Eigen::Vector3d::Zero()) +
           elliptical_jump_displacement(x, 16.0 * (1 - nu * nu) / (M_PI * (2 - nu) * E) * shear);
    else if (sliding > 0)
      u += Eigen::Vector3d(eps * (x - centre)) +
           elliptical_jump_displacement(x, sliding * 16.0 * (1 - nu * nu) / (M_PI * (2 - nu) * E) * shear);
    else
      u += eps * (x - centre);
  }
  return u;
}

Eigen::Matrix3d PennyField::gradient(const Eigen::Vector3d& x, int side) const {
  if (shear.squaredNorm() > 0)
    throw Error("penny field with shear: its gradient is not available (the shear part is a displacement by "
                "quadrature, for Dirichlet data): no L2 / H1 errors, nodal errors only away from the disc");
  if (closed) return penny_normal_strain(*this);
  Eigen::Matrix3d G;
  evaluate(x, side, nullptr, &G);
  return G;
}

Eigen::Matrix3d PennyField::stress(const Eigen::Vector3d& x, int side) const {
  const Eigen::Matrix3d G = gradient(x, side);
  const Eigen::Matrix3d eps = 0.5 * (G + G.transpose());
  const double mu = E / (2 * (1 + nu)), lambda = 2 * mu * nu / (1 - 2 * nu);
  return lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2 * mu * eps;
}

Eigen::Matrix3d RigidMotion::gradient() const {
  Eigen::Matrix3d W;
  W << 0, -rotation.z(), rotation.y(), rotation.z(), 0, -rotation.x(), -rotation.y(), rotation.x(), 0;
  return W;
}

Eigen::Vector3d ExactField::displacement(const Eigen::Vector3d& x, int side) const {
  if (kind == Kind::Williams) return williams.displacement(x, side);
  if (kind == Kind::Penny) return penny.displacement(x, side);
  if (kind == Kind::Linear) return linear_translation + linear_gradient * x;
  return side < 0 ? below.displacement(x) : above.displacement(x);
}

Eigen::Matrix3d ExactField::gradient(const Eigen::Vector3d& x, int side) const {
  if (kind == Kind::Williams) return williams.gradient(x, side);
  if (kind == Kind::Penny) return penny.gradient(x, side);
  if (kind == Kind::Linear) return linear_gradient;
  return side < 0 ? below.gradient() : above.gradient();
}

}  // namespace xfem
