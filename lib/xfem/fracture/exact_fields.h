// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <string>

#include "xfem/geometry/crack_front.h"

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
///
/// With a remote shear traction `shear` (tau, a vector in the disc's plane: the remote stress is
/// sigma n n^T + n tau^T + tau n^T, a disc inclined to a remote tension) the field adds the uniform
/// shear strain and the perturbation of the shear-loaded penny crack (Segedin 1950; Kassir & Sih):
/// its faces slide by the elliptical jump u+ - u- = 16 (1 - nu^2) / (pi (2 - nu) E) sqrt(a^2 - r^2)
/// tau (the same direction everywhere), and its displacement is Somigliana's integral of that jump
/// over the disc with Kelvin's point-force stress, u_m(x) = int b_i n_j sigma^(m)_ij(y - x) dS(y),
/// evaluated by quadrature (Gauss-Legendre in r = a sin t, 32 x 128 points; it gives Sneddon's
/// normal part to 1e-9 at a distance 0.25 a from the disc: test/unit/test_penny_field.cpp). That part
/// is available as a displacement only, at points 0.25 a and more from the disc (what Dirichlet
/// data on a box around the disc need); gradient() throws for it. Stress intensity factors in the
/// frame a = radial, b = n, c = a x b at the front point at angle phi from tau:
/// K_II = 4 / (2 - nu) sqrt(a / pi) tau.a (= 4 / (pi (2 - nu)) |tau| sqrt(pi a) cos phi),
/// K_III = 4 (1 - nu) / (2 - nu) sqrt(a / pi) tau.c (= 4 (1 - nu) / (pi (2 - nu)) |tau| sqrt(pi a)
/// sin phi; the handbooks' -sin phi is for c along +phi: here c = -e_phi for n = +z).
struct PennyField {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit; its side is the cut's +1 side
  double radius = 1.0;                                ///< a, metres
  double sigma = 0.0;                                 ///< remote tension normal to the disc, Pa
  Eigen::Vector3d shear = Eigen::Vector3d::Zero();    ///< remote shear traction on the disc's plane (in it), Pa
  double E = 1.0, nu = 0.3;                           ///< Young's modulus (Pa), Poisson's ratio
  /// false: the crack loaded on its faces instead (pressure sigma, shear traction `shear` on the
  /// face above, the opposite below; zero at infinity): the same field without the remote uniform
  /// one, which has no jump, so the opening and K are the same (problem.json "cut_loads").
  bool remote = true;
  /// true: the faces pressed shut by a remote compression sigma <= 0 (problem.json "loading":
  /// "closed"; frictionless contact, issue 33): they carry the normal stress, so the normal part
  /// is the uniform field sigma n n^T alone (no Sneddon perturbation, no opening); the shear part
  /// is unchanged (frictionless faces slide freely by the elliptical jump above).
  bool closed = false;
  /// With `closed`: Coulomb friction mu between the shut faces (issue 33). They carry mu |sigma|
  /// of the shear, so they slide by the elliptical jump of the effective shear
  /// tau (1 - mu |sigma| / |tau|) where that is positive, and stick (the uniform field alone) else.
  double friction = 0.0;

  /// Displacement at x (metres; rigid motion: none, u(centre) = 0). `side` (+1 / -1) picks the
  /// face for a point in the disc's plane inside the disc (|z| <= 1e-12 a); 0: the +1 face.
  /// With shear: throws xfem::Error closer than 0.25 a to the disc (the quadrature's limit).
  Eigen::Vector3d displacement(const Eigen::Vector3d& x, int side = 0) const;
  /// du_i/dx_j at x (row i, column j): singular like rho^-1/2 at the front (rho = the distance to
  /// the front circle), returned as 0 within 1e-10 a of it. `side` as for displacement().
  /// Throws xfem::Error with shear (not available).
  Eigen::Matrix3d gradient(const Eigen::Vector3d& x, int side = 0) const;
  /// The stress sigma_ij = lambda tr(eps) delta_ij + 2 mu eps_ij of gradient(x, side).
  Eigen::Matrix3d stress(const Eigen::Vector3d& x, int side = 0) const;
  /// K_I = 2 sigma sqrt(a / pi), the same at every front point (K_II = K_III = 0 without shear).
  double K1() const;
  /// (K_I, K_II, K_III) at the front point closest to x, in the frame a = radial, b = n, c = a x b.
  Eigen::Vector3d stress_intensity(const Eigen::Vector3d& x) const;
  /// Somigliana's integral (above) of a jump b(y) = sqrt(a^2 - r^2) `jump` over the disc at x:
  /// the displacement of a crack opened (jump along n) or slid (in the plane) elliptically.
  Eigen::Vector3d elliptical_jump_displacement(const Eigen::Vector3d& x, const Eigen::Vector3d& jump) const;

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
