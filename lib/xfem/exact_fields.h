// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <string>

#include "xfem/crack_front.h"

namespace xfem {

/// Williams near-tip displacement field of a straight cut front (modes I, II: plane strain with
/// kappa = 3 - 4 nu; mode III: anti-plane shear), an exact solution of 3D linear elasticity with
/// traction-free cut faces. Frame of DESIGN.md: the front is the line through `origin` along c;
/// b is the cut's unit normal; a = b x c points ahead into intact material; the cut is the
/// half-plane xb = 0, xa < 0, with theta = +-pi on its two faces.
struct WilliamsField {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d a = Eigen::Vector3d::UnitX();  ///< unit, ahead of the front
  Eigen::Vector3d b = Eigen::Vector3d::UnitY();  ///< unit, the cut's normal
  double K1 = 0.0, K2 = 0.0, K3 = 0.0;          ///< stress intensity factors, Pa sqrt(m)
  double E = 1.0, nu = 0.3;                      ///< Young's modulus (Pa), Poisson's ratio

  /// Displacement at x (metres). `side` (+1 / -1) picks the face for a point on the cut
  /// (|xb| <= 1e-9 r behind the front: theta = side * pi); 0 lets atan2 decide.
  Eigen::Vector3d displacement(const Eigen::Vector3d& x, int side = 0) const;

  /// Displacement gradient du_i/dx_j at x (row i, column j), 1: singular like r^-1/2 at the
  /// front, returned as 0 on it (r = 0). `side` as for displacement().
  Eigen::Matrix3d gradient(const Eigen::Vector3d& x, int side = 0) const;

  /// The field as a combination of the four crack-tip functions of branch_functions.h:
  /// u(x) = sum_j column j * F_j(x), F evaluated in the frame (a, b, c = a x b, origin). Columns
  /// are 3-vectors in global coordinates, metres / sqrt(metre). The modes lie in span{F}: that is
  /// why X-FEM with every node branch-enriched reproduces them.
  Eigen::Matrix<double, 3, 4> branch_coefficients() const;

  /// The same coefficients for the F of another frame (a mesh's crack-tip frame, crack_front.h):
  /// exact when that frame's front line is this field's (within `tolerance`, metres) and its a
  /// is this a; its b may be -b (the cut's normal the other way round: F_0 and F_3 change sign).
  /// Throws xfem::Error when the fronts differ, naming both.
  Eigen::Matrix<double, 3, 4> branch_coefficients(const CrackTipFrame& frame, double tolerance) const;

  /// This field's own crack-tip frame, R = (a | b | a x b).
  CrackTipFrame frame() const;
};

/// Sneddon's penny-shaped crack: a flat disc cut of radius a (centre, unit normal n) in an
/// infinite isotropic solid under remote uniaxial tension sigma normal to the disc (Sneddon 1946;
/// Kassir & Sih; docs/VERIFICATION.md "Penny-shaped crack"). The field is the uniform tension
/// field plus the perturbation of the disc's faces loaded by the pressure -sigma, written with
/// one harmonic potential phi (Green & Zerna's representation for a problem symmetric about the
/// disc's plane, z = n.(x - centre) >= 0, u_z odd and u_r even in z):
///   2 mu u_r = (1 - 2 nu) phi_r + z chi_r,   2 mu u_z = -2 (1 - nu) chi + z chi_z,   chi = phi_z,
/// with chi = -(2 sigma a / pi) eta (1 - zeta arccot zeta) and
/// phi = (2 sigma a^2 / (3 pi)) (arccot zeta + P2(eta) q2(zeta)), q2 = (3 zeta^2 + 1) / 2 arccot zeta
/// - 3 zeta / 2, in the oblate spheroidal coordinates z + i r = a sinh(mu + i theta), zeta = sinh mu,
/// eta = cos theta (the disc is zeta = 0). Exact: the faces are traction-free, the stress tends to
/// sigma n n^T far away, the opening is 2 u_z = 8 (1 - nu^2) sigma / (pi E) sqrt(a^2 - r^2) and
/// K_I = 2 sigma sqrt(a / pi) all along the front (test/unit/test_penny_field.cpp checks each).
struct PennyField {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit; its side is the cut's +1 side
  double radius = 1.0;                                ///< a, metres
  double sigma = 0.0;                                 ///< remote tension normal to the disc, Pa
  double E = 1.0, nu = 0.3;                           ///< Young's modulus (Pa), Poisson's ratio

  /// Displacement at x (metres; rigid motion: none, u(centre) = 0). `side` (+1 / -1) picks the
  /// face for a point in the disc's plane inside the disc (|z| <= 1e-12 a); 0: the +1 face.
  Eigen::Vector3d displacement(const Eigen::Vector3d& x, int side = 0) const;
  /// du_i/dx_j at x (row i, column j): singular like rho^-1/2 at the front (rho = the distance to
  /// the front circle), returned as 0 within 1e-10 a of it. `side` as for displacement().
  Eigen::Matrix3d gradient(const Eigen::Vector3d& x, int side = 0) const;
  /// The stress sigma_ij = lambda tr(eps) delta_ij + 2 mu eps_ij of gradient(x, side).
  Eigen::Matrix3d stress(const Eigen::Vector3d& x, int side = 0) const;
  /// K_I = 2 sigma sqrt(a / pi), the same at every front point (K_II = K_III = 0).
  double K1() const;

 private:
  void evaluate(const Eigen::Vector3d& x, int side, Eigen::Vector3d* u, Eigen::Matrix3d* grad) const;
};

/// Rigid motion u(x) = t + w x (x - centre) of one piece of a body.
struct RigidMotion {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();  ///< small rotation vector, radians
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d displacement(const Eigen::Vector3d& x) const {
    return translation + rotation.cross(x - centre);
  }
  /// du_i/dx_j: the skew matrix of `rotation` (constant; its symmetric part, the strain, is 0).
  Eigen::Matrix3d gradient() const;
};

/// An exact displacement field for verification (docs/FORMATS.md "Exact fields"): a Williams
/// near-tip field, a rigid motion per piece of a body that a cut separates completely (the
/// piece above the cut, H = +1, on the normal's side, and the piece below, H = -1), or one
/// linear field u = t + G x on both sides (exact with a cut whose faces the stress leaves
/// traction-free, e.g. uniaxial tension along the cut's plane; the caller chooses G so), or the
/// penny-shaped crack under remote tension.
struct ExactField {
  enum class Kind { Williams, Rigid, Linear, Penny };
  Kind kind = Kind::Williams;
  WilliamsField williams;
  PennyField penny;
  RigidMotion above, below;  ///< Rigid: the motion of each piece
  Eigen::Matrix3d linear_gradient = Eigen::Matrix3d::Zero();     ///< Linear: G, du_i/dx_j
  Eigen::Vector3d linear_translation = Eigen::Vector3d::Zero();  ///< Linear: t, m

  /// u(x) on `side` (+1 / -1) of the cut. Williams: side matters only on the cut face (see
  /// WilliamsField); Rigid: side picks the piece (0 is taken as +1, the convention D1 of
  /// docs/CLASSIFICATION.md for a point on the cut).
  Eigen::Vector3d displacement(const Eigen::Vector3d& x, int side) const;
  /// du_i/dx_j at x on `side`.
  Eigen::Matrix3d gradient(const Eigen::Vector3d& x, int side) const;
};

}  // namespace xfem
